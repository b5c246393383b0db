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
    private final OffscreenRenderer.Handle handle;
    private final OffscreenRenderer gl;
    /** Patch deviations of this DEM source, kept across renders (level of detail costs a lookup then). */
    private final DeviationCache deviations = new DeviationCache();
    /** Fine patches' geometries with their GL buffers, kept across renders; one render uses it at a time. */
    private final MeshCache meshes = new MeshCache();
    private final java.util.concurrent.locks.ReentrantLock meshLock = new java.util.concurrent.locks.ReentrantLock();

    private PanoramaRenderer(DemSource dem, OffscreenRenderer.Handle handle) {
        this.dem = dem;
        this.handle = handle;
        this.gl = handle == null ? null : handle.renderer();
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
     * Opens a renderer that needs no OpenGL: the exact CPU reference
     * ({@link dempano.reference.ReferenceRenderer}). Same requests and outputs; the depth mode,
     * views and supersampling do not apply. Slower than a GPU, exact to micrometres.
     */
    public static PanoramaRenderer openReference(DemSource dem) {
        return new PanoramaRenderer(dem, null);
    }

    /**
     * Opens a renderer on a DEM source, creating the OpenGL context.
     *
     * @throws dempano.render.GlUnavailableException when no OpenGL context can be had (message says why)
     */
    public static PanoramaRenderer open(DemSource dem) {
        return new PanoramaRenderer(dem, OffscreenRenderer.acquire());
    }

    /** The OpenGL renderer in use. */
    public String glRenderer() {
        return gl == null ? REFERENCE_RENDERER : gl.glRenderer();
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
     */
    public Panorama render(PanoramaRequest req, Consumer<String> progress) {
        Map<String, Double> timings = new LinkedHashMap<>();
        long t = System.nanoTime();
        progress.accept("loading tiles");
        Mosaic mosaic = Mosaic.around(dem, req.latDeg(), req.lonDeg(), req.rangeMetres(), req.missingTiles());
        req.missingTiles().checkData(mosaic, req.latDeg(), req.lonDeg(), req.altitudeMetres());
        t = lap(timings, "tiles", t);
        long samplesPerTile = (long) (mosaic.intervalsPerDegree() + 1) * (mosaic.intervalsPerDegree() + 1);
        MemoryEstimate.of(req, gl != null, Math.max(2 * samplesPerTile * mosaic.tilesUsed().size(), mosaic.tileBytes()))
                .check(Runtime.getRuntime().maxMemory());

        Viewpoint requested = Double.isNaN(req.altitudeMetres())
                ? Viewpoint.onDem(mosaic, req.latDeg(), req.lonDeg(), req.offsetMetres(), req.eyeHeightMetres())
                : Viewpoint.atAltitude(mosaic, req.latDeg(), req.lonDeg(), req.altitudeMetres(), req.eyeHeightMetres());
        ViewpointAdjustment.Adjusted adjusted = ViewpointAdjustment.apply(mosaic, requested, req.snapToSummitMetres(),
                req.clearViewMetres(), req.refraction());
        Viewpoint eye = adjusted.eye();
        if (gl == null) {
            return renderReference(req, mosaic, adjusted, timings, t, progress);
        }
        progress.accept("building terrain mesh");
        Material material = gl.newTerrainMaterial(req.rangeMetres());
        if (!req.colour()) {
            material.setBoolean("DistanceOnly", true);
        }
        ElevationRange er = req.elevationRange();
        // Terrain wholly below the lowest view row the stitcher samples (the bottom row's 4×4
        // neighbourhood reaches two view pixels lower) is left out with what nearer terrain hides.
        double cullBelowDeg = er.bottomDeg() - 3 / req.pixelsPerDegree();
        PanoramaGeometry geometry = PanoramaGeometry.of(req.pixelsPerDegree(), er.bottomDeg(), er.topDeg());
        ViewLayout layout = ViewLayout.forPanorama(geometry, req.views(), req.supersampling());
        // Far plane: beyond the farthest terrain within range (curvature drops it, height raises it).
        double far = Math.hypot(req.rangeMetres() * 1.05, 20_000) + 1000;
        double near = safeNearMetres(req.nearMetres(), mosaic, eye, layout);
        ViewCapture[] captures;
        SeenTriangles seen = null;
        boolean exact = req.distance() && req.exactDistances();
        long triangles;
        // The mesh cache's geometries can be in one scene at a time, so it is held from building to
        // drawing (not through stitching); a concurrent render builds its own geometry meanwhile.
        boolean withMeshCache = meshLock.tryLock();
        try {
            TerrainBuilder.Terrain terrain = TerrainBuilder.build(mosaic, eye, req.refraction(), req.rangeMetres(), material,
                    req.pixelsPerDegree(), req.lodErrorPx(), 1, deviations, withMeshCache ? meshes : null, cullBelowDeg);
            t = lap(timings, "mesh", t);
            triangles = terrain.triangles();
            progress.accept("rendering " + req.views() + " views of " + layout.widthPx() + "×" + layout.heightPx()
                    + " (" + triangles / 1_000_000.0 + " M triangles, " + terrain.reusedPatches() + " patches reused)");
            long[] drawAndRead = new long[2];
            long resolveNanos = 0;
            try {
                // Colour only reads the range target whatever the depth mode: its nearest samples find the silhouettes.
                captures = gl.render(terrain.root(), new OffscreenRenderer.ViewRequest(layout, req.depthMode(), near, far,
                        req.colour(), req.depthMode() == DepthMode.SHADER_RANGE || !req.distance(), exact, false),
                        drawAndRead);
                if (exact) {
                    // While the geometries' buffers live: the triangles seen, in double precision.
                    long beforeResolve = System.nanoTime();
                    seen = SeenTriangleResolver.resolve(terrain.drawn(), captures, new EyePlacement(eye, req.refraction()),
                            req.rangeMetres());
                    resolveNanos = System.nanoTime() - beforeResolve;
                    for (int k = 0; k < captures.length; k++) { // the raw ids are no longer needed
                        captures[k] = new ViewCapture(captures[k].view(), captures[k].rgba(), captures[k].depth());
                    }
                }
            } finally {
                terrain.root().detachAllChildren();
                List<com.jme3.scene.Spatial> released = new ArrayList<>(terrain.transientParts());
                released.addAll(terrain.evicted());
                gl.release(released);
            }
            long afterRender = System.nanoTime();
            // "render" splits into drawing and reading back; what remains (scene upload, culling, release) is "upload".
            timings.put("upload", (afterRender - t - drawAndRead[0] - drawAndRead[1] - resolveNanos) / 1e6);
            timings.put("draw", drawAndRead[0] / 1e6);
            timings.put("readback", drawAndRead[1] / 1e6);
            if (exact) {
                timings.put("triangles", resolveNanos / 1e6);
            }
            t = afterRender;
        } finally {
            if (withMeshCache) {
                meshLock.unlock();
            }
        }

        progress.accept("stitching");
        int[] argb = req.colour() ? new int[geometry.widthPx() * geometry.heightPx()] : null;
        float[] distance = new float[geometry.widthPx() * geometry.heightPx()];
        if (req.distance()) {
            float[][] inverseEyeDepth = new float[captures.length][];
            for (int k = 0; k < captures.length; k++) {
                inverseEyeDepth[k] = Stitcher.inverseEyeDepths(captures[k], layout, req.depthMode(), near, far);
            }
            Stitcher.Result stitched = Stitcher.stitch(geometry, layout, captures, inverseEyeDepth,
                    exact ? new Stitcher.Exact(seen, new TerrainRayProbe(mosaic, eye, req.refraction(), req.rangeMetres())) : null,
                    argb, distance);
            if (exact) {
                progress.accept("distances: " + stitched.exactPixels() + " pixels from the " + seen.triangles()
                        + " triangles seen, "
                        + stitched.probedPixels() + " by probing the terrain, " + stitched.fallbackPixels() + " by inverse depth");
            }
        } else {
            Stitcher.stitchColour(geometry, layout, captures, argb, distance);
        }
        t = lap(timings, "stitch", t);
        Drawing drawing = new Drawing(req.views(), layout.widthPx(), layout.heightPx(),
                req.depthMode() == DepthMode.STANDARD_24 ? far : Double.POSITIVE_INFINITY, near, req.lodErrorPx(), triangles);
        return finish(req, mosaic, adjusted, geometry, argb, distance, drawing, timings, t, progress);
    }

    private Panorama renderReference(PanoramaRequest req, Mosaic mosaic, ViewpointAdjustment.Adjusted adjusted,
                                     Map<String, Double> timings, long t, Consumer<String> progress) {
        Viewpoint eye = adjusted.eye();
        ElevationRange er = req.elevationRange();
        PanoramaGeometry geometry = PanoramaGeometry.of(req.pixelsPerDegree(), er.bottomDeg(), er.topDeg());
        progress.accept("sweeping " + geometry.widthPx() + " columns on the CPU");
        var result = dempano.reference.ReferenceRenderer.render(mosaic, eye, req.refraction(), req.rangeMetres(),
                geometry, req.colour());
        t = lap(timings, "render", t);
        return finish(req, mosaic, adjusted, geometry, result.argb(), result.distanceMetres(),
                new Drawing(req.views(), 0, 0, Double.POSITIVE_INFINITY, 0, 0, 0), timings, t, progress);
    }

    /**
     * How the views were drawn, for the metadata (zeros and an infinite far plane for the CPU reference).
     *
     * @param farMetres far plane that bounds distances (infinite unless the depth mode has one)
     */
    private record Drawing(int views, int viewWidthPx, int viewHeightPx, double farMetres, double nearMetres,
                           double lodErrorPx, long triangles) {
    }

    private Panorama finish(PanoramaRequest req, Mosaic mosaic, ViewpointAdjustment.Adjusted adjusted,
                            PanoramaGeometry geometry, int[] argb, float[] distance, Drawing drawing,
                            Map<String, Double> timings, long t, Consumer<String> progress) {
        Viewpoint eye = adjusted.eye();
        if (argb != null) {
            Silhouettes.draw(argb, distance, geometry.widthPx(), geometry.heightPx());
        }
        if (req.elevationRange().auto()) {
            PanoramaGeometry cropped = AutoCrop.crop(geometry, distance);
            int skip = (int) Math.round((geometry.topElevationDeg() - cropped.topElevationDeg()) * geometry.pixelsPerDegree());
            argb = argb == null ? null : AutoCrop.rows(argb, geometry.widthPx(), skip, cropped.heightPx());
            distance = AutoCrop.rows(distance, geometry.widthPx(), skip, cropped.heightPx());
            geometry = cropped;
            t = lap(timings, "crop", t);
        }
        if (!req.layers().isEmpty()) {
            progress.accept("computing layers " + req.layers());
        }
        var layers = LayerComputer.compute(req.layers(), geometry, distance, eye.eyeFrame(), req.refraction(), mosaic);
        if (!req.layers().isEmpty()) {
            lap(timings, "layers", t);
        }
        List<String> used = new ArrayList<>(), missing = new ArrayList<>();
        mosaic.tilesUsed().forEach(id -> used.add(id.name()));
        mosaic.tilesMissing().forEach(id -> missing.add(id.name()));
        List<String> warnings = new ArrayList<>(mosaic.warnings());
        if (req.distance()) {
            // A wall beside the eye (a viewpoint next to the DEM's own summit): say so, with the options that fix it.
            NearTerrain.measure(geometry, distance, NearTerrain.DEFAULT_NEAR_METRES).warning().ifPresent(warnings::add);
        }
        PanoramaMetadata meta = new PanoramaMetadata(eye.latDeg(), eye.lonDeg(), eye.groundElevationMetres(),
                eye.offsetMetres(), eye.standingAltitudeMetres(), eye.eyeHeightMetres(), eye.eyeAltitudeMetres(),
                req.rangeMetres(), req.refraction().coefficient(), req.depthMode(), drawing.nearMetres(), drawing.farMetres(),
                drawing.views(), drawing.viewWidthPx(), drawing.viewHeightPx(), used, missing, warnings, timings, glRenderer(),
                drawing.lodErrorPx(), drawing.triangles(), adjusted.move(), demSources(mosaic));
        // Colour only: the nearest-sample ranges served the silhouettes and the crop; they are no distance map.
        return new Panorama(geometry, argb, req.distance() ? distance : null, layers, meta);
    }

    /**
     * The requested near plane, lowered where terrain comes closer to the eye than it (an eye low
     * over a steep slope): otherwise the near plane would cut a hole through which far terrain or
     * sky shows. The terrain's distance is bounded below by the eye's height above the DEM times the
     * cosine of the steepest slope in the cells around the eye; a point at that distance has an eye
     * depth of at least that times the cosine of the views' largest off-axis angle.
     */
    static double safeNearMetres(double requested, Mosaic mosaic, Viewpoint eye, ViewLayout layout) {
        double clearance = eye.eyeAltitudeMetres() - eye.groundElevationMetres();
        double r = mosaic.rowOf(eye.latDeg()), c = mosaic.colOf(eye.lonDeg());
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

    private static long lap(Map<String, Double> timings, String stage, long since) {
        long now = System.nanoTime();
        timings.put(stage, (now - since) / 1e6);
        return now;
    }

    @Override
    public void close() {
        if (handle != null) {
            meshLock.lock();
            try {
                gl.release(meshes.clear());
            } finally {
                meshLock.unlock();
                handle.close();
            }
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
