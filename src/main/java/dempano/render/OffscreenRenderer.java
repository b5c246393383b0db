package dempano.render;

import com.jme3.app.LegacyApplication;
import com.jme3.asset.AssetManager;
import com.jme3.material.MatParamOverride;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.Matrix4f;
import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import com.jme3.renderer.Renderer;
import com.jme3.renderer.ViewPort;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import com.jme3.texture.FrameBuffer;
import com.jme3.texture.Image;
import dempano.panorama.DepthMode;
import dempano.panorama.ViewCapture;
import dempano.panorama.ViewLayout;
import dempano.terrain.TerrainBuilder;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.lwjgl.opengl.GL11;
import org.lwjgl.opengl.GL30;
import org.lwjgl.opengl.GL45;

/**
 * One OpenGL context (headless by default, see {@link GlPlatform}) on its own thread, rendering
 * perspective views of a scene into a framebuffer with a colour target, a float range target and a
 * depth buffer, and reading all three back. Thread-safe: calls are serialized onto the GL thread.
 */
public final class OffscreenRenderer {
    private static final Logger LOG = Logger.getLogger(OffscreenRenderer.class.getName());
    /** Sky colour in the colour image (RGBA, 0..1). */
    public static final float[] SKY_RGBA = {0.60f, 0.78f, 0.97f, 1f};
    private static final long START_TIMEOUT_SECONDS = 120;

    private final GlApp app;
    private final String glRenderer;
    private final String glVersion;
    private volatile boolean closed;

    private OffscreenRenderer(GlApp app, String glRenderer, String glVersion) {
        this.app = app;
        this.glRenderer = glRenderer;
        this.glVersion = glVersion;
    }

    // GLFW allows one context owner per process here (closing one terminates GLFW for all), so every
    // user shares one context, released when the last user closes it.
    private static OffscreenRenderer shared;
    /** Handles open on this context (guarded by the class lock). */
    private int users;

    /**
     * A handle on the process's GL context, created on first use (and anew after a failed one). Each
     * handle must be closed; a context ends with the last of its handles.
     *
     * @throws GlUnavailableException naming what is missing when no context can be created
     */
    public static synchronized Handle acquire() {
        if (shared == null || shared.closed) {
            awaitEnd(lastGlThread);
            shared = open();
        }
        shared.users++;
        return new Handle(shared);
    }

    /**
     * The GL thread of the last context started (guarded by the class lock). A context ends on its GL thread with
     * glfwTerminate, which would end a context created meanwhile under its feet ("Failed to create display"): a new
     * context first waits for that thread, whether its context was closed, broken by an Error or never made.
     */
    private static Thread lastGlThread;

    private static void awaitEnd(Thread t) {
        if (t == null || t == Thread.currentThread()) {
            return;
        }
        try {
            t.join(TimeUnit.SECONDS.toMillis(START_TIMEOUT_SECONDS));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static synchronized void release(OffscreenRenderer r) {
        if (--r.users == 0) {
            r.close();
            if (shared == r) {
                shared = null;
            }
        }
    }

    /** A user's share of the GL context. */
    public static final class Handle implements AutoCloseable {
        private final OffscreenRenderer renderer;
        private boolean closed;

        private Handle(OffscreenRenderer renderer) {
            this.renderer = renderer;
        }

        public OffscreenRenderer renderer() {
            if (closed) {
                throw new IllegalStateException("renderer handle is closed");
            }
            return renderer;
        }

        @Override
        public void close() {
            synchronized (OffscreenRenderer.class) {
                if (!closed) {
                    closed = true;
                    release(renderer);
                }
            }
        }
    }

    private static OffscreenRenderer open() {
        GlPlatform.quietJme();
        GlPlatform.configure();
        GlApp app = new GlApp();
        AppSettings s = new AppSettings(true);
        s.setRenderer(GlPlatform.RENDERER);
        s.setResolution(16, 16);
        s.setAudioRenderer(null);
        s.setFrameRate(250); // idle loop sleeps; tasks start within 4 ms
        s.setVSync(false);
        s.setGammaCorrection(false);
        s.setSamples(0);
        app.setSettings(s);
        app.setPauseOnLostFocus(false);
        try {
            app.start(JmeContext.Type.OffscreenSurface);
        } catch (RuntimeException e) {
            throw new GlUnavailableException("cannot start an OpenGL context: " + e.getMessage() + "; " + GlPlatform.hint(), e);
        }
        String[] info;
        try {
            info = app.ready.get(START_TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            app.stop(false);
            throw new GlUnavailableException("cannot create an OpenGL context (" + e.getCause().getMessage() + "); "
                    + GlPlatform.hint(), e.getCause());
        } catch (TimeoutException | InterruptedException e) {
            app.stop(false);
            throw new GlUnavailableException("no OpenGL context after " + START_TIMEOUT_SECONDS + " s; " + GlPlatform.hint(), e);
        } finally {
            lastGlThread = app.glThread; // made, failed or late: a next context waits for this thread (see acquire)
        }
        return new OffscreenRenderer(app, info[0], info[1]);
    }

    /** The GL_RENDERER string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)". */
    public String glRenderer() {
        return glRenderer;
    }

    public String glVersion() {
        return glVersion;
    }

    public AssetManager assetManager() {
        return app.getAssetManager();
    }

    /** A new terrain material for a range of sight (see {@link TerrainMaterial}). */
    public Material newTerrainMaterial(double rangeMetres) {
        return TerrainMaterial.create(app.getAssetManager(), rangeMetres);
    }

    /**
     * What one render draws and reads back.
     *
     * @param layout     the views
     * @param mode       projection and depth test; which target {@link ViewCapture#depth()} holds
     * @param nearMetres near plane
     * @param farMetres  far plane (STANDARD_24) and culling distance (all modes)
     * @param options    what else it does ({@link Option}); {@link Option#RANGE_TARGET} is needed by SHADER_RANGE
     */
    public record ViewRequest(ViewLayout layout, DepthMode mode, double nearMetres, double farMetres, Set<Option> options) {
        /** What a render reads back and how it draws, beyond the mode's depth. */
        public enum Option {
            /**
             * Read the colour target (else captures carry no colour; set the terrain material's {@code DistanceOnly}
             * so the shader skips shading).
             */
            COLOUR,
            /**
             * Captures' depth is the shader's range target whatever the mode (the mode then only chooses the
             * projection and depth test).
             */
            RANGE_TARGET,
            /** Also read which triangle each sample sees ({@link ViewCapture#triangleIds()}), for exact per-pixel distances. */
            SURFACES,
            /** Free the scene's GL buffers afterwards (for single-use scenes). */
            RELEASE,
            /**
             * Draw terrain faces turned away from the eye too (slower; the same picture wherever the terrain is seen
             * from above: for checking that); without it they are culled ({@link TerrainBuilder#CULL_BACK_FACES}: one
             * draw call per geometry).
             */
            BACK_FACES
        }

        public ViewRequest {
            options = java.util.Collections.unmodifiableSet(options.isEmpty() ? EnumSet.noneOf(Option.class) : EnumSet.copyOf(options));
            if (mode == DepthMode.SHADER_RANGE && !options.contains(Option.RANGE_TARGET)) {
                throw new IllegalArgumentException("the shader-range mode reads the range target");
            }
        }

        /** Colour and the mode's depth, nothing else; back faces culled, buffers kept. */
        public static ViewRequest of(ViewLayout layout, DepthMode mode, double nearMetres, double farMetres) {
            return new ViewRequest(layout, mode, nearMetres, farMetres, mode == DepthMode.SHADER_RANGE
                    ? EnumSet.of(Option.COLOUR, Option.RANGE_TARGET) : EnumSet.of(Option.COLOUR));
        }

        /** The same request with an option more. */
        public ViewRequest with(Option option) {
            EnumSet<Option> more = EnumSet.of(option);
            more.addAll(options);
            return new ViewRequest(layout, mode, nearMetres, farMetres, more);
        }

        /** The same request drawing every face, turned to the eye or not (as before back faces were culled). */
        public ViewRequest withBackFaces() {
            return with(Option.BACK_FACES);
        }

        public boolean colour() {
            return options.contains(Option.COLOUR);
        }

        public boolean rangeTarget() {
            return options.contains(Option.RANGE_TARGET);
        }

        public boolean surfaces() {
            return options.contains(Option.SURFACES);
        }

        public boolean release() {
            return options.contains(Option.RELEASE);
        }

        public boolean drawBackFaces() {
            return options.contains(Option.BACK_FACES);
        }
    }

    /**
     * Renders the views of a layout, the eye at the scene's origin looking horizontally: colour and
     * the depth mode's target, GL buffers freed afterwards when {@code release}.
     *
     * @param scene eye-relative scene (x east, y up, z south)
     */
    public ViewCapture[] render(Node scene, ViewLayout layout, DepthMode mode, double nearMetres, double farMetres,
                                boolean release) {
        ViewRequest r = ViewRequest.of(layout, mode, nearMetres, farMetres);
        return render(scene, release ? r.with(ViewRequest.Option.RELEASE) : r, new long[2]);
    }

    /**
     * Renders the views a request asks for, also reporting where the time went:
     * {@code drawAndReadNanos[0]} receives the time to draw (up to glFinish), {@code [1]} the time to
     * read the targets back.
     *
     * @param scene eye-relative scene (x east, y up, z south)
     */
    public ViewCapture[] render(Node scene, ViewRequest request, long[] drawAndReadNanos) {
        return render(scene, request, drawAndReadNanos, capture -> { });
    }

    /**
     * As {@link #render(Node, ViewRequest, long[])}, handing each view's capture to {@code onView} as soon as it is
     * read back, in view order, so that a caller can work on the first views while the others are drawn. {@code
     * onView} runs on the GL thread and must only pass the capture on (the next view is drawn after it returns).
     */
    public ViewCapture[] render(Node scene, ViewRequest request, long[] drawAndReadNanos,
                                java.util.function.Consumer<ViewCapture> onView) {
        return onGlThread("rendering", () -> app.renderViews(scene, request, drawAndReadNanos, onView));
    }

    /** A GL task's result or what it threw (never thrown on the GL thread: jME would log it and hang the caller). */
    private record Outcome<T>(T value, Throwable failure) {
    }

    /**
     * Runs work on the GL thread and waits for it. Whatever the work throws reaches the caller; an
     * {@link Error} there (out of memory above all) leaves GL state unknown, so the renderer is then
     * closed and says so on every later call. A GL thread that ended while the caller waited is
     * reported instead of waited on forever.
     */
    private <T> T onGlThread(String what, java.util.concurrent.Callable<T> work) {
        checkUsable();
        Future<Outcome<T>> f = app.enqueue(() -> {
            try {
                return new Outcome<>(work.call(), null);
            } catch (Throwable t) {
                if (t instanceof Error) {
                    app.fatal = t;
                }
                return new Outcome<>(null, t);
            }
        });
        Outcome<T> outcome;
        try {
            while (true) {
                try {
                    outcome = f.get(200, TimeUnit.MILLISECONDS);
                    break;
                } catch (TimeoutException e) {
                    Thread t = app.glThread;
                    if (t == null || !t.isAlive() || app.fatal != null) {
                        Throwable cause = app.fatal;
                        markBroken();
                        throw new RenderFailedException("the OpenGL thread ended while " + what
                                + (cause == null ? "" : " (" + cause + ")") + "; open a new renderer", cause);
                    }
                }
            }
        } catch (InterruptedException e) {
            throw dempano.util.Threads.interrupted(what, e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(what + " failed: " + e.getCause(), e.getCause());
        }
        Throwable failure = outcome.failure();
        if (failure == null) {
            return outcome.value();
        }
        if (failure instanceof OutOfMemoryError oom) {
            markBroken();
            throw oom; // the caller's thread reports it (the CLI with the way out)
        }
        if (failure instanceof Error err) {
            markBroken();
            throw new RenderFailedException("the OpenGL thread failed while " + what + ": " + err + "; open a new renderer", err);
        }
        if (failure instanceof RuntimeException re) {
            throw re;
        }
        throw new IllegalStateException(what + " failed: " + failure, failure);
    }

    /** Throws when the GL thread failed earlier or the renderer is closed. */
    private void checkUsable() {
        Throwable fatal = app.fatal;
        if (fatal != null) {
            throw new RenderFailedException("this renderer's OpenGL thread failed earlier (" + fatal
                    + "); open a new renderer", fatal);
        }
        if (closed) {
            throw new IllegalStateException("renderer is closed");
        }
        Thread t = app.glThread;
        if (t != null && !t.isAlive()) {
            throw new RenderFailedException("this renderer's OpenGL thread has ended; open a new renderer", null);
        }
    }

    /** After a failure on the GL thread: no more work goes there; the next acquire makes a new context. */
    private void markBroken() {
        if (app.fatal == null) {
            app.fatal = new IllegalStateException("the OpenGL thread ended");
        }
        synchronized (OffscreenRenderer.class) {
            if (shared == this) {
                shared = null; // the handles still held release nothing of a new context
            }
        }
        if (!closed) {
            closed = true;
            app.stop(false);
        }
    }

    /**
     * Frees the GL buffers of geometries no longer drawn, then their native memory (on the GL
     * thread; returns when done).
     */
    public void release(java.util.Collection<? extends Spatial> parts) {
        if (parts.isEmpty() || closed || app.fatal != null) {
            return;
        }
        onGlThread("releasing buffers", () -> {
            for (Spatial s : parts) {
                GlApp.deleteGlBuffers(app.getRenderer(), s);
                dempano.terrain.TerrainBuilder.destroyBuffers(s);
            }
            return null;
        });
    }

    private void close() {
        if (closed) {
            Thread t = app.glThread;
            if (t != null && t.isAlive() && t != Thread.currentThread()) {
                app.stop(false); // a broken renderer: make sure its thread goes
            }
        } else {
            closed = true;
            app.stop(true);
            // stop(true) returns once the context is marked destroyed, which jME does before its thread
            // calls glfwTerminate: a context created meanwhile would be terminated under its feet
            // ("Failed to create display"). Wait for the GL thread itself to end.
            Thread t = app.glThread;
            if (t != null && t != Thread.currentThread()) {
                try {
                    t.join(TimeUnit.SECONDS.toMillis(START_TIMEOUT_SECONDS));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }

    /** The standard projection (OpenGL clip z in [-1, 1]) for an off-axis frustum given as image-plane tangents. */
    static Matrix4f standardProjection(double l, double r, double b, double t, double n, double f) {
        return new Matrix4f(
                (float) (2 / (r - l)), 0, (float) ((r + l) / (r - l)), 0,
                0, (float) (2 / (t - b)), (float) ((t + b) / (t - b)), 0,
                0, 0, (float) (-(f + n) / (f - n)), (float) (-2 * f * n / (f - n)),
                0, 0, -1, 0);
    }

    /** Reversed-Z projection with an infinite far plane (clip z in [0, 1], depth = n / z_e). */
    static Matrix4f reversedProjection(double l, double r, double b, double t, double n) {
        return new Matrix4f(
                (float) (2 / (r - l)), 0, (float) ((r + l) / (r - l)), 0,
                0, (float) (2 / (t - b)), (float) ((t + b) / (t - b)), 0,
                0, 0, 0, (float) n,
                0, 0, -1, 0);
    }

    private static final class GlApp extends LegacyApplication {
        final CompletableFuture<String[]> ready = new CompletableFuture<>();
        volatile Thread glThread;
        /** Set when an Error struck the GL thread (its GL state is then unknown). */
        volatile Throwable fatal;
        private FrameBuffer fb;
        private int fbWidth, fbHeight;
        private boolean fbReversed;

        @Override
        public void initialize() {
            glThread = Thread.currentThread();
            try {
                super.initialize();
                String version = GL11.glGetString(GL11.GL_VERSION);
                String renderer = GL11.glGetString(GL11.GL_RENDERER);
                int major = GL11.glGetInteger(GL30.GL_MAJOR_VERSION), minor = GL11.glGetInteger(GL30.GL_MINOR_VERSION);
                if (major < 4 || (major == 4 && minor < 5)) {
                    throw new IllegalStateException("OpenGL " + major + "." + minor + " (" + renderer
                            + ") is too old: dempano needs 4.5 (clip control)");
                }
                ready.complete(new String[] {renderer, version});
            } catch (RuntimeException e) {
                ready.completeExceptionally(e);
                throw e;
            }
        }

        @Override
        public void handleError(String errMsg, Throwable t) {
            // jME would log and carry on (exit code 0); make the failure reach the caller instead.
            LOG.log(Level.FINE, errMsg, t);
            if (glThread == null) {
                glThread = Thread.currentThread(); // a context that failed to start: it still ends GLFW on this thread
            }
            if (ready.isDone() && fatal == null) {
                fatal = t != null ? t : new IllegalStateException(errMsg);
            }
            if (!ready.isDone()) {
                // GLFW's errors come as errMsg and again as t's message: say it once.
                boolean repeats = t == null || t.getMessage() == null || errMsg.contains(t.getMessage());
                ready.completeExceptionally(new IllegalStateException(errMsg + (repeats ? "" : ": " + t.getMessage()), t));
            }
            stop(false);
        }

        private FrameBuffer framebuffer(int w, int h, boolean reversed) {
            if (fb != null && fbWidth == w && fbHeight == h && fbReversed == reversed) {
                return fb;
            }
            if (fb != null) {
                renderer.deleteFrameBuffer(fb);
            }
            fb = new FrameBuffer(w, h, 1);
            fb.addColorTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.RGBA8));
            // The range in metres (a float's bits) and which triangle (its number in the scene).
            fb.addColorTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.RG32UI));
            fb.setDepthTarget(FrameBuffer.FrameBufferTarget.newTarget(reversed ? Image.Format.Depth32F : Image.Format.Depth24));
            fb.setMultiTarget(true);
            fbWidth = w;
            fbHeight = h;
            fbReversed = reversed;
            return fb;
        }

        ViewCapture[] renderViews(Node scene, ViewRequest request, long[] nanos, java.util.function.Consumer<ViewCapture> onView) {
            ViewLayout layout = request.layout();
            DepthMode mode = request.mode();
            double near = request.nearMetres(), far = request.farMetres();
            boolean withColour = request.colour(), readRangeTarget = request.rangeTarget(), surfaces = request.surfaces();
            int w = layout.widthPx(), h = layout.heightPx();
            boolean reversed = mode.reversedZ();
            FrameBuffer target = framebuffer(w, h, reversed);
            Camera cam = new Camera(w, h);
            double half = layout.halfWidthTan();
            cam.setFrustum((float) near, (float) far, (float) (-half * near), (float) (half * near),
                    (float) (layout.topTan() * near), (float) (layout.bottomTan() * near));
            cam.setProjectionMatrix(reversed
                    ? reversedProjection(-half, half, layout.bottomTan(), layout.topTan(), near)
                    : standardProjection(-half, half, layout.bottomTan(), layout.topTan(), near, far));
            cam.setLocation(Vector3f.ZERO);
            setDepthState(scene, reversed, request.drawBackFaces());
            scene.updateLogicalState(0);
            scene.updateGeometricState();
            ViewPort vp = renderManager.createPreView("dempano-view", cam);
            vp.setClearFlags(false, false, false);
            vp.attachScene(scene);
            vp.setOutputFrameBuffer(target);
            // Culling by azimuth sector, computed here from each mesh's own bounds (the eye is at the
            // origin of every view; jME's hierarchical bounds are not relied on).
            java.util.List<Geometry> geometries = new java.util.ArrayList<>();
            scene.depthFirstTraversal(sp -> {
                sp.setCullHint(Spatial.CullHint.Never);
                if (sp instanceof Geometry g) {
                    geometries.add(g);
                }
            });
            double[][] sectors = new double[geometries.size()][];
            for (int i = 0; i < sectors.length; i++) {
                sectors[i] = AzimuthSector.of(geometries.get(i));
            }
            ViewCapture[] out = new ViewCapture[layout.views()];
            ByteBuffer colour = ByteBuffer.allocateDirect(w * h * 4).order(ByteOrder.nativeOrder());
            FloatBuffer depth = ByteBuffer.allocateDirect(w * h * 4).order(ByteOrder.nativeOrder()).asFloatBuffer();
            IntBuffer rangeAndTriangle = surfaces
                    ? ByteBuffer.allocateDirect(w * h * 8).order(ByteOrder.nativeOrder()).asIntBuffer() : null;
            int[] pairs = surfaces ? new int[2 * w * h] : null;
            try {
                for (int k = 0; k < layout.views(); k++) {
                    if (layout.ring()) {
                        double az = Math.toRadians(layout.axisAzimuthDeg(k));
                        cam.lookAtDirection(new Vector3f((float) Math.sin(az), 0, (float) -Math.cos(az)), Vector3f.UNIT_Y);
                    } else { // east-north-up to jME's axes: x east, y up, z south
                        double[] a = layout.axes(k);
                        cam.lookAtDirection(new Vector3f((float) a[6], (float) a[8], (float) -a[7]),
                                new Vector3f((float) a[3], (float) a[5], (float) -a[4]));
                    }
                    cam.setLocation(Vector3f.ZERO);
                    double[] viewSector = layout.azimuthSectorDeg(k);
                    for (int i = 0; i < sectors.length; i++) {
                        geometries.get(i).setCullHint(viewSector == null
                                || AzimuthSector.overlaps(sectors[i], viewSector[0], viewSector[1])
                                ? Spatial.CullHint.Never : Spatial.CullHint.Always);
                    }
                    renderer.setFrameBuffer(target);
                    GL45.glClipControl(GL30.GL_LOWER_LEFT, reversed ? GL45.GL_ZERO_TO_ONE : GL45.GL_NEGATIVE_ONE_TO_ONE);
                    GL11.glDepthMask(true);
                    GL11.glColorMask(true, true, true, true);
                    GL30.glClearBufferfv(GL11.GL_COLOR, 0, OffscreenRenderer.SKY_RGBA);
                    GL30.glClearBufferuiv(GL11.GL_COLOR, 1, new int[] {0, 0, 0, 0});
                    GL30.glClearBufferfv(GL11.GL_DEPTH, 0, new float[] {reversed ? 0f : 1f});
                    long t0 = System.nanoTime();
                    renderManager.render(0, false);
                    renderer.setFrameBuffer(target);
                    GL11.glFinish(); // so that drawing and reading back are timed apart
                    long t1 = System.nanoTime();
                    GL11.glPixelStorei(GL11.GL_PACK_ALIGNMENT, 1);
                    byte[] rgba = null;
                    if (withColour) {
                        GL11.glReadBuffer(GL30.GL_COLOR_ATTACHMENT0);
                        colour.clear();
                        GL11.glReadPixels(0, 0, w, h, GL11.GL_RGBA, GL11.GL_UNSIGNED_BYTE, colour);
                        rgba = new byte[w * h * 4];
                        colour.get(rgba);
                    }
                    float[] d = new float[w * h];
                    int[] triangleIds = null;
                    if (surfaces) {
                        // One read of the whole range target: the range's bits and the triangle.
                        GL11.glReadBuffer(GL30.GL_COLOR_ATTACHMENT1);
                        rangeAndTriangle.clear();
                        GL11.glReadPixels(0, 0, w, h, GL30.GL_RG_INTEGER, GL11.GL_UNSIGNED_INT, rangeAndTriangle);
                        rangeAndTriangle.get(pairs); // one bulk copy: the loop below then reads a heap array
                        triangleIds = new int[w * h];
                        split(pairs, readRangeTarget ? d : null, triangleIds);
                    }
                    if (!readRangeTarget || !surfaces) {
                        depth.clear();
                        if (readRangeTarget) {
                            // The red channel alone: the range's bits.
                            GL11.glReadBuffer(GL30.GL_COLOR_ATTACHMENT1);
                            GL11.glReadPixels(0, 0, w, h, GL30.GL_RED_INTEGER, GL11.GL_UNSIGNED_INT, depth);
                        } else {
                            GL11.glReadPixels(0, 0, w, h, GL11.GL_DEPTH_COMPONENT, GL11.GL_FLOAT, depth);
                        }
                        depth.get(d);
                    }
                    GL11.glReadBuffer(GL30.GL_COLOR_ATTACHMENT0);
                    int err = GL11.glGetError();
                    if (err != GL11.GL_NO_ERROR) {
                        throw new IllegalStateException("OpenGL error 0x" + Integer.toHexString(err) + " rendering view " + k);
                    }
                    out[k] = new ViewCapture(k, rgba, d, triangleIds);
                    nanos[0] += t1 - t0;
                    nanos[1] += System.nanoTime() - t1;
                    onView.accept(out[k]);
                }
            } finally {
                GL45.glClipControl(GL30.GL_LOWER_LEFT, GL45.GL_NEGATIVE_ONE_TO_ONE);
                vp.detachScene(scene);
                renderManager.removePreView(vp);
                renderer.setFrameBuffer(null);
                if (request.release()) {
                    deleteGlBuffers(renderer, scene);
                }
            }
            return out;
        }

        /**
         * The range target's pairs apart: the ranges into {@code ranges} (unless null) and the triangle names into
         * {@code triangleIds} (−1 where nothing was drawn). A method of its own so that the JIT compiles this loop
         * alone, not the whole of renderViews on-stack.
         */
        private static void split(int[] pairs, float[] ranges, int[] triangleIds) {
            for (int i = 0, o = 0; i < triangleIds.length; i++, o += 2) {
                float range = Float.intBitsToFloat(pairs[o]);
                if (ranges != null) {
                    ranges[i] = range;
                }
                triangleIds[i] = range > 0 ? pairs[o + 1] : -1;
            }
        }

        /**
         * The depth test for the projection, and the faces culled: the back faces of terrain whose triangles all face
         * out ({@link TerrainBuilder#CULL_BACK_FACES}), unless asked to draw them; none of any other geometry.
         */
        private static void setDepthState(Spatial s, boolean reversed, boolean drawBackFaces) {
            if (s instanceof Geometry g) {
                RenderState rs = g.getMaterial().getAdditionalRenderState();
                rs.setDepthFunc(reversed ? RenderState.TestFunction.GreaterOrEqual : RenderState.TestFunction.LessOrEqual);
                rs.setFaceCullMode(!drawBackFaces && Boolean.TRUE.equals(g.getUserData(TerrainBuilder.CULL_BACK_FACES))
                        ? RenderState.FaceCullMode.Back : RenderState.FaceCullMode.Off);
            } else if (s instanceof Node n) {
                for (Spatial c : n.getChildren()) {
                    setDepthState(c, reversed, drawBackFaces);
                }
            }
        }

        private static void deleteGlBuffers(Renderer renderer, Spatial s) {
            if (s instanceof Geometry g) {
                for (VertexBuffer vb : g.getMesh().getBufferList()) {
                    renderer.deleteBuffer(vb);
                }
            } else if (s instanceof Node n) {
                for (Spatial c : n.getChildren()) {
                    deleteGlBuffers(renderer, c);
                }
            }
        }
    }
}
