package dempano;

import com.jme3.material.Material;
import dempano.dem.DemSource;
import dempano.dem.Mosaic;
import dempano.geo.Viewpoint;
import dempano.geo.ViewpointAdjustment;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.LayerComputer;
import dempano.panorama.NearTerrain;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.PanoramaMetadata;
import dempano.panorama.Silhouettes;
import dempano.panorama.Stitcher;
import dempano.panorama.ViewCapture;
import dempano.panorama.ViewLayout;
import dempano.camera.CameraView;
import dempano.camera.PanoramaTarget;
import dempano.camera.TargetImage;
import dempano.render.OffscreenRenderer;
import dempano.panorama.SeenTriangles;
import dempano.reference.TerrainRayProbe;
import dempano.terrain.DeviationCache;
import dempano.terrain.EyePlacement;
import dempano.terrain.SeenTriangleResolver;
import dempano.terrain.MeshCache;
import dempano.terrain.TerrainBuilder;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * The entry point for pipelines: open once, render many panoramas, close.
 *
 * <pre>{@code
 * try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(Path.of("dem")))) {
 *     Panorama p = r.render(PanoramaRequest.at(46.4314, 8.0942));
 *     double metres = p.distanceAt(135.0, 2.5);
 * }
 * }</pre>
 *
 * Thread-safe: DEM loading and mesh building run on the calling thread; GL work is serialized onto
 * one GL thread.
 */
public final class PanoramaRenderer implements AutoCloseable {
    private final DemSource dem;
    /** The GL context's handle, being created (see {@link #openInBackground}) or made; null for the CPU reference. */
    private final java.util.concurrent.CompletableFuture<OffscreenRenderer.Handle> handle;
    /** Patch deviations of this DEM source, kept across renders (level of detail costs a lookup then). */
    private final DeviationCache deviations = new DeviationCache();
    /** Fine patches' geometries with their GL buffers, kept across renders; one render uses it at a time. */
    private final MeshCache meshes = new MeshCache();
    private final java.util.concurrent.locks.ReentrantLock meshLock = new java.util.concurrent.locks.ReentrantLock();
    /** Set by the first {@link #close}: later renders are refused at once, later closes do nothing. */
    private final java.util.concurrent.atomic.AtomicBoolean closed = new java.util.concurrent.atomic.AtomicBoolean();
    /** False after {@link #withoutMeshCache}. */
    private volatile boolean keepMeshes = true;

    /** The thread creating the context ({@link #openInBackground}), else null. */
    private final Thread starter;

    private PanoramaRenderer(DemSource dem, java.util.concurrent.CompletableFuture<OffscreenRenderer.Handle> handle) {
        this(dem, handle, null);
    }

    private PanoramaRenderer(DemSource dem, java.util.concurrent.CompletableFuture<OffscreenRenderer.Handle> handle,
                             Thread starter) {
        this.dem = dem;
        this.handle = handle;
        this.starter = starter;
    }

    /**
     * The context's handle, waiting while it is being created. Where the creating thread ended without a result (out
     * of memory even for reporting its failure, as a resident process with a tiny heap showed) a wait would last for
     * ever: that is a {@link java.util.concurrent.CompletionException} as any failure to create it.
     */
    private OffscreenRenderer.Handle awaitHandle() {
        boolean interrupted = false; // waited for regardless, as join() did; the flag is kept
        try {
            while (true) {
                try {
                    return handle.get(200, java.util.concurrent.TimeUnit.MILLISECONDS);
                } catch (java.util.concurrent.TimeoutException e) {
                    if (starter != null && !starter.isAlive() && !handle.isDone()) {
                        throw new java.util.concurrent.CompletionException(new dempano.render.GlUnavailableException(
                                "the OpenGL context's start ended without a result (out of memory?)", null));
                    }
                } catch (java.util.concurrent.ExecutionException e) {
                    throw new java.util.concurrent.CompletionException(e.getCause());
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** True for the CPU reference renderer (no GL context). */
    private boolean reference() {
        return handle == null;
    }

    /**
     * The GL renderer, waiting for its context where it is still being created.
     *
     * @throws dempano.render.GlUnavailableException as {@link #open} would have
     */
    private OffscreenRenderer gl() {
        try {
            return awaitHandle().renderer();
        } catch (java.util.concurrent.CompletionException e) {
            if (e.getCause() instanceof RuntimeException re) {
                throw re;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw e;
        }
    }

    /** The DEM this renderer draws (for looking up heights beside a render, e.g. summits without one). */
    public DemSource dem() {
        return dem;
    }

    /** Name of the CPU reference renderer, as metadata reports it. */
    public static final String REFERENCE_RENDERER = "dempano CPU reference (horizon sweep, double precision)";

    /** Per tile used, the sources that served it (see {@link Mosaic#tileSources()}). */
    private static List<PanoramaMetadata.TileSource> demSources(Mosaic mosaic) {
        List<PanoramaMetadata.TileSource> out = new ArrayList<>();
        mosaic.tileSources().forEach((id, list) -> list.forEach(c ->
                out.add(new PanoramaMetadata.TileSource(id.name(), c.source(), c.verticalDatum(), c.samples()))));
        return out;
    }

    /**
     * Keeps the patch deviations this renderer measures in a store on disk, and takes those measured by earlier
     * processes from it ({@link DeviationStore}: served only for the same heights). Call before rendering; null for
     * none (the default). Returns this renderer.
     */
    public PanoramaRenderer withDeviationStore(dempano.terrain.DeviationStore store) {
        deviations.useDisk(store);
        return this;
    }

    /**
     * Keeps no terrain meshes from render to render: each render's meshes (their Java buffers and GL copies) are
     * freed once its views are drawn and the triangles seen resolved, before the stitch, instead of being kept for
     * the next render's patches. For one panorama per process (the CLI's), where nothing would be drawn again: the
     * CLI's peak resident memory at Mount Washington (−10…5°, 20 px/°, 100 km) falls from 776–777 MB, reached
     * during the stitch, to 732–734 MB (docs/cold-start.md). Call before rendering. Returns this renderer.
     */
    public PanoramaRenderer withoutMeshCache() {
        keepMeshes = false;
        return this;
    }

    /**
     * Opens a renderer that needs no OpenGL: the exact CPU reference
     * ({@link dempano.reference.ReferenceRenderer}). Same requests and outputs; the depth mode,
     * views and supersampling do not apply. Slower than a GPU, exact to micrometres.
     */
    public static PanoramaRenderer openReference(DemSource dem) {
        Objects.requireNonNull(dem, "dem");
        return new PanoramaRenderer(dem, null);
    }

    /**
     * Opens a renderer on a DEM source, creating the OpenGL context.
     *
     * @throws dempano.render.GlUnavailableException when no OpenGL context can be had (message says why)
     */
    public static PanoramaRenderer open(DemSource dem) {
        Objects.requireNonNull(dem, "dem"); // before the context is made
        return new PanoramaRenderer(dem, java.util.concurrent.CompletableFuture.completedFuture(OffscreenRenderer.acquire()));
    }

    /**
     * Opens a renderer whose OpenGL context is created on another thread meanwhile, with the terrain shader's
     * definition loaded: the first render loads its tiles and builds its mesh while the context starts
     * (a cold start from the shell: docs/cold-start.md). A failure to create the context is thrown, as by
     * {@link #open}, by the first call that needs it ({@link #glRenderer()}, a render); {@link #close()} waits
     * for the context and ends it.
     */
    public static PanoramaRenderer openInBackground(DemSource dem) {
        Objects.requireNonNull(dem, "dem");
        java.util.concurrent.CompletableFuture<OffscreenRenderer.Handle> pending = new java.util.concurrent.CompletableFuture<>();
        Thread starter = new Thread(() -> {
            try {
                OffscreenRenderer.Handle h = OffscreenRenderer.acquire();
                try {
                    h.renderer().newTerrainMaterial(1000); // loads the material definition (cached by the asset manager)
                } catch (RuntimeException e) {
                    // the render that needs it says so
                }
                pending.complete(h);
            } catch (Throwable t) {
                pending.completeExceptionally(t);
            }
        }, "dempano-gl-start");
        starter.setDaemon(true);
        starter.start();
        return new PanoramaRenderer(dem, pending, starter);
    }

    /** The OpenGL renderer in use. */
    public String glRenderer() {
        return reference() ? REFERENCE_RENDERER : gl().glRenderer();
    }

    public Panorama render(PanoramaRequest request) {
        return render(request, stage -> { });
    }

    /**
     * Renders a panorama, reporting each stage as it starts.
     *
     * @throws dempano.dem.DemException      for unreadable or ambiguous tiles, and missing ones as the request's
     *                                       {@link dempano.dem.MissingTilePolicy} says
     * @throws IllegalArgumentException      for a viewpoint without DEM data
     * @throws InsufficientMemoryException   before rendering, when the request needs more heap than the JVM may use
     * @throws dempano.render.RenderFailedException when the GL thread fails (the renderer is then closed)
     * @throws IllegalStateException         when this renderer was closed; a
     *                                       {@link java.util.concurrent.CancellationException} when the calling thread
     *                                       was interrupted (its interrupt flag is set again)
     * @throws NullPointerException          naming a null argument
     */
    public Panorama render(PanoramaRequest req, Consumer<String> progress) {
        Objects.requireNonNull(req, "request");
        Objects.requireNonNull(progress, "progress");
        checkOpen();
        Stopwatch clock = new Stopwatch();
        progress.accept("loading tiles");
        Mosaic mosaic = tiles(req, clock);
        MemoryEstimate.of(req, !reference(), tileBytes(mosaic)).check(Runtime.getRuntime().maxMemory());
        Viewpoint requested = Double.isNaN(req.altitudeMetres())
                ? Viewpoint.onDem(mosaic, req.latDeg(), req.lonDeg(), req.offsetMetres(), req.eyeHeightMetres())
                : Viewpoint.atAltitude(mosaic, req.latDeg(), req.lonDeg(), req.altitudeMetres(), req.eyeHeightMetres());
        Scene scene = new Scene(mosaic, ViewpointAdjustment.apply(mosaic, requested, req.snapToSummitMetres(),
                req.clearViewMetres(), req.refraction()));
        if (reference()) {
            return renderReference(req, scene, clock, progress);
        }
        ElevationRange er = req.elevationRange();
        // Terrain wholly below the lowest view row the stitcher samples (the bottom row's 4×4
        // neighbourhood reaches two view pixels lower) is left out with what nearer terrain hides.
        double cullBelowDeg = er.bottomDeg() - 3 / req.pixelsPerDegree();
        PanoramaGeometry geometry = PanoramaGeometry.of(req.pixelsPerDegree(), er.bottomDeg(), er.topDeg());
        ViewLayout layout = ViewLayout.forPanorama(geometry, req.views(), req.supersampling());
        Drawn drawn = drawAndStitch(req, scene, new Views(new PanoramaTarget(geometry), layout, req.pixelsPerDegree(),
                cullBelowDeg), clock, progress);
        return finish(req, scene, geometry, drawn.images(), drawing(req, layout, drawn), clock, progress);
    }

    /** Bytes the mosaic's tiles take, for the memory estimate. */
    private static long tileBytes(Mosaic mosaic) {
        long samplesPerTile = (long) (mosaic.intervalsPerDegree() + 1) * (mosaic.intervalsPerDegree() + 1);
        return Math.max(2 * samplesPerTile * mosaic.tilesUsed().size(), mosaic.tileBytes());
    }

    /**
     * Renders a camera's own view on its pixel grid through the panorama's pipeline: the views that cover the
     * camera's rays ({@link ViewLayout#forTarget}), drawn and resampled as a panorama's are, with exact
     * per-pixel distances when the settings ask for them. The silhouettes are drawn into the colour.
     *
     * On the CPU reference renderer ({@link #openReference}) every pixel's own ray is cast on the triangulated
     * surface instead ({@link dempano.reference.RayCastReference}); the views, depth mode and supersampling do not
     * apply.
     *
     * @throws IllegalArgumentException for a viewpoint without DEM data or a field of view too wide for
     *                                  perspective views
     */
    public CameraImage render(CameraRequest request, Consumer<String> progress) {
        Objects.requireNonNull(request, "request");
        Objects.requireNonNull(progress, "progress");
        checkOpen();
        PanoramaRequest req = request.settings();
        CameraView view = request.view();
        ViewLayout layout = reference() ? null : ViewLayout.forTarget(view, req.supersampling());
        Stopwatch clock = new Stopwatch();
        progress.accept("loading tiles");
        Mosaic mosaic = tiles(req, clock);
        MemoryEstimate.of(request, layout, tileBytes(mosaic)).checkCamera(Runtime.getRuntime().maxMemory());
        Viewpoint eye = request.pose().viewpoint(mosaic);
        Scene scene = new Scene(mosaic, ViewpointAdjustment.apply(mosaic, eye, Double.NaN, Double.NaN, req.refraction()));
        if (reference()) {
            return renderCameraReference(request, scene, clock, progress);
        }
        double viewPixelDeg = Math.toDegrees(2 * layout.halfWidthTan() / layout.widthPx());
        // Terrain wholly below the views' lowest ray, less three view pixels (the 4×4 neighbourhoods), is left out.
        double cullBelowDeg = layout.lowestElevationDeg() - 3 * viewPixelDeg;
        Drawn drawn = drawAndStitch(req, scene, new Views(view, layout, 1 / viewPixelDeg, cullBelowDeg), clock, progress);
        return finishCamera(request, scene, drawn.images(), drawing(req, layout, drawn), clock, progress, List.of());
    }

    /** A camera's silhouettes, layers, near-terrain warning and metadata. */
    private CameraImage finishCamera(CameraRequest request, Scene scene, Images images, Drawing drawing, Stopwatch clock,
                                     Consumer<String> progress, List<String> renderWarnings) {
        PanoramaRequest req = request.settings();
        CameraView view = request.view();
        if (images.argb() != null) {
            Silhouettes.draw(images.argb(), images.distance(), view.widthPx(), view.heightPx());
        }
        if (!req.layers().isEmpty()) {
            progress.accept("computing layers " + req.layers());
        }
        var layers = LayerComputer.compute(req.layers(), view, images.distance(),
                new LayerComputer.Surroundings(scene.eye().eyeFrame(), req.refraction(), scene.mosaic()));
        if (!req.layers().isEmpty()) {
            clock.lap("layers");
        }
        List<String> warnings = new ArrayList<>(scene.mosaic().warnings());
        scene.eye().filledVoidWarning(scene.mosaic()).ifPresent(warnings::add);
        warnings.addAll(renderWarnings);
        if (req.distance()) {
            NearTerrain.measure(view, images.distance(), NearTerrain.DEFAULT_NEAR_METRES).cameraWarning().ifPresent(warnings::add);
        }
        PanoramaMetadata meta = metadata(req, scene, drawing, clock.timings, warnings);
        return new CameraImage(view, request.pose(),
                new CameraImage.Pixels(images.argb(), req.distance() ? images.distance() : null, layers), meta);
    }

    /** A camera's view by the CPU reference: every pixel's own ray cast on the triangulated surface. */
    private CameraImage renderCameraReference(CameraRequest request, Scene scene, Stopwatch clock, Consumer<String> progress) {
        PanoramaRequest req = request.settings();
        CameraView view = request.view();
        progress.accept("casting " + view.widthPx() + "×" + view.heightPx() + " rays on the CPU");
        var result = dempano.reference.RayCastReference.render(
                new dempano.reference.RayCastReference.Scene(scene.mosaic(), scene.eye(), req.refraction()),
                req.rangeMetres(), view, req.colour());
        clock.lap("render");
        List<String> undecided = result.undecided() == 0 ? List.of() : List.of(result.undecided()
                + " rays could not be decided (the eye inside the terrain?): NaN in the distances");
        return finishCamera(request, scene, new Images(result.argb(), result.distanceMetres()),
                new Drawing(0, 0, 0, Double.POSITIVE_INFINITY, Double.NaN, 0, 0), clock, progress, undecided);
    }

    /** {@link #render(CameraRequest, Consumer)} without progress reports. */
    public CameraImage render(CameraRequest request) {
        return render(request, stage -> { });
    }

    /**
     * The DEM's surface at the request's coordinate, metres above sea level (the drawn surface a viewpoint stands on,
     * {@link Mosaic#heightAt}), from the tiles a render there loads (kept for it); NaN in a void or on a missing tile.
     *
     * @throws IllegalArgumentException as a render there would for missing tiles its policy refuses
     */
    public double groundElevationMetres(PanoramaRequest at) {
        Objects.requireNonNull(at, "at");
        return tiles(at, new Stopwatch()).heightAt(at.latDeg(), at.lonDeg());
    }

    /** The tiles around the request's coordinate, checked as its missing-tile policy says. */
    private Mosaic tiles(PanoramaRequest req, Stopwatch clock) {
        Mosaic mosaic = Mosaic.around(dem, req.latDeg(), req.lonDeg(), req.rangeMetres(), req.missingTiles());
        req.missingTiles().checkData(mosaic, req.latDeg(), req.lonDeg(), req.altitudeMetres());
        clock.lap("tiles");
        return mosaic;
    }

    /**
     * Where the eye is and the DEM around it.
     *
     * @param adjusted the eye as placed (after any viewpoint adjustment) and how it moved
     */
    private record Scene(Mosaic mosaic, ViewpointAdjustment.Adjusted adjusted) {
        Viewpoint eye() {
            return adjusted.eye();
        }
    }

    /**
     * The views as drawn and stitched.
     *
     * @param images     the target's pixels
     * @param nearMetres near plane used
     * @param farMetres  far plane used
     */
    private record Drawn(Images images, double nearMetres, double farMetres, long triangles) {
    }

    /** A target's pixels: colour (ARGB, null when not rendered) and distance (metres, +∞ sky), row-major. */
    private record Images(int[] argb, float[] distance) {
    }

    /** Stage timings in milliseconds, in the order the stages ran, and the clock between them. */
    private static final class Stopwatch {
        final Map<String, Double> timings = new LinkedHashMap<>();
        long since = System.nanoTime();

        void lap(String stage) {
            long now = System.nanoTime();
            timings.put(stage, (now - since) / 1e6);
            since = now;
        }
    }

    /**
     * Passes a render's views are stitched in, each as soon as its views are drawn, while the GL thread draws the
     * next pass's: at Mount Washington (8 views) the whole process took 2.29 s with 4 passes, 2.33 s with 2, 2.41 s
     * with 1 (5 alternating runs). Stitching a pass on one core only, to leave the other to the drawing, was slower
     * (drawing uses about 1.2 cores; the stitch is the longer part).
     */
    static final int STITCH_PASSES = 4;

    /** {@link #STITCH_PASSES}, or another count for tests (the passes never change a bit of the output). */
    private volatile int stitchPasses = STITCH_PASSES;

    /** This renderer stitching in {@code passes} passes (tests: any count gives the same output). */
    PanoramaRenderer withStitchPasses(int passes) {
        if (passes < 1) {
            throw new IllegalArgumentException("passes must be at least 1: " + passes);
        }
        stitchPasses = passes;
        return this;
    }

    /**
     * What is drawn for a target: its views and the terrain the level of detail and culling leave.
     *
     * @param pixelsPerDegree the level of detail's pixel size
     * @param cullBelowDeg    terrain wholly below this elevation is left out
     */
    private record Views(TargetImage target, ViewLayout layout, double pixelsPerDegree, double cullBelowDeg) {
    }

    /**
     * Builds the terrain mesh for the eye, draws the views of a layout and resamples them into the target's pixels
     * (colour, distance; exact distances where asked) in {@link #STITCH_PASSES} passes of consecutive views, each
     * stitched as soon as its views are drawn while the GL thread draws on. The stages "draw" and "readback" (GL
     * thread) therefore overlap "triangles" and "stitch" (this thread's time resolving and stitching).
     */
    private Drawn drawAndStitch(PanoramaRequest req, Scene scene, Views views, Stopwatch clock, Consumer<String> progress) {
        Viewpoint eye = scene.eye();
        Mosaic mosaic = scene.mosaic();
        ViewLayout layout = views.layout();
        progress.accept("building terrain mesh");
        // Far plane: beyond the farthest terrain within range (curvature drops it, height raises it).
        double far = Math.hypot(req.rangeMetres() * 1.05, 20_000) + 1000;
        double near = safeNearMetres(req.nearMetres(), mosaic, eye, layout);
        boolean exact = req.distance() && req.exactDistances();
        Passes passes;
        long triangles;
        // The mesh cache's geometries can be in one scene at a time, so it is held from building to
        // drawing (and the stitching drawing overlaps); a concurrent render builds its own geometry meanwhile.
        boolean withMeshCache = keepMeshes && meshLock.tryLock();
        try {
            // Built without a material: the GL context may still be starting (openInBackground). The material
            // (it needs the context's asset manager) is set on every geometry drawn afterwards.
            TerrainBuilder.Terrain terrain = TerrainBuilder.build(mosaic, eye, req.refraction(), req.rangeMetres(), null,
                    new TerrainBuilder.Detail(views.pixelsPerDegree(), req.lodErrorPx(), 1, deviations,
                            withMeshCache ? meshes : null, views.cullBelowDeg()));
            clock.lap("mesh");
            OffscreenRenderer gl = gl();
            Material material = gl.newTerrainMaterial(req.rangeMetres());
            if (!req.colour()) {
                material.setBoolean("DistanceOnly", true);
            }
            TerrainBuilder.applyEye(material, new EyePlacement(eye, req.refraction()));
            for (com.jme3.scene.Geometry g : terrain.drawn()) {
                g.setMaterial(material);
            }
            clock.lap("context");
            passes = new Passes(req, scene, views, near, far, exact);
            triangles = terrain.triangles();
            progress.accept("rendering " + layout.views() + " views of " + layout.widthPx() + "×" + layout.heightPx()
                    + " (" + triangles / 1_000_000.0 + " M triangles, " + terrain.reusedPatches() + " patches reused)");
            long[] drawAndRead = new long[2];
            long[] renderNanos = new long[1];
            // Colour only reads the range target whatever the depth mode: its nearest samples find the silhouettes.
            java.util.EnumSet<OffscreenRenderer.ViewRequest.Option> reads = java.util.EnumSet.noneOf(OffscreenRenderer.ViewRequest.Option.class);
            if (req.colour()) {
                reads.add(OffscreenRenderer.ViewRequest.Option.COLOUR);
            }
            if (req.depthMode() == DepthMode.SHADER_RANGE || !req.distance()) {
                reads.add(OffscreenRenderer.ViewRequest.Option.RANGE_TARGET);
            }
            if (exact) {
                reads.add(OffscreenRenderer.ViewRequest.Option.SURFACES);
            }
            OffscreenRenderer.ViewRequest request = new OffscreenRenderer.ViewRequest(layout, req.depthMode(), near, far, reads);
            java.util.concurrent.BlockingQueue<Object> arrived = new java.util.concurrent.LinkedBlockingQueue<>();
            Object end = new Object();
            // The GL thread draws on; this thread waits for it on a helper thread of its own, so as to take the
            // captures as they come. The helper ends with the drawing (it is joined before anything is released).
            java.util.concurrent.CompletableFuture<Void> drawing = new java.util.concurrent.CompletableFuture<>();
            Thread helper = new Thread(() -> {
                long t0 = System.nanoTime();
                try {
                    gl.render(terrain.root(), request, drawAndRead, arrived::add);
                    renderNanos[0] = System.nanoTime() - t0;
                    drawing.complete(null);
                } catch (Throwable t) {
                    drawing.completeExceptionally(t);
                } finally {
                    arrived.add(end);
                }
            }, "dempano-draw");
            helper.setDaemon(true);
            try {
                helper.start();
                ViewCapture[] pass = new ViewCapture[layout.views()];
                int received = 0;
                boolean ended = false;
                int passCount = Math.min(stitchPasses, layout.views());
                for (int p = 0; p < passCount && !ended; p++) {
                    // A pass: its share of the views (consecutive: drawn in order), stitched once all came.
                    java.util.Arrays.fill(pass, null);
                    int last = (int) ((long) layout.views() * (p + 1) / passCount);
                    while (received < last) {
                        Object next = take(arrived);
                        if (next == end) {
                            ended = true; // the drawing failed: thrown below
                            break;
                        }
                        ViewCapture c = (ViewCapture) next;
                        pass[c.view()] = c;
                        received++;
                    }
                    if (ended) {
                        break;
                    }
                    if (p == 0) {
                        progress.accept("stitching");
                    }
                    passes.stitch(pass, terrain.drawn());
                }
                joinDrawing(helper, drawing);
            } finally {
                // Never detach or release while the GL thread may still be drawing the scene; release even when
                // interrupted (the flag is kept for the caller).
                dempano.util.Threads.joinUninterruptibly(helper);
                boolean interrupted = Thread.interrupted();
                try {
                    terrain.root().detachAllChildren();
                    List<com.jme3.scene.Spatial> released = new ArrayList<>(terrain.transientParts());
                    released.addAll(terrain.evicted());
                    gl.release(released);
                } finally {
                    if (interrupted) {
                        Thread.currentThread().interrupt();
                    }
                }
            }
            clock.timings.put("upload", (renderNanos[0] - drawAndRead[0] - drawAndRead[1]) / 1e6);
            clock.timings.put("draw", drawAndRead[0] / 1e6);
            clock.timings.put("readback", drawAndRead[1] / 1e6);
            if (exact) {
                clock.timings.put("triangles", passes.resolveNanos / 1e6);
            }
            clock.timings.put("stitch", passes.stitchNanos / 1e6);
            clock.since = System.nanoTime();
        } finally {
            if (withMeshCache) {
                meshLock.unlock();
            }
        }
        if (exact) {
            progress.accept("distances: " + passes.exactPixels + " pixels from the " + passes.seenTriangles
                    + " triangles seen, " + passes.probedPixels + " by probing the terrain, " + passes.fallbackPixels
                    + " by inverse depth");
        }
        return new Drawn(new Images(passes.argb, passes.distance), near, far, triangles);
    }

    /** The next capture (or the end mark); an interrupt ends the render ("interrupted while rendering"). */
    private static Object take(java.util.concurrent.BlockingQueue<Object> queue) {
        try {
            return queue.take();
        } catch (InterruptedException e) {
            throw dempano.util.Threads.interrupted("rendering", e);
        }
    }

    /** Waits for the drawing and throws what it threw, as it threw it. */
    private static void joinDrawing(Thread helper, java.util.concurrent.CompletableFuture<Void> drawing) {
        dempano.util.Threads.joinUninterruptibly(helper);
        try {
            drawing.join();
        } catch (java.util.concurrent.CompletionException e) {
            throw dempano.util.Threads.unchecked(e.getCause());
        }
    }

    /**
     * What one stitch with distances was given: enough to run {@link Stitcher#stitch} again on the same views, which
     * {@link StitchBenchmark} does to time the stitch alone (one per pass; the passes fill disjoint pixels).
     */
    record StitchInputs(TargetImage target, ViewLayout layout, ViewCapture[] captures, float[][] inverseEyeDepth,
                        Stitcher.Exact exact, boolean colour) {
    }

    /** Receives each stitch pass's inputs where set (benchmarks only); null in normal use. */
    static volatile Consumer<StitchInputs> stitchTap;

    /** The stitch of one target, pass by pass: its outputs, its counts and the time it took on this thread. */
    private static final class Passes {
        final PanoramaRequest req;
        final Views views;
        final double nearMetres, farMetres;
        final EyePlacement placement;
        final TerrainRayProbe probe;
        final int[] argb;
        final float[] distance;
        long exactPixels, probedPixels, fallbackPixels, seenTriangles, resolveNanos, stitchNanos;
        private SeenTriangleResolver.Scene resolver;

        Passes(PanoramaRequest req, Scene scene, Views views, double nearMetres, double farMetres, boolean exact) {
            this.req = req;
            this.views = views;
            this.nearMetres = nearMetres;
            this.farMetres = farMetres;
            placement = exact ? new EyePlacement(scene.eye(), req.refraction()) : null;
            probe = exact ? new TerrainRayProbe(scene.mosaic(), scene.eye(), req.refraction(), req.rangeMetres()) : null;
            int pixels = views.target().widthPx() * views.target().heightPx();
            argb = req.colour() ? new int[pixels] : null;
            distance = new float[pixels];
        }

        /**
         * Resolves the triangles a pass's views saw (while the geometries' buffers live) and stitches the pixels that
         * sample those views; {@code pass} holds the pass's captures, null for the other views.
         */
        void stitch(ViewCapture[] pass, List<com.jme3.scene.Geometry> drawn) {
            ViewLayout layout = views.layout();
            SeenTriangles seen = null;
            if (probe != null) {
                long beforeResolve = System.nanoTime();
                if (resolver == null) { // one per render: its tables serve every pass
                    resolver = new SeenTriangleResolver.Scene(drawn, placement, req.rangeMetres());
                }
                seen = resolver.resolve(pass);
                resolveNanos += System.nanoTime() - beforeResolve;
                seenTriangles += seen.triangles();
                for (int k = 0; k < pass.length; k++) { // the raw ids are no longer needed
                    if (pass[k] != null) {
                        pass[k] = new ViewCapture(pass[k].view(), pass[k].rgba(), pass[k].depth());
                    }
                }
            }
            long beforeStitch = System.nanoTime();
            if (req.distance()) {
                // With exact distances on the shader's range, the stitcher converts the few samples it needs itself.
                float[][] inverseEyeDepth = null;
                if (probe == null || req.depthMode() != DepthMode.SHADER_RANGE) {
                    inverseEyeDepth = new float[pass.length][];
                    for (int k = 0; k < pass.length; k++) {
                        if (pass[k] != null) {
                            inverseEyeDepth[k] = Stitcher.inverseEyeDepths(pass[k], layout, req.depthMode(), nearMetres,
                                    farMetres);
                        }
                    }
                }
                Stitcher.Exact exactInputs = probe != null ? new Stitcher.Exact(seen, probe) : null;
                ViewCapture[] captures = pass.clone();
                Consumer<StitchInputs> tap = stitchTap;
                if (tap != null) {
                    tap.accept(new StitchInputs(views.target(), layout, captures, inverseEyeDepth, exactInputs, argb != null));
                }
                Stitcher.Result stitched = Stitcher.stitch(views.target(), layout, captures, inverseEyeDepth, exactInputs,
                        argb, distance);
                exactPixels += stitched.exactPixels();
                probedPixels += stitched.probedPixels();
                fallbackPixels += stitched.fallbackPixels();
            } else {
                Stitcher.stitchColour(views.target(), layout, pass.clone(), argb, distance);
            }
            stitchNanos += System.nanoTime() - beforeStitch;
        }
    }

    private static Drawing drawing(PanoramaRequest req, ViewLayout layout, Drawn drawn) {
        return new Drawing(layout.views(), layout.widthPx(), layout.heightPx(),
                req.depthMode() == DepthMode.STANDARD_24 ? drawn.farMetres() : Double.POSITIVE_INFINITY, drawn.nearMetres(),
                req.lodErrorPx(), drawn.triangles());
    }

    private Panorama renderReference(PanoramaRequest req, Scene scene, Stopwatch clock, Consumer<String> progress) {
        ElevationRange er = req.elevationRange();
        PanoramaGeometry geometry = PanoramaGeometry.of(req.pixelsPerDegree(), er.bottomDeg(), er.topDeg());
        progress.accept("sweeping " + geometry.widthPx() + " columns on the CPU");
        var result = dempano.reference.ReferenceRenderer.render(scene.mosaic(), scene.eye(), req.refraction(),
                req.rangeMetres(), geometry, req.colour());
        clock.lap("render");
        return finish(req, scene, geometry, new Images(result.argb(), result.distanceMetres()),
                new Drawing(0, 0, 0, Double.POSITIVE_INFINITY, Double.NaN, 0, 0), clock, progress);
    }

    /**
     * How the views were drawn, for the metadata (for the CPU reference: no views, no near plane (NaN), an infinite far
     * plane, the full-resolution surface (bound 0) and no triangles).
     *
     * @param farMetres far plane that bounds distances (infinite unless the depth mode has one)
     */
    private record Drawing(int views, int viewWidthPx, int viewHeightPx, double farMetres, double nearMetres,
                           double lodErrorPx, long triangles) {
    }

    private Panorama finish(PanoramaRequest req, Scene scene, PanoramaGeometry geometry, Images images, Drawing drawing,
                            Stopwatch clock, Consumer<String> progress) {
        Viewpoint eye = scene.eye();
        Mosaic mosaic = scene.mosaic();
        int[] argb = images.argb();
        float[] distance = images.distance();
        if (argb != null) {
            Silhouettes.draw(argb, distance, geometry.widthPx(), geometry.heightPx());
        }
        if (req.elevationRange().auto()) {
            PanoramaGeometry cropped = AutoCrop.crop(geometry, distance);
            int skip = (int) Math.round((geometry.topElevationDeg() - cropped.topElevationDeg()) * geometry.pixelsPerDegree());
            argb = argb == null ? null : AutoCrop.rows(argb, geometry.widthPx(), skip, cropped.heightPx());
            distance = AutoCrop.rows(distance, geometry.widthPx(), skip, cropped.heightPx());
            geometry = cropped;
            clock.lap("crop");
        }
        if (!req.layers().isEmpty()) {
            progress.accept("computing layers " + req.layers());
        }
        var layers = LayerComputer.compute(req.layers(), geometry, distance, eye.eyeFrame(), req.refraction(), mosaic);
        if (!req.layers().isEmpty()) {
            clock.lap("layers");
        }
        List<String> warnings = new ArrayList<>(mosaic.warnings());
        eye.filledVoidWarning(mosaic).ifPresent(warnings::add);
        if (req.distance()) {
            // A wall beside the eye (a viewpoint next to the DEM's own summit): say so, with the options that fix it.
            NearTerrain.measure(geometry, distance, NearTerrain.DEFAULT_NEAR_METRES).warning().ifPresent(warnings::add);
        }
        PanoramaMetadata meta = metadata(req, scene, drawing, clock.timings, warnings);
        // Colour only: the nearest-sample ranges served the silhouettes and the crop; they are no distance map.
        return new Panorama(geometry, argb, req.distance() ? distance : null, layers, meta);
    }

    private PanoramaMetadata metadata(PanoramaRequest req, Scene scene, Drawing drawing, Map<String, Double> timings,
                                      List<String> warnings) {
        Viewpoint eye = scene.eye();
        Mosaic mosaic = scene.mosaic();
        List<String> used = new ArrayList<>(), missing = new ArrayList<>();
        mosaic.tilesUsed().forEach(id -> used.add(id.name()));
        mosaic.tilesMissing().forEach(id -> missing.add(id.name()));
        return new PanoramaMetadata(eye, req.rangeMetres(), req.refraction().coefficient(), req.depthMode(), drawing.nearMetres(), drawing.farMetres(),
                drawing.views(), drawing.viewWidthPx(), drawing.viewHeightPx(), used, missing, warnings, timings, glRenderer(),
                drawing.lodErrorPx(), drawing.triangles(), scene.adjusted().move(), demSources(mosaic));
    }

    /**
     * The requested near plane, lowered where terrain comes closer to the eye than it (an eye low
     * over a steep slope): otherwise the near plane would cut a hole through which far terrain or
     * sky shows. The terrain's distance is bounded below by the eye's height above the DEM times the
     * cosine of the steepest slope in the cells around the eye; a point at that distance has an eye
     * depth of at least that times the cosine of the views' largest off-axis angle.
     */
    static double safeNearMetres(double requested, Mosaic mosaic, Viewpoint eye, ViewLayout layout) {
        double r = mosaic.rowOf(eye.latDeg()), c = mosaic.colOf(eye.lonDeg());
        // The eye's clearance over the surface drawn (the triangle under it, Mosaic.heightAt, which the eye height is
        // counted from).
        double clearance = eye.eyeAltitudeMetres() - eye.groundElevationMetres();
        double dy = 6_371_000.0 * Math.toRadians(1.0 / mosaic.intervalsPerDegree());
        double dx = dy * Math.cos(Math.toRadians(eye.latDeg()));
        double maxGradient = 0;
        for (int i = (int) Math.floor(r) - 1; i <= (int) Math.floor(r) + 2; i++) {
            for (int j = (int) Math.floor(c) - 1; j <= (int) Math.floor(c) + 2; j++) {
                if (i < 0 || j < 0 || i + 1 >= mosaic.rows() || j + 1 >= mosaic.cols()) {
                    continue;
                }
                float h = mosaic.sample(i, j), hs = mosaic.sample(i + 1, j), he = mosaic.sample(i, j + 1);
                if (!Float.isNaN(h) && !Float.isNaN(hs) && !Float.isNaN(he)) {
                    maxGradient = Math.max(maxGradient, Math.hypot((he - h) / dx, (hs - h) / dy));
                }
            }
        }
        double cosSlope = 1 / Math.sqrt(1 + maxGradient * maxGradient);
        double tanV = Math.max(Math.abs(layout.topTan()), Math.abs(layout.bottomTan())), tanH = layout.halfWidthTan();
        double cosOffAxis = 1 / Math.sqrt(1 + tanH * tanH + tanV * tanV);
        double bound = 0.9 * Math.max(0, clearance) * cosSlope * cosOffAxis;
        return Math.max(0.01, Math.min(requested, bound));
    }

    /**
     * Ends the GL context's use by this renderer and frees its meshes. A second call does nothing; a render started
     * afterwards is refused ({@link IllegalStateException}), and one still running on another thread fails when it
     * next needs the context: close after the renders end.
     */
    @Override
    public void close() {
        if (closed.getAndSet(true)) {
            return; // closed already (AutoCloseable's advice: a second close does nothing)
        }
        if (handle != null) {
            OffscreenRenderer.Handle h;
            try {
                h = awaitHandle();
            } catch (java.util.concurrent.CompletionException e) {
                return; // no context was made: nothing to end
            }
            meshLock.lock();
            try {
                h.renderer().release(meshes.clear());
            } finally {
                meshLock.unlock();
                h.close();
            }
        }
    }

    /** Refuses a render on a closed renderer before any tile is read or mesh built. */
    private void checkOpen() {
        if (closed.get()) {
            throw new IllegalStateException("this renderer is closed: open another");
        }
    }

    /** Crops an auto elevation range to the terrain. */
    static final class AutoCrop {
        private AutoCrop() {
        }

        static PanoramaGeometry crop(PanoramaGeometry g, float[] distance) {
            int w = g.widthPx(), h = g.heightPx();
            int topRow = h, lowestSkylineRow = 0;
            for (int c = 0; c < w; c++) {
                int r = 0;
                while (r < h && !Float.isFinite(distance[r * w + c])) {
                    r++;
                }
                topRow = Math.min(topRow, r);
                lowestSkylineRow = Math.max(lowestSkylineRow, r);
            }
            if (topRow >= h) {
                return g; // nothing but sky
            }
            double ppd = g.pixelsPerDegree();
            int first = Math.max(0, topRow - (int) Math.ceil(ppd));
            int last = Math.min(h - 1, lowestSkylineRow + (int) Math.ceil(10 * ppd));
            return new PanoramaGeometry(ppd, g.topElevationDeg() - first / ppd, last - first + 1);
        }

        static int[] rows(int[] a, int w, int skip, int rows) {
            int[] out = new int[w * rows];
            System.arraycopy(a, skip * w, out, 0, out.length);
            return out;
        }

        static float[] rows(float[] a, int w, int skip, int rows) {
            float[] out = new float[w * rows];
            System.arraycopy(a, skip * w, out, 0, out.length);
            return out;
        }
    }
}
