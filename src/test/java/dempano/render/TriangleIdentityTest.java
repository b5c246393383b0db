package dempano.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.SeenTriangles;
import dempano.panorama.ViewCapture;
import dempano.panorama.ViewLayout;
import dempano.terrain.EyePlacement;
import dempano.terrain.SeenTriangleResolver;
import dempano.terrain.TerrainBuilder;
import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The triangle the shader names for each view sample (its provoking vertex, {@code VertexBase +
 * gl_VertexID}, and its facing, read back as RG32UI and resolved by {@link SeenTriangleResolver})
 * is the one that sample's own centre
 * ray meets: intersected in double precision, the named triangle gives the range the shader wrote
 * beside it. Real scenes with full-resolution, simplified and merged patches and their skirts.
 */
class TriangleIdentityTest {
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "Mount Washington, 44.2706, -71.3033, 2, 80000",
            "Eggishorn, 46.4316, 8.0929, 2, 80000",
    })
    void eachSampleNamesTheTriangleItsRayMeets(String place, double lat, double lon, double eyeHeightMetres,
                                               double rangeMetres) {
        RealSceneViews scene = RealSceneViews.of(lat, lon, eyeHeightMetres, rangeMetres);
        TerrainBuilder.Terrain terrain = scene.terrain();
        ViewLayout layout = scene.layout();
        Viewpoint eye = scene.eye();
        Refraction refraction = scene.refraction();
        int levels = 0;
        for (int n : terrain.patchesPerLevel()) {
            levels += n > 0 ? 1 : 0;
        }
        assertTrue(levels >= 3, "full-resolution and simplified patches: " + Arrays.toString(terrain.patchesPerLevel()));
        try (OffscreenRenderer.Handle handle = OffscreenRenderer.acquire()) {
            OffscreenRenderer gl = handle.renderer();
            OffscreenRenderer.ViewRequest request = scene.drawnBy(gl).request();
            ViewCapture[] captures = gl.render(terrain.root(), request, new long[2]);
            int[] bases = TerrainBuilder.vertexBases(terrain.drawn());
            assertEquals(terrain.drawn().size(), bases.length - 1);
            Set<Integer> geometriesSeen = new HashSet<>();
            SeenTriangles seen = SeenTriangleResolver.resolve(terrain.drawn(), captures, new EyePlacement(eye, refraction),
                    rangeMetres);
            long terrainSamples = 0, met = 0, metOnSimplified = 0;
            double[] relative = new double[layout.widthPx() * layout.heightPx() * layout.views()];
            int n = 0;
            for (int k = 0; k < captures.length; k++) {
                double[] a = layout.axes(k); // right, up, forward in east-north-up
                int[] ids = captures[k].triangleIds();
                int[] triangleOf = seen.triangleOfSample()[k];
                for (int i = 0; i < ids.length; i++) {
                    if (ids[i] < 0) {
                        assertEquals(-1, triangleOf[i], "sky sample " + i + " of view " + k);
                        continue;
                    }
                    terrainSamples++;
                    int g = Arrays.binarySearch(bases, ids[i] >>> 1);
                    geometriesSeen.add(g >= 0 ? g : -g - 2);
                    double x = layout.xTanOfPixel(i % layout.widthPx()), y = layout.yTanOfPixel(i / layout.widthPx());
                    double east = a[0] * x + a[3] * y + a[6], north = a[1] * x + a[4] * y + a[7];
                    double up = a[2] * x + a[5] * y + a[8];
                    double norm = Math.sqrt(east * east + north * north + up * up);
                    // jME axes: x east, y up, z south.
                    double metres = seen.distanceAlong(triangleOf[i], east / norm, up / norm, -north / norm);
                    double range = captures[k].depth()[i];
                    double rel = Math.abs(metres - range) / range;
                    relative[n++] = Double.isFinite(rel) ? rel : Double.MAX_VALUE;
                    if (rel <= 1e-3) {
                        met++;
                        metOnSimplified += seen.simplified()[triangleOf[i]] ? 1 : 0;
                    }
                }
            }
            double[] sorted = Arrays.copyOf(relative, n);
            Arrays.sort(sorted);
            double median = sorted[n / 2];
            System.out.printf("%s: %d samples on terrain, %d triangles seen, %d geometries; the named triangle "
                            + "gives the written range within 0.1 %% at %.4f %% of samples (%d on simplified "
                            + "patches), median relative difference %.2e%n", place, terrainSamples, seen.triangles(),
                    geometriesSeen.size(), 100.0 * met / terrainSamples, metOnSimplified, median);
            assertTrue(terrainSamples > captures[0].triangleIds().length, "terrain seen: " + terrainSamples);
            assertTrue(geometriesSeen.size() > 20, geometriesSeen.size() + " geometries seen");
            assertTrue(metOnSimplified > 0 && metOnSimplified < met, metOnSimplified + " of " + met + " on simplified patches");
            // Float rounding of the written range: a wrong triangle would miss the ray or lie elsewhere.
            assertTrue(median < 1e-5, "median relative difference " + median);
            // A sample near a shared edge may, in double precision, just miss the triangle the
            // rasteriser (float vertices and rays) gave it: at Mount Washington 0.10 % of samples,
            // 95 % of them within 1 % of the triangle's size outside an edge, most at grazing
            // incidence where a 1e-7 rad ray difference moves the hit by decimetres. A wrong
            // numbering (another triangle, another geometry's base) misses nearly every ray.
            assertTrue(met >= 0.998 * terrainSamples, met + " of " + terrainSamples + " samples");
            // One resolver for the views one at a time (the renderer's stitch passes) gives each view what a fresh
            // resolve of that view alone gives: the same triangles seen (nothing kept from the views before) and,
            // at every sample, the same corners.
            SeenTriangleResolver.Scene passes = new SeenTriangleResolver.Scene(terrain.drawn(),
                    new EyePlacement(eye, refraction), rangeMetres);
            for (int k = 0; k < captures.length; k++) {
                ViewCapture[] alone = new ViewCapture[captures.length];
                alone[k] = captures[k];
                SeenTriangles inTurn = passes.resolve(alone);
                SeenTriangles fresh = SeenTriangleResolver.resolve(terrain.drawn(), alone, new EyePlacement(eye, refraction),
                        rangeMetres);
                assertEquals(fresh.triangles(), inTurn.triangles(), "view " + k + ": triangles seen");
                int[] a = fresh.triangleOfSample()[k], b = inTurn.triangleOfSample()[k];
                for (int i = 0; i < a.length; i++) {
                    assertEquals(a[i] < 0, b[i] < 0, "view " + k + ", sample " + i);
                    if (a[i] >= 0) {
                        assertArrayEquals(Arrays.copyOfRange(fresh.corners(), 9 * a[i], 9 * a[i] + 9),
                                Arrays.copyOfRange(inTurn.corners(), 9 * b[i], 9 * b[i] + 9), "view " + k + ", sample " + i);
                    }
                }
                for (int other = 0; other < captures.length; other++) {
                    assertEquals(other == k, inTurn.triangleOfSample()[other] != null, "view " + other + " in pass " + k);
                }
            }
        } finally {
            terrain.root().detachAllChildren();
        }
    }
}
