package dempano.terrain;

import com.jme3.material.Material;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.terrain.geomipmap.TerrainPatch;
import com.jme3.terrain.geomipmap.TerrainQuad;
import com.jme3.util.BufferUtils;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.ShortBuffer;
import dempano.dem.Triangulation;
import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.IntStream;

/**
 * Builds the terrain the GPU draws: the mosaic cut into blocks of {@link #BLOCK_INTERVALS}² cells
 * (each a jME {@link TerrainQuad}) of patches of {@link #PATCH_INTERVALS}² cells (each a
 * {@link TerrainPatch}). Every vertex sits where the WGS84 ellipsoid puts it, stored as an ECEF
 * position in double-single form (two floats, 1e-15 relative), with its ellipsoid normal and
 * height: nothing depends on the eye, so a {@link MeshCache} keeps patch geometries (and their GL
 * buffers) from one viewpoint to the next. The vertex shader subtracts the eye's position in the same
 * form (float rounding stays relative to the distance from the eye: 3 cm at 300 km), lifts each
 * vertex by refraction, k·d²/2R, and turns it into the eye's frame, jME axes x = east, y = up,
 * z = south ({@link EyePlacement}). Each geometry's bound is set in the eye's frame for each build.
 * Patches wholly beyond the range are left out.
 *
 * <p>Level of detail: each patch is drawn with every 2^level-th sample, the level chosen by
 * {@link LevelOfDetail} from the patch's own deviations and its distance, before any vertex is placed,
 * so the cost is that of what is drawn. For a panorama (a fixed eye) the level also bounds the
 * relative distance error of ground seen at grazing incidence
 * ({@link LevelOfDetail#DEFAULT_MAX_DISTANCE_ERROR}), from the patch's height range and height steps. jME's own TerrainQuad mesh building (a flat grid at full
 * resolution, geomipmapping by fixed distance) is not used: the quads and patches are filled here.
 *
 * <p>Each vertex also carries, in its first texture coordinate, the terrain elevation in metres
 * (for colouring), its flags and its grid position in the patch (which name the triangles:
 * {@link #VERTEX_BASE}).
 */
public final class TerrainBuilder {
    /** Cells per TerrainQuad block side (a power of two). */
    public static final int BLOCK_INTERVALS = 512;
    /** Cells per TerrainPatch side. */
    public static final int PATCH_INTERVALS = 64;
    /** Levels of detail of a patch: steps 1, 2, 4, … PATCH_INTERVALS. */
    static final int LEVELS = Integer.numberOfTrailingZeros(PATCH_INTERVALS) + 1;
    /** Patches at this level (step 4) and coarser are merged per block into one geometry. */
    static final int MERGED_LEVEL = 2;

    private TerrainBuilder() {
    }

    /**
     * What was built.
     *
     * @param patchesPerLevel patches drawn at each level (index = level, step 2^level)
     * @param hiddenPatches   patches within range left out as hidden ({@link HorizonCulling})
     * @param reusedPatches   patches whose geometry came from the {@link MeshCache}
     * @param transientParts  geometries made for this build only: release their buffers after drawing
     * @param evicted         geometries the mesh cache let go: release their buffers too
     * @param drawn           every geometry of the scene, in the order of the {@link #VERTEX_BASE}
     *                        each carries (the shader writes that base plus the provoking vertex's
     *                        number in the geometry, and the facing, beside each sample's range;
     *                        see {@link #vertexBases})
     */
    public record Terrain(Node root, long vertices, long triangles, int blocks, int patches, int[] patchesPerLevel,
                          int hiddenPatches, int reusedPatches, List<Geometry> transientParts, List<Geometry> evicted,
                          List<Geometry> drawn) {
    }

    /**
     * The material parameter, set per geometry as an override, that numbers the vertices of one
     * build: the scene's number of the geometry's first vertex ({@link #vertexBases}).
     *
     * <p>What the shader writes per sample is {@code 2 × (base + provoking vertex) + bit}. Every
     * mesh this class builds keeps this contract, which makes that a triangle's name: each vertex
     * is the last (GL's provoking) vertex of at most two triangles, and the bit tells the two
     * apart by where the sample lies in the patch's grid. Each vertex carries its grid row and
     * column in the patch (texture coordinate z, w) and, in its flags (texture coordinate y), how
     * the triangles it ends are told apart ({@link #NAMED_MASK}): with Δrow, Δcol of a point
     * relative to the provoking vertex, f = Δcol − Δrow ({@link #NAMED_NW_SE}), Δrow + Δcol
     * ({@link #NAMED_NE_SW}), Δcol ({@link #NAMED_ALONG_COLUMNS}) or Δrow
     * ({@link #NAMED_ALONG_ROWS}); the bit is 0 where f &gt; 0 inside the triangle, else 1. Within
     * each of its triangles f keeps one sign (its other two vertices' f are of one sign or 0), and
     * the two triangles a vertex ends have opposite signs, so the shader interpolates the grid
     * position and compares, and {@link SeenTriangleResolver} sums f over the other two vertices.
     * The bit does not depend on the winding or the eye: every triangle faces out (cells up,
     * skirts out of their patch), so one draw call may cull the back faces
     * ({@link #CULL_BACK_FACES}). The shader does not read gl_PrimitiveID because llvmpipe then
     * assembles each triangle apart and shades every vertex once per triangle (draw 1.65 s against
     * 0.88 s at srtm3-150km).
     */
    public static final String VERTEX_BASE = "VertexBase";

    /** The naming rules of {@link #VERTEX_BASE}, as flag bits (above the debug flags 1, 2, 4). */
    public static final int NAMED_NW_SE = 0, NAMED_NE_SW = 8, NAMED_ALONG_COLUMNS = 16, NAMED_ALONG_ROWS = 24,
            NAMED_MASK = 24;

    /**
     * {@link #VERTEX_BASE}'s f at a point Δrow, Δcol from the provoking vertex, under a naming rule.
     *
     * @param rule one of {@link #NAMED_NW_SE}, {@link #NAMED_NE_SW}, {@link #NAMED_ALONG_COLUMNS},
     *             {@link #NAMED_ALONG_ROWS}
     */
    public static double namingSide(int rule, double deltaRow, double deltaCol) {
        return switch (rule) {
            case NAMED_NW_SE -> deltaCol - deltaRow;
            case NAMED_NE_SW -> deltaRow + deltaCol;
            case NAMED_ALONG_COLUMNS -> deltaCol;
            default -> deltaRow;
        };
    }

    /**
     * User data on a terrain geometry (true): every triangle faces out, GL's front (wound
     * counter-clockwise) on the side it is meant to be seen from: a cell's triangles from above, a
     * skirt from outside its patch (the crack it hides is seen from the neighbour's side; a skirt seen
     * from inside its patch is below that patch's surface). A renderer may cull the back faces:
     * wherever the terrain is seen from above, the faces drawn are those it draws with none culled.
     * {@link dempano.render.OffscreenRenderer} does, in one draw call.
     */
    public static final String CULL_BACK_FACES = "dempano.cullBackFaces";

    /**
     * The scene's number of each drawn geometry's first vertex, and the total last: geometry g
     * holds the scene's vertices bases[g] to bases[g + 1] − 1 (what {@link #VERTEX_BASE} carries).
     *
     * @throws IllegalStateException when the scene has 2^30 vertices or more (the shader writes
     *                               twice the number, plus one bit)
     */
    public static int[] vertexBases(List<Geometry> drawn) {
        int[] bases = new int[drawn.size() + 1];
        long total = 0;
        for (int g = 0; g < drawn.size(); g++) {
            bases[g] = (int) total;
            total += drawn.get(g).getMesh().getVertexCount();
            if (total >= 1 << 30) {
                throw new IllegalStateException("2^30 vertices or more in one scene");
            }
        }
        bases[drawn.size()] = (int) total;
        return bases;
    }

    /**
     * How finely and with what help a terrain is built: the level of detail, the fly-through's exaggeration,
     * the caches and the culling below the lowest sampled ray.
     *
     * @param pixelsPerDegree resolution the level of detail is chosen for, pixels per degree (of the views)
     * @param maxErrorPx      bound on a simplified patch's screen error, pixels (0 = full resolution everywhere)
     * @param exaggeration    heights multiplied by this (the fly-through's vertical exaggeration; 1 for
     *                        panoramas and cameras); the colour and the level of detail use the true heights
     * @param cache           patch deviations, taken where it has them and added where it lacks them (null = no
     *                        cache); it must belong to the DEM source the mosaic came from
     * @param meshes          geometries of fine patches (levels below {@link #MERGED_LEVEL}) kept across builds
     *                        (null = every geometry is made for this build and listed in
     *                        {@link Terrain#transientParts()}). Cached geometries are shared with later builds:
     *                        draw one build's terrain before making the next.
     * @param cullBelowDeg    leaves out the patches {@link HorizonCulling} finds hidden from the eye: wholly below
     *                        the horizon of nearer terrain, or wholly below this elevation angle, degrees (the
     *                        lowest any target pixel samples). NaN = draw every patch (a fly-through, whose eye
     *                        moves; the level of detail then bounds the screen angle only, not the distance)
     */
    public record Detail(double pixelsPerDegree, double maxErrorPx, double exaggeration, DeviationCache cache,
                         MeshCache meshes, double cullBelowDeg) {
        /** A level of detail alone: no exaggeration, caches or culling. */
        public static Detail of(double pixelsPerDegree, double maxErrorPx) {
            return new Detail(pixelsPerDegree, maxErrorPx, 1, null, null, Double.NaN);
        }

        public Detail withExaggeration(double v) {
            return new Detail(pixelsPerDegree, maxErrorPx, v, cache, meshes, cullBelowDeg);
        }

        public Detail withCache(DeviationCache v) {
            return new Detail(pixelsPerDegree, maxErrorPx, exaggeration, v, meshes, cullBelowDeg);
        }

        public Detail withMeshes(MeshCache v) {
            return new Detail(pixelsPerDegree, maxErrorPx, exaggeration, cache, v, cullBelowDeg);
        }

        public Detail withCullBelowDeg(double v) {
            return new Detail(pixelsPerDegree, maxErrorPx, exaggeration, cache, meshes, v);
        }
    }

    /**
     * The terrain of {@code mosaic} seen from {@code eye}: each patch simplified as far as
     * {@link LevelOfDetail} allows for a screen error of at most {@link Detail#maxErrorPx()} pixels at
     * {@link Detail#pixelsPerDegree()} (0 = full resolution everywhere). Where neighbouring patches
     * differ, vertical skirts as deep as both patches' errors together close the cracks between them.
     *
     * @param rangeMetres terrain whose ground distance exceeds this is left out (whole patches here;
     *                    the exact cut is made per fragment by the shader)
     * @param material    every geometry's material, given the eye's uniforms ({@link EyePlacement#apply});
     *                    null = none set (the geometries are read on the CPU only)
     */
    public static Terrain build(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres, Material material,
                                Detail detail) {
        return new Build(mosaic, eye, refraction, rangeMetres, detail).run(material);
    }

    /**
     * One build: its inputs, the window of the mosaic it covers, and its passes in the order {@link #run} makes
     * them (the patches within range; their levels; their skirts and cached meshes; the vertices of the others;
     * the scene).
     */
    private static final class Build {
        final Mosaic mosaic;
        final Viewpoint eye;
        final Refraction refraction;
        final double rangeMetres;
        final Detail detail;
        /** The eye's fractional row and column in the mosaic. */
        final double eyeRow, eyeCol;
        /**
         * First and last rows and columns of the mosaic that can lie within range (a generous box; the exact cut
         * comes later), the first grown back to a whole patch of the global grid.
         */
        final int r0, r1, c0, c1;
        /** The mosaic's first row and column on the global grid (rows from 90° N, columns from 180° W). */
        final long globalRow0, globalCol0;
        /** The smallest and largest cosine of latitude within range, as bounds. */
        final double cosMin, cosMax;
        /** A row's length on the mean sphere, metres. */
        final double rowMetresExact;

        Build(Mosaic mosaic, Viewpoint eye, Refraction refraction, double rangeMetres, Detail detail) {
            this.mosaic = mosaic;
            this.eye = eye;
            this.refraction = refraction;
            this.rangeMetres = rangeMetres;
            this.detail = detail;
            eyeRow = mosaic.rowOf(eye.latDeg());
            eyeCol = mosaic.colOf(eye.lonDeg());
            // Rows are shortest (metres) on the side nearer the pole: take the smaller cosine, as a lower bound.
            double metresPerRow = 111_000.0 / mosaic.intervalsPerDegree();
            cosMin = Math.cos(Math.toRadians(Math.min(89.9, Math.abs(eye.latDeg()) + rangeMetres / 111_000.0 + 0.01)));
            cosMax = Math.cos(Math.toRadians(Math.max(0, Math.abs(eye.latDeg()) - rangeMetres / 111_000.0 - 0.01)));
            double metresPerCol = metresPerRow * Math.max(0.001, cosMin);
            int rowFirst = Math.max(0, (int) Math.floor(eyeRow - rangeMetres / metresPerRow * 1.05 - 2));
            r1 = Math.min(mosaic.rows() - 1, (int) Math.ceil(eyeRow + rangeMetres / metresPerRow * 1.05 + 2));
            int colFirst = Math.max(0, (int) Math.floor(eyeCol - rangeMetres / metresPerCol * 1.05 - 2));
            c1 = Math.min(mosaic.cols() - 1, (int) Math.ceil(eyeCol + rangeMetres / metresPerCol * 1.05 + 2));
            // Patches on a grid aligned to whole multiples of the patch size from 90°N, 180°W, so that a
            // patch is the same whatever the viewpoint (its deviations can be cached). The window grows
            // to whole patches; rows and columns beyond the mosaic repeat its edge (degenerate cells).
            globalRow0 = (long) (90 - mosaic.latNorthDeg()) * mosaic.intervalsPerDegree();
            globalCol0 = (long) Math.floorMod(mosaic.lonWestDeg() + 180, 360) * mosaic.intervalsPerDegree();
            r0 = rowFirst - (int) Math.floorMod(globalRow0 + rowFirst, PATCH_INTERVALS);
            c0 = colFirst - (int) Math.floorMod(globalCol0 + colFirst, PATCH_INTERVALS);
            rowMetresExact = 6_371_000.0 * Math.toRadians(1.0 / mosaic.intervalsPerDegree());
        }

        Terrain run(Material material) {
            // Nothing derived from heights a tile no longer has is served (a tile file rewritten since the last build).
            if (detail.cache() != null) {
                detail.cache().forgetChanged(mosaic);
            }
            List<Geometry> stale = detail.meshes() == null ? List.of() : detail.meshes().forgetChanged(mosaic);
            List<PatchWork> inRange = patchesInRange();
            chooseLevels(inRange);
            int culled = 0;
            if (!Double.isNaN(detail.cullBelowDeg()) && detail.exaggeration() == 1) {
                culled = cull(inRange, mosaic, eye.eyeFrame(), eye.eyeAltitudeMetres(), refraction.coefficient(),
                        detail.cullBelowDeg());
            }
            java.util.Set<MeshCache.Key> inUse = new java.util.HashSet<>();
            List<PatchWork> kept = withSkirts(inRange, inUse);
            place(kept);
            return assemble(kept, material, culled, stale, inUse);
        }

        /**
         * The patches of the window not wholly beyond the range (with 2 km to spare), with their nearest and farthest
         * ground distances as bounds and their cache keys.
         */
        private List<PatchWork> patchesInRange() {
            int p = PATCH_INTERVALS;
            List<PatchWork> inRange = new ArrayList<>();
            for (int pr = r0; pr < r1; pr += p) {
                for (int pc = c0; pc < c1; pc += p) {
                    PatchWork w = new PatchWork();
                    w.row0 = pr;
                    w.col0 = pc;
                    // Nearest point of the patch to the eye, horizontally, as a lower bound (slightly short rows
                    // and columns): it decides both the range cut and the level.
                    double dr = Math.max(0, Math.max(w.row0 - eyeRow, eyeRow - (w.row0 + p))) * rowMetresExact * 0.995;
                    double dc = Math.max(0, Math.max(w.col0 - eyeCol, eyeCol - (w.col0 + p))) * rowMetresExact * cosMin * 0.995;
                    w.nearestMetres = Math.hypot(dr, dc);
                    if (w.nearestMetres > rangeMetres + 2000) {
                        continue; // beyond range: dropped
                    }
                    // Farthest point, as an upper bound (long rows and columns: the cosine nearest the equator).
                    double fr = Math.max(Math.abs(w.row0 - eyeRow), Math.abs(w.row0 + p - eyeRow)) * rowMetresExact * 1.005;
                    double fc = Math.max(Math.abs(w.col0 - eyeCol), Math.abs(w.col0 + p - eyeCol)) * rowMetresExact * cosMax * 1.005;
                    w.farthestMetres = Math.hypot(fr, fc);
                    w.cacheKey = new DeviationCache.Key(mosaic.intervalsPerDegree(), globalRow0 + w.row0,
                            Math.floorMod(globalCol0 + w.col0, 360L * mosaic.intervalsPerDegree()));
                    // Cached deviations hold only where this mosaic has every height of the patch too.
                    w.cacheable = cacheable(mosaic, w.row0, w.col0);
                    inRange.add(w);
                }
            }
            return inRange;
        }

        /**
         * Pass 1 (parallel): each patch's deviations (cached, kept on disk, or measured) and, from them and its
         * distance, its level.
         */
        private void chooseLevels(List<PatchWork> inRange) {
            DeviationCache cache = detail.cache();
            if (cache != null) {
                cache.lookUp(inRange.stream().filter(w -> w.cacheable).toList(), w -> w.cacheKey, (w, raw) -> {
                    w.rawDeviations = raw;
                    w.fromCache = true;
                });
            }
            // The distance bound needs a fixed eye (a panorama; not a fly-through, whose eye moves).
            double maxDistanceError = !Double.isNaN(detail.cullBelowDeg()) && detail.exaggeration() == 1
                    ? LevelOfDetail.DEFAULT_MAX_DISTANCE_ERROR : 0;
            DeviationStore disk = cache == null ? null : cache.disk();
            dempano.util.Parallel.forEachIndex(inRange.size(), i -> { // measured or cached: costs differ per patch
                PatchWork w = inRange.get(i);
                if (w.rawDeviations == null) {
                    float[] heights = patchHeights(mosaic, w.row0, w.col0);
                    if (disk != null && w.cacheable) {
                        long hashA = DeviationStore.hashA(heights), hashB = DeviationStore.hashB(heights);
                        float[] kept = disk.get(w.cacheKey, hashA, hashB);
                        if (kept == null) {
                            kept = deviationsOf(heights);
                            disk.put(w.cacheKey, hashA, hashB, kept);
                        }
                        w.rawDeviations = kept;
                    } else {
                        w.rawDeviations = deviationsOf(heights);
                    }
                }
                w.deviations = new double[LEVELS];
                // The earth curves under a coarse cell too: its flat facets sag below the drawn surface.
                for (int level = 1; level < LEVELS; level++) {
                    w.deviations[level] = w.rawDeviations[level]
                            + LevelOfDetail.chordSagMetres((1 << level) * rowMetresExact, refraction.coefficient());
                }
                LevelOfDetail.Sight sight = new LevelOfDetail.Sight(w.nearestMetres, w.farthestMetres,
                        w.rawDeviations[LEVELS + 1], maxDistanceError > 0 ? riseAwayFromEye(mosaic, w, eyeRow, eyeCol) : 0,
                        eye.eyeAltitudeMetres(), refraction.coefficient());
                w.level = LevelOfDetail.chooseLevel(w.deviations, sight, detail.pixelsPerDegree(), detail.maxErrorPx(),
                        maxDistanceError);
            });
            if (disk != null) {
                disk.flush();
            }
            if (cache != null) {
                cache.store(inRange.stream().filter(w -> w.cacheable && !w.fromCache).toList(), w -> w.cacheKey,
                        w -> w.rawDeviations);
            }
        }

        /**
         * Pass 2: skirts on the edges where the neighbour's level differs (equal levels share their edge vertices
         * exactly: no crack), and each fine patch's cached geometry where the mesh cache has it (its key added to
         * {@code inUse}). Hidden patches count as neighbours: their neighbours' skirts do not change (and cannot be
         * seen there). Returns the patches not hidden.
         */
        private List<PatchWork> withSkirts(List<PatchWork> inRange, java.util.Set<MeshCache.Key> inUse) {
            int p = PATCH_INTERVALS;
            Map<Long, PatchWork> work = new HashMap<>();
            for (PatchWork w : inRange) {
                work.put(key(w.row0, w.col0), w);
            }
            MeshCache meshes = detail.meshes();
            List<PatchWork> kept = new ArrayList<>(work.values().stream().filter(w -> !w.hidden).toList());
            for (PatchWork w : kept) {
                long[] sides = {key(w.row0 - p, w.col0), key(w.row0, w.col0 + p), key(w.row0 + p, w.col0), key(w.row0, w.col0 - p)};
                w.skirts = new double[4]; // north, east, south, west
                for (int e = 0; e < 4; e++) {
                    PatchWork n = work.get(sides[e]);
                    if (n != null && n.level != w.level) {
                        w.skirts[e] = w.errorMetres() + n.errorMetres() + 0.5;
                    }
                }
                if (meshes != null && w.cacheable && w.level < MERGED_LEVEL) {
                    w.meshKey = new MeshCache.Key(mosaic.intervalsPerDegree(), w.cacheKey.globalRow(), w.cacheKey.globalCol(),
                            w.level, w.skirts[0], w.skirts[1], w.skirts[2], w.skirts[3], detail.exaggeration());
                    w.cached = meshes.get(w.meshKey);
                    inUse.add(w.meshKey);
                }
            }
            return kept;
        }

        /**
         * Pass 3 (parallel): the vertices of the patches not cached. Patches of every level: a full-resolution patch
         * places hundreds of times the vertices of a coarse one. A patch drawn alone becomes its jME mesh (direct
         * buffers) at once, so that its heap arrays die young: kept until every patch was placed, they were 150 MB of
         * a cold Mount Washington render's heap, copied by the collector two or three times over.
         */
        private void place(List<PatchWork> kept) {
            int nr = r1 - r0 + 1 + PATCH_INTERVALS, nc = c1 - c0 + 1 + PATCH_INTERVALS;
            double[] sinLat = new double[nr], cosLat = new double[nr], sinLon = new double[nc], cosLon = new double[nc];
            for (int r = 0; r < nr; r++) {
                double phi = Math.toRadians(mosaic.latOfRow(clampRow(mosaic, r0 + r)));
                sinLat[r] = Math.sin(phi);
                cosLat[r] = Math.cos(phi);
            }
            for (int c = 0; c < nc; c++) {
                double lam = Math.toRadians(mosaic.wrappedLonOfCol(clampCol(mosaic, c0 + c)));
                sinLon[c] = Math.sin(lam);
                cosLon[c] = Math.cos(lam);
            }
            Placer placer = new Placer(mosaic, r0, c0, sinLat, cosLat, sinLon, cosLon, detail.exaggeration());
            List<PatchWork> toPlace = kept.stream().filter(w -> w.cached == null).toList();
            dempano.util.Parallel.forEachIndex(toPlace.size(), i -> {
                PatchWork w = toPlace.get(i);
                PatchMesh placed = placer.mesh(w, w.skirts);
                w.hull = placed.hull();
                if (w.level >= MERGED_LEVEL) {
                    w.mesh = placed;
                } else {
                    w.alone = PatchMesh.merge(List.of(placed));
                }
            });
        }

        /**
         * The scene: a node per block, a geometry per fine patch (new ones put in the mesh cache where keyed) and one
         * per block for its coarse patches merged (tens of thousands of tiny draw calls and buffers cost more than
         * their triangles), each bound in the eye's frame, their vertices numbered ({@link #VERTEX_BASE}); the
         * mesh cache then lets go of what the scene does not use ({@code inUse}).
         */
        private Terrain assemble(List<PatchWork> kept, Material material, int culled, List<Geometry> stale,
                                 java.util.Set<MeshCache.Key> inUse) {
            int p = PATCH_INTERVALS;
            MeshCache meshes = detail.meshes();
            EyePlacement placement = new EyePlacement(eye, refraction);
            if (material != null) {
                applyEye(material, placement);
            }
            Node root = new Node("terrain");
            Map<Long, TerrainQuad> quads = new HashMap<>();
            Map<Long, List<PatchMesh>> merged = new HashMap<>();
            List<Geometry> transientParts = new ArrayList<>();
            List<Geometry> drawn = new ArrayList<>();
            long vertices = 0, triangles = 0;
            int reused = 0;
            int[] patchesPerLevel = new int[Integer.numberOfTrailingZeros(p) + 1];
            for (PatchWork w : kept) {
                int br = r0 + (w.row0 - r0) / BLOCK_INTERVALS * BLOCK_INTERVALS, bc = c0 + (w.col0 - c0) / BLOCK_INTERVALS * BLOCK_INTERVALS;
                TerrainQuad quad = quads.computeIfAbsent(key(br, bc), k -> {
                    TerrainQuad q = new TerrainQuad();
                    q.setName("block-" + br + "-" + bc);
                    root.attachChild(q);
                    return q;
                });
                patchesPerLevel[w.level]++;
                if (w.cached != null) {
                    Geometry g = w.cached.geometry();
                    vertices += g.getMesh().getVertexCount();
                    triangles += g.getMesh().getTriangleCount();
                    reused++;
                    attach(quad, g, w.cached.hull(), material, placement, drawn);
                    continue;
                }
                if (w.level >= MERGED_LEVEL) {
                    vertices += w.mesh.vertexCount();
                    triangles += w.mesh.indices().length / 3;
                    merged.computeIfAbsent(key(br, bc), k -> new ArrayList<>()).add(w.mesh);
                } else {
                    vertices += w.alone.getVertexCount();
                    triangles += w.alone.getTriangleCount();
                    TerrainPatch patch = new TerrainPatch("patch-" + w.row0 + "-" + w.col0 + "-level-" + w.level);
                    patch.setUserData(FULL_RESOLUTION, w.level == 0 && detail.exaggeration() == 1);
                    patch.setMesh(w.alone);
                    attach(quad, patch, w.hull, material, placement, drawn);
                    if (w.meshKey != null) {
                        meshes.put(w.meshKey, new MeshCache.Entry(patch, w.hull, w.alone.getVertexCount()));
                    } else {
                        transientParts.add(patch);
                    }
                }
            }
            for (Map.Entry<Long, List<PatchMesh>> e : merged.entrySet()) {
                TerrainQuad quad = quads.get(e.getKey());
                TerrainPatch patch = new TerrainPatch(quad.getName() + "-coarse-" + e.getValue().size() + "-patches");
                patch.setMesh(PatchMesh.merge(e.getValue()));
                attach(quad, patch, PatchMesh.hull(e.getValue()), material, placement, drawn);
                transientParts.add(patch);
            }
            // Vertices numbered for this build (a cached geometry carries the numbers of its latest build).
            int[] bases = vertexBases(drawn);
            for (int g = 0; g < drawn.size(); g++) {
                drawn.get(g).addMatParamOverride(new com.jme3.material.MatParamOverride(com.jme3.shader.VarType.Int,
                        VERTEX_BASE, bases[g]));
            }
            List<Geometry> evicted = new ArrayList<>(stale);
            if (meshes != null) {
                evicted.addAll(meshes.trim(inUse));
            }
            root.updateGeometricState();
            return new Terrain(root, vertices, triangles, quads.size(), kept.size(), patchesPerLevel, culled, reused,
                    transientParts, evicted, List.copyOf(drawn));
        }
    }

    /** Sets the eye's uniforms ({@link EyePlacement#uniforms()}) on a terrain material. */
    public static void applyEye(Material m, EyePlacement eye) {
        EyePlacement.Uniforms u = eye.uniforms();
        m.setVector3("EyeHigh", new com.jme3.math.Vector3f(u.eyeHigh()[0], u.eyeHigh()[1], u.eyeHigh()[2]));
        m.setVector3("EyeLow", new com.jme3.math.Vector3f(u.eyeLow()[0], u.eyeLow()[1], u.eyeLow()[2]));
        m.setVector3("EyeFoot", new com.jme3.math.Vector3f(u.eyeFoot()[0], u.eyeFoot()[1], u.eyeFoot()[2]));
        float[] r = u.ecefToEye();
        m.setParam("EcefToEye", com.jme3.shader.VarType.Matrix3,
                new com.jme3.math.Matrix3f(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]));
        m.setFloat("LiftPerSquareMetre", u.liftPerSquareMetre());
        m.setFloat("MeanRadius", (float) Ellipsoid.MEAN_RADIUS_METRES);
    }

    /**
     * Puts a geometry under its block for this eye: its material, and its bound in the eye's frame
     * (the vertices are ECEF; jME's culling and the views' azimuth sectors read this bound).
     */
    private static void attach(Node quad, Geometry g, double[] hull, Material material, EyePlacement placement,
                               List<Geometry> drawn) {
        if (material != null) {
            g.setMaterial(material);
        }
        g.clearMatParamOverrides(); // numbered once the scene is complete (build)
        drawn.add(g);
        double[] box = placement.bound(hull);
        g.setModelBound(new com.jme3.bounding.BoundingBox(
                new com.jme3.math.Vector3f((float) box[0], (float) box[1], (float) box[2]),
                new com.jme3.math.Vector3f((float) box[3], (float) box[4], (float) box[5])));
        g.setUserData(EYE_BOUND, true);
        g.setUserData(CULL_BACK_FACES, true);
        quad.attachChild(g);
    }

    /** User data on a terrain geometry: its model bound is in the eye's frame already (do not recompute it from the vertices). */
    public static final String EYE_BOUND = "dempano.eyeBound";

    /**
     * User data on a terrain geometry: true when it is a full-resolution patch (level 0: every
     * sample, triangulated as {@link Triangulation}), whose triangles are the CPU reference's own.
     * Absent on merged coarse blocks.
     */
    public static final String FULL_RESOLUTION = "dempano.fullResolution";

    /**
     * Marks the patches no panorama ray reaches (see {@link HorizonCulling}); returns how many. The
     * drawn surface of a patch interpolates its samples, so their lowest and highest bound it.
     */
    private static int cull(List<PatchWork> patches, Mosaic mosaic, LocalFrame frame, double eyeAltitudeMetres,
                            double refractionK, double cullBelowDeg) {
        int p = PATCH_INTERVALS;
        List<HorizonCulling.Bounds> bounds = IntStream.range(0, patches.size()).parallel().mapToObj(i -> {
            PatchWork w = patches.get(i);
            double[] ecef = new double[3], enu = new double[3];
            double first = Double.NaN, min = 0, max = 0, far = 0;
            for (int corner = 0; corner < 4; corner++) {
                int r = clampRow(mosaic, w.row0 + (corner >> 1) * p);
                int c = clampCol(mosaic, w.col0 + (corner & 1) * p);
                Ellipsoid.toEcef(mosaic.latOfRow(r), mosaic.lonOfCol(c), 0, ecef);
                frame.ecefToEnu(ecef[0], ecef[1], ecef[2], enu);
                double az = Math.toDegrees(Math.atan2(enu[0], enu[1]));
                if (Double.isNaN(first)) {
                    first = az;
                } else {
                    double rel = az - first;
                    rel -= 360 * Math.floor((rel + 180) / 360); // to [-180, 180)
                    min = Math.min(min, rel);
                    max = Math.max(max, rel);
                }
                // Horizontal distance in the eye's frame, a little under the ground distance: widen.
                far = Math.max(far, Math.hypot(enu[0], enu[1]) * 1.001 + 1);
            }
            return new HorizonCulling.Bounds(first + min, first + max, w.nearestMetres, far,
                    w.rawDeviations[LEVELS], w.rawDeviations[LEVELS + 1]);
        }).toList();
        boolean[] hidden = HorizonCulling.hidden(bounds, eyeAltitudeMetres, refractionK, cullBelowDeg,
                HorizonCulling.DEFAULT_MARGIN_DEG);
        int count = 0;
        for (int i = 0; i < hidden.length; i++) {
            patches.get(i).hidden = hidden[i];
            count += hidden[i] ? 1 : 0;
        }
        return count;
    }

    /**
     * {@link LevelOfDetail#riseAwayFromEye} of a patch from its cached height steps: corners in the
     * patch's east-north plane, spacings as upper bounds (the largest radius of curvature, the cosine
     * of the patch's edge nearer the equator), and the meridians' convergence between eye and patch
     * ((east offset / R) · tan φ) with room as the directions' slack.
     */
    private static double riseAwayFromEye(Mosaic mosaic, PatchWork w, double eyeRow, double eyeCol) {
        int p = PATCH_INTERVALS;
        double radians = Math.toRadians(1.0 / mosaic.intervalsPerDegree());
        double latNorth = mosaic.latOfRow(w.row0), latSouth = latNorth - p / (double) mosaic.intervalsPerDegree();
        double equatorward = Math.signum(latNorth) == Math.signum(latSouth) ? Math.min(Math.abs(latNorth), Math.abs(latSouth)) : 0;
        double poleward = Math.min(89, Math.max(Math.abs(latNorth), Math.abs(latSouth)));
        double north = 6_400_000 * radians, east = north * Math.cos(Math.toRadians(equatorward));
        double[] corners = new double[8];
        for (int q = 0; q < 4; q++) {
            corners[2 * q] = (w.col0 + (q & 1) * p - eyeCol) * east;
            corners[2 * q + 1] = (eyeRow - (w.row0 + (q >> 1) * p)) * north;
        }
        double slack = 0.01 + 2 * w.farthestMetres / LevelOfDetail.MIN_RADIUS_OF_CURVATURE_METRES
                * Math.tan(Math.toRadians(poleward));
        float[] raw = w.rawDeviations;
        return LevelOfDetail.riseAwayFromEye(new double[] {raw[LEVELS + 2], raw[LEVELS + 3]},
                new double[] {raw[LEVELS + 4], raw[LEVELS + 5]}, east, north, corners, slack);
    }

    private static final ThreadLocal<float[]> PATCH_HEIGHTS =
            ThreadLocal.withInitial(() -> new float[(PATCH_INTERVALS + 1) * (PATCH_INTERVALS + 1)]);

    /**
     * A patch's deviations per level measured on the mosaic, metres (rounded up to float), then its
     * lowest and highest sample (metres), then the least and greatest rise from a sample to its east
     * neighbour and to its south neighbour (metres, rounded outwards): {@link #LEVELS} + 6 values.
     */
    /**
     * The drawn heights of a patch, (PATCH_INTERVALS + 1)² row by row, NaN as 0: all the measurement reads. In a
     * per-thread array, overwritten by the thread's next call.
     */
    private static float[] patchHeights(Mosaic mosaic, int row0, int col0) {
        int p = PATCH_INTERVALS;
        float[] heights = PATCH_HEIGHTS.get(); // reused: tens of thousands of patches per build
        if (row0 >= 0 && col0 >= 0 && row0 + p < mosaic.rows() && col0 + p < mosaic.cols()) {
            // Inside the mosaic (no clamping): a row of samples at a time, as drawnHeight() reads them one by one.
            for (int a = 0; a <= p; a++) {
                mosaic.sampleRow(row0 + a, col0, p + 1, heights, a * (p + 1));
            }
            for (int k = 0; k < heights.length; k++) {
                if (Float.isNaN(heights[k])) {
                    heights[k] = 0f;
                }
            }
        } else {
            for (int a = 0; a <= p; a++) {
                for (int b = 0; b <= p; b++) {
                    heights[a * (p + 1) + b] = drawnHeight(mosaic, row0 + a, col0 + b);
                }
            }
        }
        return heights;
    }

    /** {@link DeviationCache}'s values of a patch from its heights ({@link #patchHeights}). */
    private static float[] deviationsOf(float[] heights) {
        int p = PATCH_INTERVALS;
        double[] dev = LevelOfDetail.deviationsMetres(heights, p + 1, 0, 0, p);
        float[] raw = new float[LEVELS + 6];
        for (int l = 0; l < LEVELS; l++) {
            raw[l] = (float) dev[l] < dev[l] ? Math.nextUp((float) dev[l]) : (float) dev[l];
        }
        float lowest = Float.POSITIVE_INFINITY, highest = Float.NEGATIVE_INFINITY;
        for (float h : heights) {
            lowest = Math.min(lowest, h);
            highest = Math.max(highest, h);
        }
        raw[LEVELS] = lowest;
        raw[LEVELS + 1] = highest;
        double minEast = Double.POSITIVE_INFINITY, maxEast = Double.NEGATIVE_INFINITY;
        double minSouth = Double.POSITIVE_INFINITY, maxSouth = Double.NEGATIVE_INFINITY;
        for (int a = 0; a <= p; a++) {
            for (int b = 0; b < p; b++) {
                double east = (double) heights[a * (p + 1) + b + 1] - heights[a * (p + 1) + b];
                double south = (double) heights[(b + 1) * (p + 1) + a] - heights[b * (p + 1) + a];
                minEast = Math.min(minEast, east);
                maxEast = Math.max(maxEast, east);
                minSouth = Math.min(minSouth, south);
                maxSouth = Math.max(maxSouth, south);
            }
        }
        raw[LEVELS + 2] = Math.nextDown((float) minEast);
        raw[LEVELS + 3] = Math.nextUp((float) maxEast);
        raw[LEVELS + 4] = Math.nextDown((float) minSouth);
        raw[LEVELS + 5] = Math.nextUp((float) maxSouth);
        return raw;
    }

    /**
     * Whether a patch's deviations hold for every viewpoint: not if it reaches beyond the mosaic or
     * into tiles that were not loaded, whose heights (sea level stand-ins) depend on the viewpoint.
     */
    private static boolean cacheable(Mosaic mosaic, int row0, int col0) {
        int p = PATCH_INTERVALS;
        if (row0 < 0 || col0 < 0 || row0 + p >= mosaic.rows() || col0 + p >= mosaic.cols()) {
            return false;
        }
        // Loading is per tile: the corners and the midpoints of the edges meet every tile the patch touches.
        for (int a = 0; a <= p; a += p / 2) {
            for (int b = 0; b <= p; b += p / 2) {
                if (Float.isNaN(mosaic.sample(row0 + a, col0 + b))) {
                    return false;
                }
            }
        }
        return true;
    }

    /** A row index held inside the mosaic: patches reaching beyond it repeat its edge (degenerate cells). */
    private static int clampRow(Mosaic mosaic, int row) {
        return Math.max(0, Math.min(mosaic.rows() - 1, row));
    }

    private static int clampCol(Mosaic mosaic, int col) {
        return Math.max(0, Math.min(mosaic.cols() - 1, col));
    }

    /** The height drawn at a (clamped) sample, metres: sea level where no tile was loaded (only beyond range). */
    private static float drawnHeight(Mosaic mosaic, int row, int col) {
        float h = mosaic.sample(clampRow(mosaic, row), clampCol(mosaic, col));
        return Float.isNaN(h) ? 0f : h;
    }

    private static long key(int row, int col) {
        return ((long) row << 32) ^ (col & 0xffffffffL);
    }

    /** A patch on its way from heights to mesh. */
    private static final class PatchWork {
        int row0, col0, level;
        DeviationCache.Key cacheKey;
        float[] rawDeviations;
        boolean cacheable, fromCache, hidden;
        double nearestMetres, farthestMetres;
        double[] deviations;
        double[] skirts;
        MeshCache.Key meshKey;
        MeshCache.Entry cached;
        /** Placed vertices and triangles of a patch merged with others (levels from MERGED_LEVEL). */
        PatchMesh mesh;
        /** The jME mesh of a patch drawn alone (levels below MERGED_LEVEL). */
        Mesh alone;
        /** ECEF points whose hull holds the placed patch. */
        double[] hull;

        double errorMetres() {
            return deviations[level];
        }
    }

    /**
     * A patch's vertex arrays and triangles: positions as ECEF double-single ({@code high} +
     * {@code low}, 3 floats each), ellipsoid normal and height above the ellipsoid ({@code up}, 4),
     * surface normal (ECEF, 3), texture coordinates (elevation, flags, grid row and column, 4), and 8 ECEF
     * points whose convex hull holds the patch ({@code hull}, 24 doubles). {@link #merge} makes the jME mesh,
     * normals there as signed normalized bytes, texture coordinates as shorts.
     */
    record PatchMesh(float[] high, float[] low, float[] up, float[] normals, float[] texCoords, int[] indices,
                     double[] hull) {

        int vertexCount() {
            return high.length / 3;
        }

        /** One jME mesh of several patches (indices 16-bit where they fit). */
        static Mesh merge(List<PatchMesh> parts) {
            int nv = 0, ni = 0;
            for (PatchMesh m : parts) {
                nv += m.vertexCount();
                ni += m.indices.length;
            }
            FloatBuffer pos = BufferUtils.createFloatBuffer(nv * 3), low = BufferUtils.createFloatBuffer(nv * 3);
            FloatBuffer up = BufferUtils.createFloatBuffer(nv * 4);
            // Normals as signed normalized bytes and the texture coordinates (elevation rounded to the metre,
            // flags, grid row and column: integers) as shorts: 12 bytes a vertex instead of 28, in the Java buffers
            // and in the driver's copy alike (the normal only shades, within 0.5°; the elevation only tints).
            ByteBuffer nor = BufferUtils.createByteBuffer(nv * 4);
            ShortBuffer tex = BufferUtils.createShortBuffer(nv * 4);
            boolean shortIndices = nv <= 65536;
            ShortBuffer si = shortIndices ? BufferUtils.createShortBuffer(ni) : null;
            IntBuffer ii = shortIndices ? null : BufferUtils.createIntBuffer(ni);
            for (PatchMesh m : parts) {
                pos.put(m.high);
                low.put(m.low);
                up.put(m.up);
                putNormals(m.normals, nor);
                putTexCoords(m.texCoords, tex);
            }
            // The triangles part by part, gathered in a heap array and put in one bulk copy (a put per index cost
            // most of a warm render's mesh stage).
            // (Each part's indices by a small method of its own: a loop in merge made the JIT recompile all of merge.)
            short[] shorts = shortIndices ? new short[ni] : null;
            int[] ints = shortIndices ? null : new int[ni];
            int at = 0, base = 0;
            for (PatchMesh m : parts) {
                if (shortIndices) {
                    shiftInto(m.indices, base, shorts, at);
                } else {
                    shiftInto(m.indices, base, ints, at);
                }
                at += m.indices.length;
                base += m.vertexCount();
            }
            if (shortIndices) {
                si.put(shorts);
            } else {
                ii.put(ints);
            }
            Mesh mesh = new Mesh();
            mesh.setMode(Mesh.Mode.Triangles);
            mesh.setBuffer(VertexBuffer.Type.Position, 3, pos.flip());
            mesh.setBuffer(VertexBuffer.Type.TexCoord2, 3, low.flip());
            mesh.setBuffer(VertexBuffer.Type.TexCoord3, 4, up.flip());
            VertexBuffer normals = new VertexBuffer(VertexBuffer.Type.Normal);
            normals.setupData(VertexBuffer.Usage.Static, 4, VertexBuffer.Format.Byte, nor.flip());
            normals.setNormalized(true);
            mesh.setBuffer(normals);
            mesh.setBuffer(VertexBuffer.Type.TexCoord, 4, tex.flip());
            if (shortIndices) {
                mesh.setBuffer(VertexBuffer.Type.Index, 3, si.flip());
            } else {
                mesh.setBuffer(VertexBuffer.Type.Index, 3, ii.flip());
            }
            mesh.updateCounts();
            return mesh;
        }

        /** Unit normals (3 floats a vertex) as signed normalized bytes, 4 a vertex (the fourth 0, for alignment). */
        private static void putNormals(float[] normals, ByteBuffer out) {
            byte[] bytes = new byte[normals.length / 3 * 4];
            // (Floors: the client compiler calls Math.round, 12 million times a cold panorama.)
            for (int k = 0, b = 0; k < normals.length; k += 3, b += 4) {
                bytes[b] = (byte) dempano.util.Floors.floorInt(normals[k] * 127.0 + 0.5);
                bytes[b + 1] = (byte) dempano.util.Floors.floorInt(normals[k + 1] * 127.0 + 0.5);
                bytes[b + 2] = (byte) dempano.util.Floors.floorInt(normals[k + 2] * 127.0 + 0.5);
            }
            out.put(bytes);
        }

        /** Texture coordinates (elevation, flags, grid row, grid column) as shorts, the elevation rounded to the metre. */
        private static void putTexCoords(float[] texCoords, ShortBuffer out) {
            short[] shorts = new short[texCoords.length];
            for (int k = 0; k < texCoords.length; k += 4) {
                shorts[k] = (short) dempano.util.Floors.floorInt(texCoords[k] + 0.5);
                shorts[k + 1] = (short) texCoords[k + 1]; // flags, row and column: integers
                shorts[k + 2] = (short) texCoords[k + 2];
                shorts[k + 3] = (short) texCoords[k + 3];
            }
            out.put(shorts);
        }

        private static void shiftInto(int[] indices, int base, short[] out, int at) {
            for (int k = 0; k < indices.length; k++) {
                out[at + k] = (short) (base + indices[k]);
            }
        }

        private static void shiftInto(int[] indices, int base, int[] out, int at) {
            for (int k = 0; k < indices.length; k++) {
                out[at + k] = base + indices[k];
            }
        }

        /** The hull points (ECEF, 3 doubles each) of several meshes together. */
        static double[] hull(List<PatchMesh> parts) {
            double[] all = new double[parts.size() * 24];
            for (int i = 0; i < parts.size(); i++) {
                System.arraycopy(parts.get(i).hull, 0, all, 24 * i, 24);
            }
            return all;
        }
    }

    /** Frees the native memory of a built terrain's buffers (the GL side is freed by the renderer). */
    public static void destroyBuffers(Spatial s) {
        if (s instanceof Geometry g) {
            for (VertexBuffer vb : g.getMesh().getBufferList()) {
                if (vb.getData() != null && vb.getData().isDirect()) {
                    BufferUtils.destroyDirectBuffer(vb.getData());
                }
            }
        } else if (s instanceof Node n) {
            for (Spatial c : n.getChildren()) {
                destroyBuffers(c);
            }
        }
    }

    /** Exact vertex positions (ECEF), normals and meshes. Stateless apart from its tables: thread-safe. */
    private static final class Placer {
        private final Mosaic mosaic;
        private final int r0, c0;
        private final double[] sinLat, cosLat, sinLon, cosLon;
        /** Per row: N(φ)·cos φ and N(φ)(1 − e²)·sin φ, metres (see the constructor). */
        private final double[] footCos, footSin;
        private final double exaggeration;

        Placer(Mosaic mosaic, int r0, int c0, double[] sinLat, double[] cosLat, double[] sinLon, double[] cosLon,
               double exaggeration) {
            this.exaggeration = exaggeration;
            this.mosaic = mosaic;
            this.r0 = r0;
            this.c0 = c0;
            this.sinLat = sinLat;
            // Per row, the foot's two latitude terms as Ellipsoid.toEcef forms them (h = 0, the same operations in
            // the same order, so the same bits): its square root once a row instead of once a vertex.
            footCos = new double[sinLat.length];
            footSin = new double[sinLat.length];
            for (int r = 0; r < sinLat.length; r++) {
                double n = Ellipsoid.primeVerticalRadiusOfSinMetres(sinLat[r]);
                footCos[r] = (n + 0.0) * cosLat[r];
                footSin[r] = (n * (1 - Ellipsoid.E2) + 0.0) * sinLat[r];
            }
            this.cosLat = cosLat;
            this.sinLon = sinLon;
            this.cosLon = cosLon;
        }

        /**
         * Places mosaic sample (r, c) at an elevation lowered by a drop as vertex k of {@code m}: its ECEF
         * position (double, no refraction: the shader lifts it for each eye) as double-single into
         * {@code m.high()} and {@code m.low()}, and its ellipsoid normal and height above the ellipsoid into
         * {@code m.up()} (4 floats).
         */
        private void place(int r, int c, double elevationMetres, double dropMetres, double[] foot, PatchMesh m, int k) {
            float[] high = m.high(), low = m.low(), up = m.up();
            int ri = Math.max(0, Math.min(sinLat.length - 1, r - r0)), ci = Math.max(0, Math.min(sinLon.length - 1, c - c0));
            foot[0] = footCos[ri] * cosLon[ci];
            foot[1] = footCos[ri] * sinLon[ci];
            foot[2] = footSin[ri];
            double h = elevationMetres - dropMetres;
            double nx = cosLat[ri] * cosLon[ci], ny = cosLat[ri] * sinLon[ci], nz = sinLat[ri];
            // ECEF(φ, λ, h) = ECEF(φ, λ, 0) + h·n̂ with n̂ the ellipsoid normal.
            split(foot[0] + h * nx, high, low, 3 * k);
            split(foot[1] + h * ny, high, low, 3 * k + 1);
            split(foot[2] + h * nz, high, low, 3 * k + 2);
            up[4 * k] = (float) nx;
            up[4 * k + 1] = (float) ny;
            up[4 * k + 2] = (float) nz;
            up[4 * k + 3] = (float) h;
        }

        /**
         * A patch's mesh at its level: every step-th sample, triangles split as {@link Triangulation}
         * says (on the mosaic grid at full resolution, on the coarse grid otherwise), and a skirt
         * hanging {@code skirtsMetres[e]} deep below each edge e (north, east, south, west) where
         * that is positive.
         */
        PatchMesh mesh(PatchWork w, double[] skirtsMetres) {
            int p = PATCH_INTERVALS, step = 1 << w.level, cs = p / step + 1;
            int skirted = 0;
            for (double d : skirtsMetres) {
                skirted += d > 0 ? 1 : 0;
            }
            int n = cs * cs + skirted * cs;
            float[] high = new float[n * 3], low = new float[n * 3];
            float[] up = new float[n * 4], normals = new float[n * 3], elevations = new float[n * 4];
            int cellTriangles = (cs - 1) * (cs - 1), triangles = cellTriangles * 2 + skirted * 2 * (cs - 1);
            // The arrays being filled (the hull comes last, from them).
            PatchMesh m = new PatchMesh(high, low, up, normals, elevations, new int[triangles * 3], null);
            placeGrid(w, step, cs, m);
            gridNormals(cs, m);
            int at = cellIndices(w, step, cs, m.indices());
            // Each skirted edge's vertices get twins lowered along the ellipsoid normal.
            int twin = cs * cs;
            for (int e = 0; e < 4; e++) {
                if (skirtsMetres[e] > 0) {
                    at = skirt(w, e, skirtsMetres[e], twin, m, at);
                    twin += cs;
                }
            }
            return new PatchMesh(high, low, up, normals, elevations, m.indices(), hull(cs, m));
        }

        // The phases of mesh, each a method of its own: the JIT then compiles small methods once, instead of
        // recompiling the whole of mesh on-stack at each of its loops (measured: 1.1-1.5 s of server compiler
        // time in a JVM's first four renders).

        /** Every step-th sample of the patch: positions, heights, flags and grid positions (see VERTEX_BASE). */
        private void placeGrid(PatchWork w, int step, int cs, PatchMesh m) {
            float[] high = m.high(), low = m.low(), up = m.up(), elevations = m.texCoords();
            double[] foot = new double[3];
            // A full-resolution patch inside the mosaic reads its heights a row at a time (as patchHeights does).
            boolean rows = step == 1 && w.row0 >= 0 && w.col0 >= 0 && w.row0 + cs <= mosaic.rows()
                    && w.col0 + cs <= mosaic.cols();
            float[] rowHeights = rows ? new float[cs] : null;
            for (int gi = 0; gi < cs; gi++) {
                int r = clampRow(mosaic, w.row0 + gi * step);
                if (rows) {
                    mosaic.sampleRow(r, w.col0, cs, rowHeights, 0);
                }
                for (int gj = 0; gj < cs; gj++) {
                    int c = clampCol(mosaic, w.col0 + gj * step), k = gi * cs + gj;
                    float h = rows ? (Float.isNaN(rowHeights[gj]) ? 0f : rowHeights[gj]) : drawnHeight(mosaic, r, c);
                    place(r, c, h * exaggeration, 0, foot, m, k);
                    elevations[4 * k] = h;
                    boolean seam = r % mosaic.intervalsPerDegree() == 0 || c % mosaic.intervalsPerDegree() == 0;
                    // The split of the cell whose north-west corner this is (a chessboard: the same for the cell
                    // whose south-east corner it is) tells the triangles it ends apart (see VERTEX_BASE).
                    boolean nwToSe = step == 1 ? Triangulation.splitsNorthWestToSouthEast(w.row0 + gi, w.col0 + gj)
                            : Triangulation.splitsNorthWestToSouthEast(gi, gj);
                    elevations[4 * k + 1] = mosaic.flags(r, c) | (seam ? 4 : 0) | (nwToSe ? NAMED_NW_SE : NAMED_NE_SW);
                    elevations[4 * k + 2] = gi;
                    elevations[4 * k + 3] = gj;
                }
            }
        }

        /** Normals (ECEF) from the exact positions: central differences over the drawn grid. */
        private static void gridNormals(int cs, PatchMesh m) {
            float[] high = m.high(), low = m.low(), up = m.up(), normals = m.normals();
            // Each position read once (a vertex serves four neighbours' differences).
            double[] p = new double[3 * cs * cs];
            for (int i = 0; i < p.length; i++) {
                p[i] = at(high, low, i);
            }
            for (int k = 0; k < cs * cs; k++) {
                int gi = k / cs, gj = k % cs;
                int north = gi > 0 ? k - cs : k, south = gi < cs - 1 ? k + cs : k;
                int left = gj > 0 ? k - 1 : k, right = gj < cs - 1 ? k + 1 : k;
                double ax = p[3 * right] - p[3 * left], ay = p[3 * right + 1] - p[3 * left + 1];
                double az = p[3 * right + 2] - p[3 * left + 2];
                double bx = p[3 * south] - p[3 * north], by = p[3 * south + 1] - p[3 * north + 1];
                double bz = p[3 * south + 2] - p[3 * north + 2];
                // (b × a) points up for a = east, b = south.
                double nx = by * az - bz * ay, ny = bz * ax - bx * az, nz = bx * ay - by * ax;
                double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
                if (len == 0) { // a degenerate cell (beyond the mosaic's edge): the ellipsoid's normal
                    nx = up[4 * k];
                    ny = up[4 * k + 1];
                    nz = up[4 * k + 2];
                    len = 1;
                }
                normals[3 * k] = (float) (nx / len);
                normals[3 * k + 1] = (float) (ny / len);
                normals[3 * k + 2] = (float) (nz / len);
            }
        }

        /** The cells' two triangles each (see the comment inside); returns the next free index. */
        private static int cellIndices(PatchWork w, int step, int cs, int[] indices) {
            int at = 0;
            for (int gi = 0; gi < cs - 1; gi++) {
                for (int gj = 0; gj < cs - 1; gj++) {
                    int nw = gi * cs + gj, ne = nw + 1, sw = nw + cs, se = sw + 1;
                    boolean nwToSe = step == 1 ? Triangulation.splitsNorthWestToSouthEast(w.row0 + gi, w.col0 + gj)
                            : Triangulation.splitsNorthWestToSouthEast(gi, gj);
                    // Every cell triangle wound counter-clockwise seen from above (GL's front, so that back faces
                    // can be culled in one draw call). The last vertex (GL's provoking vertex) names it (see
                    // VERTEX_BASE): a NW–SE cell's two triangles both end on its north-west corner; a NE–SW cell's
                    // north-western triangle ends there too, its south-eastern one on its south-east corner, which
                    // is the north-west corner of the next cell along the diagonal, a NE–SW cell as well (the split
                    // alternates like a chessboard).
                    if (nwToSe) {
                        at = put(indices, at, se, ne, nw);
                        at = put(indices, at, sw, se, nw);
                    } else {
                        at = put(indices, at, sw, ne, nw);
                        at = put(indices, at, ne, sw, se);
                    }
                }
            }
            return at;
        }

        /**
         * Edge e's skirt (see mesh): twins of its vertices from {@code twin} on, lowered {@code depthMetres},
         * and its triangles from index {@code at}; returns the next free index.
         */
        private int skirt(PatchWork w, int e, double depthMetres, int twin, PatchMesh m, int at) {
            int step = 1 << w.level, cs = PATCH_INTERVALS / step + 1;
            float[] high = m.high(), low = m.low(), up = m.up(), normals = m.normals(), elevations = m.texCoords();
            int[] indices = m.indices();
            double[] foot = new double[3];
            for (int t = 0; t < cs; t++) {
                int v = edgeVertex(e, t, cs), gi = v / cs, gj = v % cs, k = twin + t;
                int r = clampRow(mosaic, w.row0 + gi * step), c = clampCol(mosaic, w.col0 + gj * step);
                place(r, c, elevations[4 * v] * exaggeration, depthMetres, foot, m, k);
                System.arraycopy(normals, 3 * v, normals, 3 * k, 3);
                System.arraycopy(elevations, 4 * v, elevations, 4 * k, 4); // the grid position of its top too
                elevations[4 * k + 1] = ((int) elevations[4 * v + 1] & ~NAMED_MASK)
                        | (e % 2 == 0 ? NAMED_ALONG_COLUMNS : NAMED_ALONG_ROWS);
                if (t > 0) {
                    // Twin k is the last vertex of this quad's first triangle and of the next quad's second
                    // (see VERTEX_BASE). Both face out of the patch: the crack a skirt hides is seen from the
                    // neighbour's side (a skirt seen from inside the patch is below its surface). Edges run
                    // eastward and southward, so the north and east skirts take one order, the others the other.
                    int a = edgeVertex(e, t - 1, cs), b = v;
                    if (e < 2) {
                        at = put(indices, at, a, b, k);
                        at = put(indices, at, a, k, k - 1);
                    } else {
                        at = put(indices, at, b, a, k);
                        at = put(indices, at, k, a, k - 1);
                    }
                }
            }
            return at;
        }

        /**
         * The prism over the patch's corner feet from its lowest to its highest vertex bounds it (up to the
         * earth's curvature between corners, which the bounds' margin covers): 8 ECEF points.
         */
        private static double[] hull(int cs, PatchMesh m) {
            float[] high = m.high(), low = m.low(), up = m.up();
            int n = m.vertexCount();
            float lowest = Float.POSITIVE_INFINITY, highest = Float.NEGATIVE_INFINITY;
            for (int k = 0; k < n; k++) {
                lowest = Math.min(lowest, up[4 * k + 3]);
                highest = Math.max(highest, up[4 * k + 3]);
            }
            double[] hull = new double[24];
            int[] corners = {0, cs - 1, (cs - 1) * cs, cs * cs - 1};
            for (int q = 0; q < 4; q++) {
                int k = corners[q];
                for (int a = 0; a < 3; a++) {
                    double footA = at(high, low, 3 * k + a) - up[4 * k + 3] * (double) up[4 * k + a];
                    hull[6 * q + a] = footA + lowest * (double) up[4 * k + a];
                    hull[6 * q + 3 + a] = footA + highest * (double) up[4 * k + a];
                }
            }
            return hull;
        }

        /** A double as float high part and float remainder. */
        private static void split(double v, float[] high, float[] low, int i) {
            high[i] = (float) v;
            low[i] = (float) (v - high[i]);
        }

        /** The double a double-single pair holds (to 1e-15 relative). */
        private static double at(float[] high, float[] low, int i) {
            return high[i] + (double) low[i];
        }

        /** Vertex index of the t-th vertex along edge e (0 north, 1 east, 2 south, 3 west). */
        private static int edgeVertex(int e, int t, int cs) {
            return switch (e) {
                case 0 -> t;
                case 1 -> t * cs + cs - 1;
                case 2 -> (cs - 1) * cs + t;
                default -> t * cs;
            };
        }

        private static int put(int[] a, int w, int i, int j, int k) {
            a[w] = i;
            a[w + 1] = j;
            a[w + 2] = k;
            return w + 3;
        }
    }
}
