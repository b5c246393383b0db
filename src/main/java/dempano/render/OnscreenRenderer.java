package dempano.render;

import com.jme3.app.SimpleApplication;
import com.jme3.font.BitmapText;
import com.jme3.input.KeyInput;
import com.jme3.input.controls.ActionListener;
import com.jme3.input.controls.KeyTrigger;
import com.jme3.material.Material;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Vector3f;
import com.jme3.post.SceneProcessor;
import com.jme3.profile.AppProfiler;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Node;
import com.jme3.system.AppSettings;
import com.jme3.texture.FrameBuffer;
import com.jme3.util.BufferUtils;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.io.AtomicFiles;
import dempano.io.IoMessages;
import dempano.io.Png;
import dempano.terrain.TerrainBuilder;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The fly-through: a jME window over the same terrain, earth model and shader as the panoramas, to
 * look for anomalies in a DEM (voids, spikes, terracing, seams, a wrong altitude at a viewpoint).
 * The terrain is built once around the start, in its east-north-up frame; the HUD converts the
 * camera back to geodetic coordinates through that frame. {@link #KEYS} lists the controls.
 */
public final class OnscreenRenderer extends SimpleApplication {
    /** The controls, as the README and the HUD list them. */
    public static final List<String> KEYS = List.of(
            "W/S forward/back, A/D left/right, Q/Z up/down, arrows or mouse drag: turn and pitch",
            "+/- (or PgUp/PgDn): speed ×2 / ÷2",
            "F1 wireframe, F2 debug colours (filled voids magenta, missing tiles red, tile seams yellow)",
            "F3 vertical exaggeration 1→2→4→1, F4 earth: curvature+refraction k=0.13 → no refraction → flat (k=1)",
            "P render the 360° panorama here (offscreen pipeline), K screenshot, Esc quit");

    /**
     * What to fly over and how.
     *
     * @param demDirs           tile directories in priority order (see {@link dempano.dem.PriorityDem})
     * @param aboveGroundMetres start height above the DEM
     * @param rangeMetres       terrain built within this distance of the start
     * @param frames            scripted mode: fly this many frames (1/30 s each) along the heading, then
     *                          write {@code screenshot} and quit; 0 = interactive
     * @param outDir            where panoramas and screenshots go
     * @param panoramaAtEnd     scripted mode: also press P at the end and wait for the panorama
     * @param missingTiles      what an absent tile is (as for a panorama; key P's panorama takes it too)
     */
    public record Options(List<Path> demDirs, double latDeg, double lonDeg, double aboveGroundMetres, double rangeMetres,
                          double headingDeg, double pitchDeg, double speedMetresPerSecond, int frames, Path screenshot,
                          boolean wireframe, boolean debugAids, double exaggeration,
                          double refractionCoefficient, int widthPx, int heightPx, Path outDir, boolean panoramaAtEnd,
                          MissingTilePolicy missingTiles) {
    }

    /** The terrain's data, read before the window opens (a wrong folder is said before anything appears). */
    private record Ground(Mosaic mosaic, Viewpoint start) {
        /**
         * Opens the DEM as the panorama command does: the folders' warnings and the mosaic's (missing tiles drawn as
         * sea level, voids filled) said on stderr; no tile at all, or none under the start, is an error.
         */
        static Ground load(Options opt) {
            dempano.dem.DemSource dem = dempano.dem.PriorityDem.open(opt.demDirs(), dempano.dem.DemFill.DEFAULT,
                    w -> System.err.println("  warning: " + w));
            Mosaic mosaic = Mosaic.around(dem, opt.latDeg(), opt.lonDeg(), opt.rangeMetres(), opt.missingTiles());
            opt.missingTiles().checkData(mosaic, opt.latDeg(), opt.lonDeg(), Double.NaN);
            mosaic.warnings().forEach(w -> System.err.println("  warning: " + w));
            return new Ground(mosaic, Viewpoint.onDem(mosaic, opt.latDeg(), opt.lonDeg(), 0, opt.aboveGroundMetres()));
        }
    }

    private final Options opt;
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private final java.util.concurrent.CountDownLatch done = new java.util.concurrent.CountDownLatch(1);
    private Mosaic mosaic;
    private Viewpoint start;
    private LocalFrame frame;
    private Material material;
    private Node terrain;
    private BitmapText hud, message;
    private boolean wireframe, debugAids;
    private double exaggeration, refractionK;
    private int scriptedFrame;
    private volatile String status = "";
    private final ScreenGrabber grabber = new ScreenGrabber();
    private int panoramas;
    /** Panoramas rendering in their own JVMs: waited for when the window closes, stopped when fly is killed. */
    private final java.util.Set<Process> running = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private volatile Thread panoramaThread;
    /** Scripted mode: the panorama at the end failed. */
    private volatile boolean panoramaFailed;

    private OnscreenRenderer(Options opt, Ground ground) {
        // The fly camera alone of SimpleApplication's default states: no statistics, and no C/M keys printing jME's
        // camera and memory dumps to stdout.
        super(new com.jme3.app.FlyCamAppState());
        this.opt = opt;
        this.mosaic = ground.mosaic();
        this.start = ground.start();
        this.frame = start.eyeFrame();
        this.wireframe = opt.wireframe();
        this.debugAids = opt.debugAids();
        this.exaggeration = opt.exaggeration();
        this.refractionK = opt.refractionCoefficient();
    }

    /**
     * Fails fast, before any DEM is read or jME started, where no window can open: on Linux and the
     * BSDs neither {@code $DISPLAY} nor {@code $WAYLAND_DISPLAY} is set (only {@code $DISPLAY} counts
     * under {@code DEMPANO_GL=x11}).
     *
     * @throws GlUnavailableException naming the missing display and how to run under Xvfb
     */
    public static void checkDisplay() {
        String problem = GlPlatform.displayProblem(GlPlatform.choice(), System.getenv(), System.getProperty("os.name", ""));
        if (problem != null) {
            throw new GlUnavailableException("fly needs a display for its window, and " + problem + "; "
                    + GlPlatform.XVFB_WAY_OUT, null);
        }
    }

    /**
     * Runs the window until it is closed (or the script ends), then waits for panoramas still rendering (key P);
     * returns 0, or 1 where the script's panorama failed; throws what went wrong (a scripted screenshot not
     * written: the {@link IOException}). A fly process that is killed stops the panoramas it started.
     */
    public static int fly(Options opt) throws IOException {
        checkDisplay();
        Ground ground = Ground.load(opt);
        GlPlatform.quietJme();
        GlPlatform.configureWindow();
        OnscreenRenderer app = new OnscreenRenderer(opt, ground);
        Thread stopPanoramas = new Thread(app::stopPanoramas, "fly-exit");
        Runtime.getRuntime().addShutdownHook(stopPanoramas);
        AppSettings s = new AppSettings(true);
        s.setTitle("dempano fly-through");
        s.setResolution(opt.widthPx(), opt.heightPx());
        s.setRenderer(GlPlatform.RENDERER);
        s.setAudioRenderer(null);
        s.setVSync(opt.frames() == 0);
        s.setSamples(0);
        s.setGammaCorrection(false);
        app.setSettings(s);
        app.setShowSettings(false); // jME's settings dialog is not installed (jme3-awt-dialogs): the flags set it all
        app.setPauseOnLostFocus(false);
        app.start(); // jME's LWJGL 3 context runs its loop on its own thread
        try {
            app.done.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            app.stop();
        }
        app.awaitPanoramas();
        try {
            Runtime.getRuntime().removeShutdownHook(stopPanoramas);
        } catch (IllegalStateException e) {
            // the JVM is ending: the hook runs
        }
        Throwable t = app.failure.get();
        if (t instanceof RuntimeException e && !(t instanceof JmeFailure)) {
            throw e; // already worded for the user
        }
        if (t instanceof IOException e) {
            throw e; // the scripted screenshot: names the file and why
        }
        if (t != null) {
            throw new GlUnavailableException(app.windowOpened
                    ? "the fly-through stopped: " + t.getMessage()
                    : "fly could not open its window: " + t.getMessage() + "; " + GlPlatform.windowHint(), t.getCause());
        }
        return app.panoramaFailed ? 1 : 0;
    }

    /** After the window closed: waits for the panoramas key P started, saying so. */
    private void awaitPanoramas() {
        for (Process p : List.copyOf(running)) {
            System.err.println("dempano fly: waiting for the panorama in progress to be written (Ctrl-C stops it)");
            try {
                p.waitFor();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
        Thread th = panoramaThread;
        if (th != null) {
            try {
                th.join(10_000); // its last line (written or failed)
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** fly is being killed (SIGTERM, Ctrl-C): its panoramas end too, each leaving no part of its files (their own exit). */
    private void stopPanoramas() {
        for (Process p : List.copyOf(running)) {
            p.destroy();
            try {
                if (p.waitFor(20, java.util.concurrent.TimeUnit.SECONDS)) {
                    System.err.println("dempano fly: the panorama in progress was stopped");
                } else {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                return;
            }
        }
    }

    /** A failure jME reported through {@link #handleError}; its message is jME's or GLFW's words, once. */
    private static final class JmeFailure extends RuntimeException {
        JmeFailure(String message, Throwable cause) {
            super(message, cause);
        }
    }

    /** Set once jME has a window and calls {@link #simpleInitApp()}. */
    private volatile boolean windowOpened;

    @Override
    public void handleError(String errMsg, Throwable t) {
        // jME would log and exit 0; make the failure reach the caller. GLFW's errors arrive as the
        // description plus an Exception carrying the same text: say it once.
        String cause = t == null || t.getMessage() == null || (errMsg != null && errMsg.contains(t.getMessage())) ? errMsg
                : errMsg == null || t.getMessage().contains(errMsg) ? t.getMessage() : errMsg + ": " + t.getMessage();
        failure.compareAndSet(null, new JmeFailure(cause == null ? String.valueOf(t) : cause, t));
        stop();
        done.countDown();
    }

    @Override
    public void destroy() {
        try {
            super.destroy();
        } finally {
            done.countDown();
        }
    }

    @Override
    public void simpleInitApp() {
        windowOpened = true;
        viewPort.setBackgroundColor(new ColorRGBA(OffscreenRenderer.SKY_RGBA[0], OffscreenRenderer.SKY_RGBA[1],
                OffscreenRenderer.SKY_RGBA[2], 1));
        cam.setFrustumPerspective(60, (float) settings.getWidth() / settings.getHeight(), 1f, (float) (opt.rangeMetres() * 1.5));
        // The start frame's origin is the eye over the true ground; the terrain is drawn exaggerated.
        cam.setLocation(new Vector3f(0, (float) (start.groundElevationMetres() * (exaggeration - 1)), 0));
        float heading = (float) Math.toRadians(opt.headingDeg()), pitch = (float) Math.toRadians(opt.pitchDeg());
        Vector3f dir = new Vector3f(FastMath.sin(heading) * FastMath.cos(pitch), FastMath.sin(pitch),
                -FastMath.cos(heading) * FastMath.cos(pitch));
        cam.lookAtDirection(dir, Vector3f.UNIT_Y);
        flyCam.setMoveSpeed((float) opt.speedMetresPerSecond());
        flyCam.setDragToRotate(true);
        flyCam.setZoomSpeed(0);
        flyCam.setEnabled(opt.frames() == 0);
        buildTerrain();
        setDisplayStatView(false);
        setDisplayFps(false);
        hud = new BitmapText(guiFont);
        hud.setSize(guiFont.getCharSet().getRenderedSize());
        hud.setColor(ColorRGBA.White);
        hud.setLocalTranslation(10, settings.getHeight() - 10, 0);
        guiNode.attachChild(hud);
        message = new BitmapText(guiFont);
        message.setColor(ColorRGBA.Yellow);
        message.setLocalTranslation(10, 10 + guiFont.getCharSet().getRenderedSize(), 0);
        guiNode.attachChild(message);
        BitmapText cross = new BitmapText(guiFont);
        cross.setText("+");
        cross.setColor(ColorRGBA.White);
        cross.setLocalTranslation(settings.getWidth() / 2f - cross.getLineWidth() / 2, settings.getHeight() / 2f + cross.getLineHeight() / 2, 0);
        guiNode.attachChild(cross);
        guiViewPort.addProcessor(grabber); // the GUI viewport is drawn last: its frame includes the HUD
        mapKeys();
    }

    private void buildTerrain() {
        if (terrain != null) {
            terrain.removeFromParent();
            renderer.cleanup(); // frees the old buffers' GL objects at the next frame
            TerrainBuilder.destroyBuffers(terrain);
        }
        material = TerrainMaterial.create(assetManager, opt.rangeMetres());
        material.setBoolean("DebugAids", debugAids);
        material.getAdditionalRenderState().setWireframe(wireframe);
        material.getAdditionalRenderState().setFaceCullMode(com.jme3.material.RenderState.FaceCullMode.Off);
        // Level of detail for the window: its pixels per degree, a one-pixel bound.
        double ppd = settings.getHeight() / 60.0;
        terrain = TerrainBuilder.build(mosaic, start, new Refraction(refractionK), opt.rangeMetres(), material,
                TerrainBuilder.Detail.of(ppd, 1).withExaggeration(exaggeration)).root();
        rootNode.attachChild(terrain);
    }

    private void mapKeys() {
        inputManager.addMapping("wireframe", new KeyTrigger(KeyInput.KEY_F1));
        inputManager.addMapping("debug", new KeyTrigger(KeyInput.KEY_F2));
        inputManager.addMapping("exaggerate", new KeyTrigger(KeyInput.KEY_F3));
        inputManager.addMapping("earth", new KeyTrigger(KeyInput.KEY_F4));
        inputManager.addMapping("faster", new KeyTrigger(KeyInput.KEY_EQUALS), new KeyTrigger(KeyInput.KEY_ADD),
                new KeyTrigger(KeyInput.KEY_PGUP));
        inputManager.addMapping("slower", new KeyTrigger(KeyInput.KEY_MINUS), new KeyTrigger(KeyInput.KEY_SUBTRACT),
                new KeyTrigger(KeyInput.KEY_PGDN));
        inputManager.addMapping("panorama", new KeyTrigger(KeyInput.KEY_P));
        inputManager.addMapping("screenshot", new KeyTrigger(KeyInput.KEY_K));
        ActionListener l = (name, pressed, tpf) -> {
            if (!pressed) {
                return;
            }
            switch (name) {
                case "wireframe" -> {
                    wireframe = !wireframe;
                    material.getAdditionalRenderState().setWireframe(wireframe);
                }
                case "debug" -> {
                    debugAids = !debugAids;
                    material.setBoolean("DebugAids", debugAids);
                }
                case "exaggerate" -> {
                    double was = exaggeration;
                    exaggeration = exaggeration >= 4 ? 1 : exaggeration * 2;
                    // Keep the camera as high above the ground under it as it was: the heights drawn scale.
                    Vector3f p = cam.getLocation();
                    double[] geo = frame.toGeodetic(p.x, -p.z, p.y);
                    double ground = groundUnder(geo[0], geo[1]);
                    if (!Double.isNaN(ground)) {
                        cam.setLocation(p.add(0, (float) (ground * (exaggeration - was)), 0));
                    }
                    buildTerrain();
                }
                case "earth" -> {
                    refractionK = refractionK == Refraction.STANDARD.coefficient() ? 0
                            : refractionK == 0 ? 1 : Refraction.STANDARD.coefficient();
                    buildTerrain();
                }
                case "faster" -> flyCam.setMoveSpeed(flyCam.getMoveSpeed() * 2);
                case "slower" -> flyCam.setMoveSpeed(Math.max(1, flyCam.getMoveSpeed() / 2));
                case "panorama" -> renderPanorama();
                case "screenshot" -> grabber.request(opt.outDir().resolve(freeName("fly-", ".png") + ".png"));
                default -> {
                }
            }
        };
        inputManager.addListener(l, "wireframe", "debug", "exaggerate", "earth", "faster", "slower", "panorama", "screenshot");
    }

    /**
     * The first {@code prefix + n} (n = 1, 2, …) that no file in the output folder starts with followed by one of the
     * suffixes: a second session into the same folder does not overwrite the first one's screenshots or panoramas.
     */
    private String freeName(String prefix, String... suffixes) {
        for (int n = 1; ; n++) {
            String name = prefix + n;
            boolean taken = false;
            for (String suffix : suffixes) {
                taken |= Files.exists(opt.outDir().resolve(name + suffix));
            }
            if (!taken) {
                return name;
            }
        }
    }

    @Override
    public void simpleUpdate(float tpf) {
        if (mosaic == null) {
            return;
        }
        if (opt.frames() > 0) {
            // Scripted: a fixed step per frame, so that the path does not depend on the machine's speed.
            cam.setLocation(cam.getLocation().add(cam.getDirection().mult((float) (opt.speedMetresPerSecond() / 30))));
            scriptedFrame++;
            if (scriptedFrame == opt.frames()) {
                grabber.request(opt.screenshot());
                if (opt.panoramaAtEnd()) {
                    renderPanorama();
                }
            } else if (scriptedFrame > opt.frames() && !grabber.pending() && (panoramaThread == null || !panoramaThread.isAlive())) {
                stop();
            }
        }
        Vector3f p = cam.getLocation(), d = cam.getDirection();
        double[] geo = frame.toGeodetic(p.x, -p.z, p.y);
        double ground = groundUnder(geo[0], geo[1]);
        double aboveGround = aboveGround(p, geo);
        double heading = dempano.geo.Angles.wrap360(Math.toDegrees(Math.atan2(d.x, -d.z))), pitch = Math.toDegrees(Math.asin(d.y));
        double[] hit = crosshair(p, d);
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "lat %.5f  lon %.5f%n", geo[0], geo[1]));
        // Above sea: the eye as high above the true ground as the camera is above the ground drawn (exaggerated,
        // lifted by refraction away from the start): where key P renders its panorama.
        sb.append(String.format(Locale.ROOT, "altitude %.0f m above sea, %.0f m above ground%n", ground + aboveGround,
                aboveGround));
        sb.append(String.format(Locale.ROOT, "heading %.1f deg  pitch %.1f deg  speed %.0f m/s%n", heading, pitch,
                opt.frames() > 0 ? opt.speedMetresPerSecond() : flyCam.getMoveSpeed()));
        sb.append(hit == null ? "crosshair: sky / beyond range\n" : String.format(Locale.ROOT,
                "crosshair: DEM %.0f m at %.5f, %.5f, %.2f km away%n", hit[2], hit[0], hit[1], hit[3] / 1000));
        sb.append(String.format(Locale.ROOT, "exaggeration x%s, %s, wireframe %s, debug colours %s",
                dempano.util.Decimals.shortest(exaggeration, 6), refractionK == 1 ? "flat earth (k = 1)" : "refraction k = " + refractionK,
                wireframe ? "on" : "off", debugAids ? "on" : "off"));
        hud.setText(sb.toString());
        message.setText(status);
    }

    /** The camera's height above the ground drawn under it (exaggerated, lifted by refraction), metres; NaN off the DEM. */
    private double aboveGround(Vector3f p, double[] geo) {
        double ground = groundUnder(geo[0], geo[1]);
        return geo[2] - (ground * exaggeration + new Refraction(refractionK).liftMetres(Math.hypot(p.x, p.z)));
    }

    /** DEM height (m) at a coordinate, NaN outside the mosaic. */
    private double groundUnder(double latDeg, double lonDeg) {
        double r = mosaic.rowOf(latDeg), c = mosaic.colOf(lonDeg);
        if (!(r >= 0 && c >= 0 && r <= mosaic.rows() - 1 && c <= mosaic.cols() - 1)) {
            return Double.NaN;
        }
        return mosaic.heightAt(latDeg, lonDeg);
    }

    /**
     * The DEM point under the crosshair: a march along the view ray in the start frame (steps growing
     * with distance), refined by bisection. Returns {lat, lon, DEM height, distance} or null.
     * Heights compare as drawn: DEM × exaggeration plus refraction's lift.
     */
    double[] crosshair(Vector3f p, Vector3f d) {
        double prevT = 0;
        double t = 1;
        Refraction k = new Refraction(refractionK);
        while (t < opt.rangeMetres()) {
            if (below(p, d, t, k)) {
                double lo = prevT, hi = t;
                for (int i = 0; i < 40; i++) {
                    double mid = (lo + hi) / 2;
                    if (below(p, d, mid, k)) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                double[] g = frame.toGeodetic(p.x + d.x * hi, -(p.z + d.z * hi), p.y + d.y * hi);
                return new double[] {g[0], g[1], groundUnder(g[0], g[1]), hi};
            }
            prevT = t;
            t = t * 1.01 + 2;
        }
        return null;
    }

    private boolean below(Vector3f p, Vector3f d, double t, Refraction k) {
        double e = p.x + d.x * t, n = -(p.z + d.z * t), u = p.y + d.y * t;
        double[] g = frame.toGeodetic(e, n, u);
        double h = groundUnder(g[0], g[1]);
        return !Double.isNaN(h) && g[2] <= h * exaggeration + k.liftMetres(Math.hypot(e, n));
    }

    /** Renders the 360° panorama at the camera in a separate JVM (its own offscreen GL context). */
    private void renderPanorama() {
        Vector3f p = cam.getLocation();
        double[] geo = frame.toGeodetic(p.x, -p.z, p.y);
        double ground = groundUnder(geo[0], geo[1]), above = aboveGround(p, geo);
        if (Double.isNaN(ground) || above < 0) {
            status = "panorama: the camera is " + (Double.isNaN(ground) ? "off the DEM" : "below the terrain");
            System.err.println("dempano fly: " + status);
            panoramaFailed |= opt.frames() > 0;
            return;
        }
        try {
            Files.createDirectories(opt.outDir());
        } catch (IOException e) {
            status = "panorama not started: cannot make " + opt.outDir() + ": " + IoMessages.reason(e);
            System.err.println("dempano fly: " + status);
            panoramaFailed |= opt.frames() > 0;
            return;
        }
        String name = freeName("fly-panorama-", ".png", ".json", "-distance.npy", ".log");
        Path prefix = opt.outDir().resolve(name), log = opt.outDir().resolve(name + ".log");
        panoramas++;
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx4g",
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), "dempano.cli.Main",
                "--lat", Double.toString(geo[0]), "--lon", Double.toString(geo[1]), "--altitude-m", Double.toString(ground + above),
                "--eye-height-m", "0", "--refraction", Double.toString(refractionK), "--out", prefix.toString(),
                "--missing-tiles", opt.missingTiles().flagValue()));
        opt.demDirs().forEach(d -> cmd.addAll(List.of("--dem-dir", d.toString())));
        status = "panorama: rendering at " + String.format(Locale.ROOT, "%.5f, %.5f, %.0f m", geo[0], geo[1], geo[2]) + " …";
        Process proc;
        try {
            proc = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        } catch (IOException e) {
            status = "panorama not started: " + IoMessages.describe(e);
            System.err.println("dempano fly: " + status);
            panoramaFailed |= opt.frames() > 0;
            return;
        }
        running.add(proc);
        Thread th = new Thread(() -> {
            try {
                int rc = proc.waitFor();
                status = rc == 0 ? "panorama written: " + prefix + ".png, " + prefix + "-distance.npy"
                        : "panorama failed (exit " + rc + "): see " + log;
                panoramaFailed |= rc != 0 && opt.frames() > 0;
                System.err.println("dempano fly: " + status);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                running.remove(proc);
            }
        }, "panorama");
        th.setDaemon(true);
        th.start();
        panoramaThread = th;
    }

    /** Reads the window's framebuffer after a frame and writes it as PNG, on request. */
    private final class ScreenGrabber implements SceneProcessor {
        private volatile Path target;
        private RenderManager rm;

        void request(Path file) {
            target = file;
        }

        boolean pending() {
            return target != null;
        }

        @Override
        public void initialize(RenderManager rm, ViewPort vp) {
            this.rm = rm;
        }

        @Override
        public void reshape(ViewPort vp, int w, int h) {
        }

        @Override
        public boolean isInitialized() {
            return rm != null;
        }

        @Override
        public void preFrame(float tpf) {
        }

        @Override
        public void postQueue(RenderQueue rq) {
        }

        @Override
        public void postFrame(FrameBuffer out) {
            Path file = target;
            if (file == null) {
                return;
            }
            int w = settings.getWidth(), h = settings.getHeight();
            ByteBuffer buf = BufferUtils.createByteBuffer(w * h * 4);
            rm.getRenderer().readFrameBuffer(null, buf);
            // RGBA rows from the bottom, as GL reads them.
            BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int i = ((h - 1 - y) * w + x) * 4;
                    img.setRGB(x, y, (buf.get(i) & 0xff) << 16 | (buf.get(i + 1) & 0xff) << 8 | (buf.get(i + 2) & 0xff));
                }
            }
            BufferUtils.destroyDirectBuffer(buf);
            try {
                Path parent = file.toAbsolutePath().getParent();
                if (parent != null) {
                    try {
                        Files.createDirectories(parent);
                    } catch (IOException e) {
                        throw new IOException("cannot write " + file + ": cannot make its folder " + parent + ": "
                                + IoMessages.reason(e), e);
                    }
                }
                AtomicFiles.write(file, stream -> Png.write(img, stream));
                status = "screenshot written: " + file;
                System.err.println("dempano fly: " + status);
                System.out.println("dempano fly HUD: " + hud.getText().replace('\n', '|'));
            } catch (IOException e) {
                status = "screenshot not written: " + e.getMessage();
                if (opt.frames() > 0) {
                    failure.compareAndSet(null, e); // the script's one output: the run fails, saying why
                } else {
                    System.err.println("dempano fly: " + status);
                }
            }
            target = null;
        }

        @Override
        public void cleanup() {
        }

        @Override
        public void setProfiler(AppProfiler profiler) {
        }
    }
}
