package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.SharedData;
import dempano.dem.DemDirectory;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import org.junit.jupiter.api.Test;

/**
 * A pixel's ray that passes under a crest between the view samples around it (none of their triangles met) and meets
 * farther terrain beyond is searched on the surface from the terrain seen around it: at Mount Washington (real SRTM3
 * tiles, 10 px/°, −5…5°, 100 km) no pixel is farther than the CPU reference by more than 5 % (581 were, the ray tens
 * of metres inside a ridge 30 km off, most meeting the missing tile's sea behind it), and sky and terrain agree in
 * every pixel.
 */
class HiddenCrestTest {
    @Test
    void noRayPassesThroughACrestToTheTerrainBehind() {
        PanoramaRequest req = PanoramaRequest.at(44.2706, -71.3033).withPixelsPerDegree(10)
                .withElevationRange(new ElevationRange(-5, 5, false)).withColour(false);
        assertNoPixelFartherThanTheReference("Mount Washington 10 px/°", req);
    }

    /**
     * The eye 40 m inside the corner of N44W072 whose three neighbours there are missing (sea level): rays 1.3° down
     * clip the data's edge 52–55 m off by centimetres (a sliver between the view samples, beside triangles whose
     * corners are 69 m off) before the cliff to the sea. The search for them started at 90 % of those corners' distance,
     * past the sliver, and met the sea 16 km off (9 pixels, 300 times too far).
     */
    @Test
    void aRayClippingTheDataEdgeBesideMissingTilesMeetsIt() {
        PanoramaRequest req = PanoramaRequest.at(44.0005, -71.9995).withRangeMetres(20_000).withPixelsPerDegree(5)
                .withElevationRange(new ElevationRange(-10, 5, false)).withColour(false);
        assertNoPixelFartherThanTheReference("tile corner beside missing tiles", req);
    }

    /**
     * An eye 2 m above the ground in a cell whose corners (593, 546 / 443, 469 m) twist by 75 m: the ground was the
     * bilinear height, 18 m under the drawn triangles there, so the eye stood inside the terrain (the CPU reference met
     * it at 0 m in half the panorama, the GL views showed sky through it in 445 676 pixels). It stands on the drawn
     * surface now.
     */
    @Test
    void anEyeInATwistedCellStandsOnTheDrawnSurface() {
        PanoramaRequest req = PanoramaRequest.at(44.02375, -71.2520833).withRangeMetres(30_000).withPixelsPerDegree(4)
                .withElevationRange(new ElevationRange(-30, 20, false)).withColour(false);
        assertNoPixelFartherThanTheReference("twisted cell at 44.02375, -71.2520833", req);
    }

    private static void assertNoPixelFartherThanTheReference(String scene, PanoramaRequest req) {
        DemDirectory dem = new DemDirectory(SharedData.demDir());
        Panorama gl, ref;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem); PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
            gl = r.render(req);
            ref = cpu.render(req);
        }
        int farther = 0, skyMismatch = 0, terrain = 0;
        float[] g = gl.distanceArray(), t = ref.distanceArray();
        for (int i = 0; i < g.length; i++) {
            if (Float.isFinite(g[i]) != Float.isFinite(t[i])) {
                skyMismatch++;
            } else if (Float.isFinite(g[i])) {
                terrain++;
                farther += g[i] > 1.05 * t[i] ? 1 : 0;
            }
        }
        System.out.printf("%s: %d terrain pixels, %d more than 5 %% farther than the reference, %d sky mismatches%n",
                scene, terrain, farther, skyMismatch);
        assertEquals(0, skyMismatch, "pixels sky in one and terrain in the other");
        assertEquals(0, farther, "pixels more than 5 % farther than the reference");
    }
}
