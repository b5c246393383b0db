package dempano.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.jme3.material.Material;
import com.jme3.scene.Geometry;
import dempano.SharedData;
import dempano.dem.DemDirectory;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.DepthMode;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.SeenTriangles;
import dempano.panorama.ViewCapture;
import dempano.panorama.ViewLayout;
import dempano.terrain.EyePlacement;
import dempano.terrain.SeenTriangleResolver;
import dempano.terrain.TerrainBuilder;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The triangle the shader names for each sample (from the flat attribute of the triangle's own
 * provoking vertex) is the one OpenGL itself counts ({@code gl_PrimitiveID}, the shader's
 * {@code PrimitiveIdCheck} variant), on every sample of real scenes with full-resolution,
 * simplified and merged patches and their skirts; and the range written beside it is the same to
 * the bit.
 */
class TriangleIdentityTest {
    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "Mount Washington, 44.2706, -71.3033, 2, 80000",
            "Eggishorn, 46.4316, 8.0929, 2, 80000",
    })
    void theProvokingVertexNamesTheTriangleGlCounts(String place, double lat, double lon, double eyeHeightMetres,
                                                    double rangeMetres) {
        Mosaic mosaic = Mosaic.around(new DemDirectory(SharedData.demDir()), lat, lon, rangeMetres,
                MissingTilePolicy.SEA_LEVEL);
        Viewpoint eye = Viewpoint.onDem(mosaic, lat, lon, 0, eyeHeightMetres);
        Refraction refraction = new Refraction(0.13);
        double ppd = 10;
        TerrainBuilder.Terrain terrain = TerrainBuilder.build(mosaic, eye, refraction, rangeMetres, null,
                TerrainBuilder.Detail.of(ppd, 0.5));
        int levels = 0;
        for (int n : terrain.patchesPerLevel()) {
            levels += n > 0 ? 1 : 0;
        }
        assertTrue(levels >= 3, "full-resolution and simplified patches: " + java.util.Arrays.toString(terrain.patchesPerLevel()));
        ViewLayout layout = ViewLayout.forPanorama(PanoramaGeometry.of(ppd, -15, 15), 8, 1);
        try (OffscreenRenderer.Handle handle = OffscreenRenderer.acquire()) {
            OffscreenRenderer gl = handle.renderer();
            Material material = gl.newTerrainMaterial(rangeMetres);
            material.setBoolean("DistanceOnly", true);
            new EyePlacement(eye, refraction).apply(material);
            for (Geometry g : terrain.drawn()) {
                g.setMaterial(material);
            }
            OffscreenRenderer.ViewRequest request = new OffscreenRenderer.ViewRequest(layout, DepthMode.SHADER_RANGE, 1,
                    rangeMetres * 1.1 + 20_000, false, true, true, false);
            ViewCapture[] provoked = gl.render(terrain.root(), request, new long[2]);
            material.setBoolean("PrimitiveIdCheck", true);
            ViewCapture[] counted = gl.render(terrain.root(), request, new long[2]);
            int[] bases = TerrainBuilder.triangleBases(terrain.drawn());
            Set<Integer> geometriesSeen = new HashSet<>();
            long terrainSamples = 0;
            for (int k = 0; k < provoked.length; k++) {
                assertArrayEquals(counted[k].triangleIds(), provoked[k].triangleIds(), "view " + k);
                assertArrayEquals(counted[k].depth(), provoked[k].depth(), "view " + k);
                for (int id : provoked[k].triangleIds()) {
                    if (id >= 0) {
                        terrainSamples++;
                        int g = java.util.Arrays.binarySearch(bases, id);
                        geometriesSeen.add(g >= 0 ? g : -g - 2);
                    }
                }
            }
            assertTrue(terrainSamples > provoked[0].triangleIds().length, "terrain seen: " + terrainSamples);
            assertTrue(geometriesSeen.size() > 20, geometriesSeen.size() + " geometries seen");
            SeenTriangles seen = SeenTriangleResolver.resolve(terrain.drawn(), provoked, new EyePlacement(eye, refraction),
                    rangeMetres);
            int simplified = 0;
            for (boolean s : seen.simplified()) {
                simplified += s ? 1 : 0;
            }
            assertTrue(simplified > 0 && simplified < seen.triangles(),
                    simplified + " of " + seen.triangles() + " triangles seen are simplified");
            System.out.printf("%s: %d samples on terrain, %d triangles seen (%d simplified), %d geometries%n", place,
                    terrainSamples, seen.triangles(), simplified, geometriesSeen.size());
            assertEquals(terrain.drawn().size(), bases.length - 1);
        } finally {
            terrain.root().detachAllChildren();
        }
    }
}
