package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.mesh.IndexBuffer;
import dempano.Synthetic;
import dempano.dem.DemSource;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.Ellipsoid;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Mesh building without GL: the deviation cache changes nothing but the time, and is reused. */
class TerrainBuilderTest {
    /**
     * Relief with ridges in both directions, so that every level of detail has a different error;
     * periodic in longitude (whole cycles around the globe), so continuous across ±180° as real
     * tiles are: neighbouring tiles must agree on their shared edge for cached deviations to hold.
     */
    static double relief(double lat, double lon) {
        double lam = Math.toRadians(lon);
        return 800 + 600 * Math.sin(lat * 20) * Math.cos(lam * 860) + 30 * Math.sin(lat * 150 + lam * 5157);
    }

    static TerrainBuilder.Terrain build(DemSource dem, double lat, double lon, double rangeMetres, DeviationCache cache) {
        Mosaic m = Mosaic.around(dem, lat, lon, rangeMetres, MissingTilePolicy.SEA_LEVEL);
        Viewpoint eye = Viewpoint.onDem(m, lat, lon, 0, 2);
        return TerrainBuilder.build(m, eye, new Refraction(0.13), rangeMetres, null, TerrainBuilder.Detail.of(20, 0.5).withCache(cache));
    }

    @ParameterizedTest
    @CsvSource({
            "46.5, 8.5, 46, 8",       // mid-block
            "10.5, 179.8, 10, 179",   // across the antimeridian: the global patch grid wraps
            "-0.3, -0.4, -1, -1",     // equator and prime meridian
    })
    void theCacheGivesTheSameTerrainAndIsReusedByAViewpointNearby(double lat, double lon, int latS, int lonW) {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(latS - 1, lonW - 1, 3, 3));
        double range = 60_000;
        DeviationCache cache = new DeviationCache();
        TerrainBuilder.Terrain first = build(dem, lat, lon, range, cache);
        TerrainBuilder.Terrain uncached = build(dem, lat, lon, range, null);
        int filled = cache.size();
        assertTrue(filled > 0.8 * first.patches(), "most patches are cacheable: " + filled + " of " + first.patches());
        TerrainBuilder.Terrain again = build(dem, lat, lon, range, cache);
        assertEquals(filled, cache.size(), "a second render of the same viewpoint adds nothing");
        for (TerrainBuilder.Terrain t : new TerrainBuilder.Terrain[] {uncached, again}) {
            assertArrayEquals(first.patchesPerLevel(), t.patchesPerLevel());
            assertEquals(first.triangles(), t.triangles());
            assertEquals(first.vertices(), t.vertices());
        }
        assertTrue(Arrays.stream(first.patchesPerLevel()).filter(n -> n > 0).count() >= 3,
                "several levels are in use: " + Arrays.toString(first.patchesPerLevel()));
        // 2 km away the range circle moves by 2 km: only patches along its rim are new.
        double lat2 = lat + 0.018;
        TerrainBuilder.Terrain moved = build(dem, lat2, lon, range, cache);
        int added = cache.size() - filled;
        assertTrue(added < 0.1 * moved.patches(), added + " new patches of " + moved.patches());
        TerrainBuilder.Terrain movedUncached = build(dem, lat2, lon, range, null);
        assertArrayEquals(movedUncached.patchesPerLevel(), moved.patchesPerLevel());
        assertEquals(movedUncached.triangles(), moved.triangles());
    }

    @Test
    void aBoundedCacheForgetsTheLeastRecentlyUsed() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        DeviationCache small = new DeviationCache(20);
        TerrainBuilder.Terrain t = build(dem, 46.5, 8.5, 30_000, small);
        assertEquals(20, small.size());
        assertEquals(build(dem, 46.5, 8.5, 30_000, null).triangles(), t.triangles());
    }

    static TerrainBuilder.Terrain build(DemSource dem, double lat, double lon, double rangeMetres, DeviationCache cache,
                                        MeshCache meshes) {
        Mosaic m = Mosaic.around(dem, lat, lon, rangeMetres, MissingTilePolicy.SEA_LEVEL);
        Viewpoint eye = Viewpoint.onDem(m, lat, lon, 0, 2);
        return TerrainBuilder.build(m, eye, new Refraction(0.13), rangeMetres, null,
                TerrainBuilder.Detail.of(20, 0.5).withCache(cache).withMeshes(meshes));
    }

    @Test
    void fineGeometriesAreReusedByTheSameAndANearbyViewpointAndMatchAFreshBuild() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        DeviationCache deviations = new DeviationCache();
        MeshCache meshes = new MeshCache();
        TerrainBuilder.Terrain first = build(dem, 46.5, 8.5, 40_000, deviations, meshes);
        assertEquals(0, first.reusedPatches());
        int fine = first.patchesPerLevel()[0] + first.patchesPerLevel()[1];
        assertEquals(fine, meshes.size(), "every fine patch (all cacheable here) is kept");
        assertEquals(first.patches() - fine > 0 ? 1 : 0, Math.min(1, first.transientParts().size()),
                "merged coarse blocks are made for the build only");
        TerrainBuilder.Terrain again = build(dem, 46.5, 8.5, 40_000, deviations, meshes);
        assertEquals(fine, again.reusedPatches(), "the same viewpoint reuses every fine patch");
        assertEquals(first.triangles(), again.triangles());
        assertEquals(first.vertices(), again.vertices());
        // 2 km away most fine patches keep their level and skirts; the terrain is that of a fresh build.
        TerrainBuilder.Terrain moved = build(dem, 46.518, 8.5, 40_000, deviations, meshes);
        TerrainBuilder.Terrain fresh = build(dem, 46.518, 8.5, 40_000, null, null);
        int movedFine = moved.patchesPerLevel()[0] + moved.patchesPerLevel()[1];
        assertTrue(moved.reusedPatches() > 0.5 * movedFine, moved.reusedPatches() + " of " + movedFine + " reused");
        assertArrayEquals(fresh.patchesPerLevel(), moved.patchesPerLevel());
        assertEquals(fresh.triangles(), moved.triangles());
        assertEquals(fresh.vertices(), moved.vertices());
        int freshFine = fresh.patchesPerLevel()[0] + fresh.patchesPerLevel()[1];
        assertEquals(freshFine + countMerged(fresh), fresh.transientParts().size(),
                "without a cache every geometry is made for the build (and released after it)");
    }

    static TerrainBuilder.Terrain panoramaBuild(DemSource dem, double lat, double lon, double eyeHeightMetres,
                                                DeviationCache cache) {
        Mosaic m = Mosaic.around(dem, lat, lon, 40_000, MissingTilePolicy.SEA_LEVEL);
        Viewpoint eye = Viewpoint.onDem(m, lat, lon, 0, eyeHeightMetres);
        // A cull angle: a panorama's build, whose fixed eye the distance bound needs.
        return TerrainBuilder.build(m, eye, new Refraction(0.13), 40_000, null,
                TerrainBuilder.Detail.of(20, 0.5).withCache(cache).withCullBelowDeg(-30));
    }

    /** A rippled slope rising northwards (every facet rises north, 6 % to 24 %) north of 46.45°, the sea south of it. */
    static double slope(double lat, double lon) {
        double y = Math.max(0, (lat - 46.45) * 111_195);
        return 0.15 * y + 15 * (1 - Math.cos(2 * Math.PI * y / 1_000));
    }

    @Test
    void cachedPatchBoundsServeTheDistanceBoundOfAnyEye() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::slope, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        DeviationCache cache = new DeviationCache();
        TerrainBuilder.Terrain low = panoramaBuild(dem, 46.5, 8.5, 2, cache);
        assertArrayEquals(panoramaBuild(dem, 46.5, 8.5, 2, null).patchesPerLevel(), low.patchesPerLevel());
        // Another eye (higher, elsewhere) over the same cached patches: its own heights, distances and
        // directions decide, as in a build without the cache.
        for (double[] eye : new double[][] {{46.5, 8.5, 1500}, {46.42, 8.41, 400}, {46.48, 8.55, 5000}}) {
            TerrainBuilder.Terrain cached = panoramaBuild(dem, eye[0], eye[1], eye[2], cache);
            TerrainBuilder.Terrain fresh = panoramaBuild(dem, eye[0], eye[1], eye[2], null);
            assertArrayEquals(fresh.patchesPerLevel(), cached.patchesPerLevel(), Arrays.toString(eye));
            assertEquals(fresh.triangles(), cached.triangles());
            assertTrue(cached.reusedPatches() == 0 && cache.size() > 0.5 * cached.patches());
        }
        assertTrue(!Arrays.equals(low.patchesPerLevel(), panoramaBuild(dem, 46.5, 8.5, 1500, cache).patchesPerLevel()),
                "the eye's height changes the levels");
    }

    private static int countMerged(TerrainBuilder.Terrain t) {
        int merged = 0;
        for (Geometry g : t.transientParts()) {
            merged += g.getName().contains("-coarse-") ? 1 : 0;
        }
        return merged;
    }

    @Test
    void aBoundedMeshCacheLetsTheLeastRecentlyUsedGoButNeverWhatTheBuildDraws() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(44, 6, 5, 5));
        MeshCache small = new MeshCache(50_000);
        TerrainBuilder.Terrain a = build(dem, 46.5, 8.5, 30_000, null, small);
        long inUseA = small.vertices();
        assertTrue(inUseA > 50_000, "this build alone needs more than the budget: " + inUseA);
        assertTrue(a.evicted().isEmpty(), "nothing the build draws is let go");
        // 150 km away: nothing in common; all of the first build's geometries go.
        TerrainBuilder.Terrain b = build(dem, 45.2, 7.2, 30_000, null, small);
        assertEquals(0, b.reusedPatches());
        assertTrue(b.evicted().size() > 0);
        int fineB = b.patchesPerLevel()[0] + b.patchesPerLevel()[1];
        assertEquals(fineB, small.size(), "only the second build's geometries stay");
        java.util.Set<Geometry> drawn = new java.util.HashSet<>();
        b.root().depthFirstTraversal(sp -> {
            if (sp instanceof Geometry g) {
                drawn.add(g);
            }
        });
        for (Geometry g : b.evicted()) {
            assertTrue(!drawn.contains(g), "an evicted geometry is not in the scene being drawn");
        }
    }

    /**
     * The contract the shader's sample names rest on ({@link TerrainBuilder#VERTEX_BASE}): every
     * vertex is the last of at most two triangles; every triangle's corners lie within one cell of
     * each other in the grid its vertices carry; the naming rule's f keeps one sign over each
     * triangle (its other two vertices' f are not of opposite signs, and not both 0); and of two
     * triangles ending at one vertex, one lies where f &gt; 0 and the other where f &lt; 0.
     * Full-resolution, simplified and merged patches, skirts.
     */
    @Test
    void everyVertexEndsAtMostTwoTrianglesOnOppositeSides() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        TerrainBuilder.Terrain t = build(dem, 46.5, 8.5, 60_000, null);
        int levels = 0;
        for (int n : t.patchesPerLevel()) {
            levels += n > 0 ? 1 : 0;
        }
        assertTrue(levels >= 3, Arrays.toString(t.patchesPerLevel()));
        long pairs = 0, single = 0;
        int[] rulesSeen = new int[4];
        for (Geometry g : t.drawn()) {
            Mesh mesh = g.getMesh();
            ShortBuffer tex = (ShortBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord).getData();
            assertEquals(4, mesh.getBuffer(VertexBuffer.Type.TexCoord).getNumComponents(), g.getName());
            IndexBuffer index = mesh.getIndexBuffer();
            int triangles = index.size() / 3;
            int[][] endingAt = new int[mesh.getVertexCount()][];
            double[] side = new double[triangles];
            for (int p = 0; p < triangles; p++) {
                int v = index.get(3 * p + 2);
                int[] list = endingAt[v];
                endingAt[v] = list == null ? new int[] {p} : new int[] {list[0], p};
                assertTrue(list == null || list.length == 1, "vertex " + v + " ends three triangles or more in " + g.getName());
                int rule = tex.get(4 * v + 1) & TerrainBuilder.NAMED_MASK;
                rulesSeen[rule / 8]++;
                double[] f = new double[2];
                for (int c = 0; c < 2; c++) {
                    int u = index.get(3 * p + c);
                    double dr = tex.get(4 * u + 2) - tex.get(4 * v + 2), dc = tex.get(4 * u + 3) - tex.get(4 * v + 3);
                    String where = g.getName() + ", triangle " + p;
                    assertTrue(Math.abs(dr) <= 1 && Math.abs(dc) <= 1, where + ": corners more than a cell apart");
                    f[c] = TerrainBuilder.namingSide(rule, dr, dc);
                }
                String where = g.getName() + ", triangle " + p + ", rule " + rule + ": f " + Arrays.toString(f);
                assertTrue(f[0] * f[1] >= 0 && (f[0] != 0 || f[1] != 0), where);
                side[p] = f[0] + f[1];
            }
            for (int[] list : endingAt) {
                if (list == null) {
                    continue;
                }
                if (list.length == 1) {
                    single++;
                    continue;
                }
                pairs++;
                assertTrue(side[list[0]] * side[list[1]] < 0, g.getName() + ": triangles " + list[0] + " and " + list[1]
                        + " end at one vertex on one side");
            }
        }
        assertTrue(pairs > single, pairs + " pairs, " + single + " single");
        for (int rule = 0; rule < 4; rule++) {
            assertTrue(rulesSeen[rule] > 0, "rule " + 8 * rule + " used: " + Arrays.toString(rulesSeen));
        }
    }

    /**
     * {@link TerrainBuilder#CULL_BACK_FACES}: every terrain triangle is wound counter-clockwise seen from above (its
     * normal by the right-hand rule rises), every skirt (a vertical wall) faces out of its patch (away from the
     * cell triangles at its top vertices), and every geometry is marked so.
     */
    @Test
    void everyTriangleFacesOut() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::relief, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        TerrainBuilder.Terrain t = build(dem, 46.5, 8.5, 60_000, null);
        long up = 0, walls = 0;
        for (Geometry g : t.drawn()) {
            assertEquals(Boolean.TRUE, g.getUserData(TerrainBuilder.CULL_BACK_FACES), g.getName());
            Mesh mesh = g.getMesh();
            FloatBuffer high = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            FloatBuffer low = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord2).getData();
            FloatBuffer ups = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord3).getData();
            IndexBuffer index = mesh.getIndexBuffer();
            int triangles = index.size() / 3;
            boolean[] wall = new boolean[triangles];
            double[][] centroidOf = new double[mesh.getVertexCount()][]; // a cell triangle's centroid at each vertex
            for (int p = 0; p < triangles; p++) {
                double[] n = normal(index, high, low, p);
                double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                if (length == 0) {
                    wall[p] = true; // a degenerate cell beyond the mosaic's edge: no face
                    continue;
                }
                int v = index.get(3 * p);
                double rise = (n[0] * ups.get(4 * v) + n[1] * ups.get(4 * v + 1) + n[2] * ups.get(4 * v + 2)) / length;
                wall[p] = Math.abs(rise) < 1e-3;
                if (!wall[p]) {
                    assertTrue(rise > 1e-3, g.getName() + ", triangle " + p + ": rise " + rise);
                    up++;
                    double[] c = new double[3];
                    for (int k = 0; k < 3; k++) {
                        for (int a = 0; a < 3; a++) {
                            c[a] += position(high, low, index.get(3 * p + k))[a] / 3;
                        }
                    }
                    for (int k = 0; k < 3; k++) {
                        centroidOf[index.get(3 * p + k)] = c;
                    }
                }
            }
            for (int p = 0; p < triangles; p++) {
                double[] n = normal(index, high, low, p);
                if (!wall[p] || n[0] == 0 && n[1] == 0 && n[2] == 0) {
                    continue;
                }
                for (int k = 0; k < 3; k++) {
                    int v = index.get(3 * p + k);
                    if (centroidOf[v] != null) { // a top vertex: the cells beside it are inside the patch
                        double[] a = position(high, low, v);
                        double inward = n[0] * (centroidOf[v][0] - a[0]) + n[1] * (centroidOf[v][1] - a[1])
                                + n[2] * (centroidOf[v][2] - a[2]);
                        assertTrue(inward < 0, g.getName() + ", skirt triangle " + p + " faces into its patch");
                        walls++;
                        break;
                    }
                }
            }
        }
        assertTrue(up > 0 && walls > 0, up + " terrain triangles, " + walls + " skirt triangles");
    }

    /** A tilted plane in latitude and longitude: 10 % up northwards, 5 % down eastwards, metres. */
    static double tilted(double lat, double lon) {
        return 3000 + 11_000 * (lat - 46.5) - 4_000 * (lon - 8.5);
    }

    /**
     * The shading normals, stored as signed normalized bytes, point within 0.5° of the surface's exact normal (the
     * cross product of the surface's tangents along latitude and longitude, by finite differences of its closed
     * form), and the elevations, stored as shorts, are the surface's height rounded to the metre: at every grid
     * vertex of every level.
     */
    @Test
    void compactNormalsAndElevationsHoldTheirStatedPrecision() {
        DemSource dem = Synthetic.tiles(TerrainBuilderTest::tilted, Synthetic.N, Synthetic.block(45, 7, 3, 3));
        TerrainBuilder.Terrain t = build(dem, 46.5, 8.5, 20_000, null);
        double worstDeg = 0, worstMetres = 0;
        long vertices = 0;
        double[] a = new double[3], b = new double[3], c = new double[3], d = new double[3];
        for (Geometry g : t.drawn()) {
            Mesh mesh = g.getMesh();
            VertexBuffer normalBuffer = mesh.getBuffer(VertexBuffer.Type.Normal);
            assertTrue(normalBuffer.isNormalized(), g.getName());
            ByteBuffer normals = (ByteBuffer) normalBuffer.getData();
            ShortBuffer tex = (ShortBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord).getData();
            FloatBuffer high = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.Position).getData();
            FloatBuffer low = (FloatBuffer) mesh.getBuffer(VertexBuffer.Type.TexCoord2).getData();
            for (int v = 0; v < mesh.getVertexCount(); v++) {
                if ((tex.get(4 * v + 1) & TerrainBuilder.NAMED_MASK) >= TerrainBuilder.NAMED_ALONG_COLUMNS) {
                    continue; // a skirt's lowered twin
                }
                double[] p = position(high, low, v);
                double[] geo = Ellipsoid.toGeodetic(p[0], p[1], p[2]);
                double step = 1e-5; // degrees: about a metre
                Ellipsoid.toEcef(geo[0] + step, geo[1], tilted(geo[0] + step, geo[1]), a);
                Ellipsoid.toEcef(geo[0] - step, geo[1], tilted(geo[0] - step, geo[1]), b);
                Ellipsoid.toEcef(geo[0], geo[1] + step, tilted(geo[0], geo[1] + step), c);
                Ellipsoid.toEcef(geo[0], geo[1] - step, tilted(geo[0], geo[1] - step), d);
                double[] north = {a[0] - b[0], a[1] - b[1], a[2] - b[2]}, east = {c[0] - d[0], c[1] - d[1], c[2] - d[2]};
                double[] n = {east[1] * north[2] - east[2] * north[1], east[2] * north[0] - east[0] * north[2],
                        east[0] * north[1] - east[1] * north[0]};
                double[] stored = {Math.max(-1, normals.get(4 * v) / 127.0), Math.max(-1, normals.get(4 * v + 1) / 127.0),
                        Math.max(-1, normals.get(4 * v + 2) / 127.0)};
                double cos = (n[0] * stored[0] + n[1] * stored[1] + n[2] * stored[2])
                        / Math.sqrt((n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
                        * (stored[0] * stored[0] + stored[1] * stored[1] + stored[2] * stored[2]));
                worstDeg = Math.max(worstDeg, Math.toDegrees(Math.acos(Math.min(1, cos))));
                worstMetres = Math.max(worstMetres, Math.abs(tex.get(4 * v) - tilted(geo[0], geo[1])));
                vertices++;
            }
        }
        assertTrue(vertices > 2_000, vertices + " grid vertices");
        assertTrue(worstDeg < 0.5, "normal off by " + worstDeg + "°"); // measured 0.33°
        assertTrue(worstMetres <= 0.51, "elevation off by " + worstMetres + " m");
    }

    private static double[] position(FloatBuffer high, FloatBuffer low, int k) {
        return new double[] {high.get(3 * k) + (double) low.get(3 * k), high.get(3 * k + 1) + (double) low.get(3 * k + 1),
                high.get(3 * k + 2) + (double) low.get(3 * k + 2)};
    }

    /** A triangle's normal by the right-hand rule over its drawn order (ECEF, double). */
    private static double[] normal(IndexBuffer index, FloatBuffer high, FloatBuffer low, int p) {
        double[][] v = new double[3][3];
        for (int c = 0; c < 3; c++) {
            int k = index.get(3 * p + c);
            for (int a = 0; a < 3; a++) {
                v[c][a] = high.get(3 * k + a) + (double) low.get(3 * k + a);
            }
        }
        double[] e1 = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
        double[] e2 = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
        return new double[] {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    }
}
