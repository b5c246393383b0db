package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.PanoramaGeometry;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Depth edges and their distance transform against brute force and hand-made distance maps. */
class SilhouetteFieldTest {
    @Test
    void distanceTransformIsTheExactEuclideanOneAndWrapsInAzimuth() {
        int w = 60, h = 25;
        Random rnd = new Random(7);
        boolean[] edge = new boolean[w * h];
        for (int k = 0; k < 12; k++) {
            edge[rnd.nextInt(w * h)] = true;
        }
        edge[3 * w + 1] = true; // next to the seam: its neighbours across it are at distance 1, 2, ...
        float[] dt = SilhouetteField.transform(edge, w, h);
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                double best = Double.POSITIVE_INFINITY;
                for (int i = 0; i < w * h; i++) {
                    if (edge[i]) {
                        int dc = Math.abs(i % w - c);
                        dc = Math.min(dc, w - dc);
                        best = Math.min(best, Math.hypot(dc, i / w - r));
                    }
                }
                assertEquals(Math.min(SilhouetteField.CAP_PX, best), dt[r * w + c], 1e-4, "at " + c + "," + r);
            }
        }
    }

    @Test
    void aNearRidgeInFrontOfFarTerrainIsAnEdgeAndASmallDepthStepIsNot() {
        double ppd = 2; // 720 columns
        int w = 720, h = 20;
        PanoramaGeometry g = new PanoramaGeometry(ppd, 5, h);
        float[] d = new float[w * h];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                // Sky above row 4; far terrain (20 km) rows 4–9; a near ridge (3 km) from row 10 down, except in
                // columns 400+, where the step is from 20 km to 18 km only (10 %: not a visible edge).
                d[r * w + c] = r < 4 ? Float.POSITIVE_INFINITY : r < 10 ? 20_000 : c < 400 ? 3_000 - 10 * r : 18_000 - 10 * r;
            }
        }
        SilhouetteField f = SilhouetteField.of(d, g);
        // Skyline: row 4's top boundary at elevation 5 − 4/2 = 3°; near ridge: row 10's at 0°.
        assertEquals(0, f.distanceDeg(100.25, 3), 1e-6);
        assertEquals(0, f.distanceDeg(100.25, 0), 1e-6);
        assertEquals(0.5, f.distanceDeg(100.25, 0.5), 1e-6);
        assertEquals(1.0, f.distanceDeg(100.25, -1), 1e-6);
        // Columns 400+ (azimuth ≥ 200°): only the skyline; 0° elevation is 3° below it.
        assertEquals(3.0, f.distanceDeg(250.25, 0), 1e-6);
        assertEquals(720 + 400, f.edgePixels());
        assertFalse(f.distanceDeg(10, 40) < SilhouetteField.CAP_PX / ppd, "outside the rows: the cap");
    }
}
