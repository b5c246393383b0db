package dempano.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.ViewCapture;
import dempano.panorama.ViewLayout;
import dempano.terrain.TerrainBuilder;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Culling the faces turned away from the eye (the offscreen renderer's default: every terrain triangle faces out,
 * {@link TerrainBuilder#CULL_BACK_FACES}, and back faces are culled in one draw call) takes away only faces turned
 * away: wherever a sample differs from the picture drawn with every face, something farther is seen now, never
 * nearer (no face turned to the eye is lost), up to a tie at an edge. From above a height field no face turned
 * away can be seen, so at Mount Washington almost every sample names the same triangle (15 of 1 273 000 differ,
 * measured). At Eggishorn 4 % do (51 045, at 100 m to 1 km): this test's 1 m near plane cuts away the slope under
 * the eye (which stands 0.9 m over the drawn surface there), so the views look out from under the ground, and see
 * faces from behind; culled, they look through them. Renders choose a near plane within the eye's clearance over
 * the drawn surface ({@link NearPlaneOnSteepSummitTest}) and see the slope itself. Drawn twice over, the culled
 * views are the same.
 */
class BackFaceCullingTest {
    /** Relative range difference that counts as one depth (a few float ulps: 1.2e-7 each). */
    private static final double TIE = 1e-6;

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "Mount Washington, 44.2706, -71.3033, 80000, 2e-5",
            "Eggishorn, 46.4316, 8.0929, 80000, 0.05",
    })
    void cullingFacesTurnedAwayTakesAwayOnlyThem(String place, double lat, double lon, double rangeMetres,
                                                  double maxDifferingShare) {
        RealSceneViews scene = RealSceneViews.of(lat, lon, 2, rangeMetres);
        TerrainBuilder.Terrain terrain = scene.terrain();
        ViewLayout layout = scene.layout();
        try (OffscreenRenderer.Handle handle = OffscreenRenderer.acquire()) {
            OffscreenRenderer gl = handle.renderer();
            OffscreenRenderer.ViewRequest culled = scene.drawnBy(gl).request();
            ViewCapture[] first = gl.render(terrain.root(), culled, new long[2]);
            ViewCapture[] every = gl.render(terrain.root(), culled.withBackFaces(), new long[2]);
            ViewCapture[] again = gl.render(terrain.root(), culled, new long[2]);
            long samples = 0, terrainSamples = 0, differing = 0;
            for (int k = 0; k < layout.views(); k++) {
                assertArrayEquals(first[k].triangleIds(), again[k].triangleIds(), place + ": view " + k + " drawn twice");
                int[] a = first[k].triangleIds(), b = every[k].triangleIds();
                for (int i = 0; i < a.length; i++) {
                    samples++;
                    terrainSamples += b[i] >= 0 ? 1 : 0;
                    if (a[i] == b[i]) {
                        continue;
                    }
                    differing++;
                    float withCulling = a[i] >= 0 ? first[k].depth()[i] : Float.POSITIVE_INFINITY;
                    float withEveryFace = every[k].depth()[i];
                    // Where a face turned away meets one turned to the eye (at an edge), the two are at one depth and
                    // float rounding decides which the depth test keeps with every face drawn: a few ulps nearer is a tie.
                    assertTrue(b[i] >= 0 && withCulling >= withEveryFace * (1 - TIE), place + ": view " + k + ", sample " + i
                            + ": culling may only take away a face turned away (" + withEveryFace + " m with every face, "
                            + withCulling + " m culled)");
                }
            }
            System.out.printf("%s: %d of %d samples (%d on terrain) name another triangle with faces turned away culled%n",
                    place, differing, samples, terrainSamples);
            assertTrue(terrainSamples > samples / 4, "terrain seen: " + terrainSamples);
            assertTrue(differing <= maxDifferingShare * samples, place + ": " + differing + " samples differ");
        }
    }
}
