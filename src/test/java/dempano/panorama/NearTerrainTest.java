package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class NearTerrainTest {
    /** 1 px per degree, +30° to −30°: row r's centre is at 29.5 − r degrees. */
    private static final PanoramaGeometry G = PanoramaGeometry.of(1, -30, 30);

    /** Far terrain below the horizontal, sky above; a near wall of the given distance up to elevation topDeg in [fromCol, toCol). */
    private static float[] map(int fromCol, int toCol, float wallMetres, double topDeg) {
        int w = G.widthPx(), h = G.heightPx();
        float[] d = new float[w * h];
        for (int r = 0; r < h; r++) {
            double el = 30 - (r + 0.5);
            Arrays.fill(d, r * w, (r + 1) * w, el < 0 ? 10_000f : Float.POSITIVE_INFINITY);
            for (int c = fromCol; c < toCol; c++) {
                if (el <= topDeg) {
                    d[r * w + (c % w)] = wallMetres;
                }
            }
        }
        return d;
    }

    @Test
    void aWallBesideTheEyeWarnsWithItsFigures() {
        NearTerrain n = NearTerrain.measure(G, map(200, 330, 10, 20), 50);
        assertEquals(130 / 360.0, n.blockedColumnShare(), 1e-9);
        assertEquals(130 * 20 / (360.0 * 30), n.blockedPixelShare(), 1e-9); // rows 0.5°…19.5° of the 30 above
        assertEquals(10, n.nearestMetres(), 0);
        assertEquals(19.5, n.highestElevationDeg(), 1e-9);
        assertEquals(10 * Math.sin(Math.toRadians(19.5)), n.highestAboveEyeMetres(), 1e-6);
        assertEquals(200, n.spanFromAzimuthDeg(), 1e-9);
        assertEquals(330, n.spanToAzimuthDeg(), 1e-9);
        String w = n.warning().orElseThrow();
        for (String s : new String[] {"36 % of the azimuths", "200°–330°", "--snap-to-summit-m", "--clear-view-m", "--offset-m"}) {
            assertTrue(w.contains(s), s + " not in: " + w);
        }
    }

    @Test
    void aRunAcrossNorthIsOneSpan() {
        NearTerrain n = NearTerrain.measure(G, map(340, 400, 10, 20), 50);
        assertEquals(340, n.spanFromAzimuthDeg(), 1e-9);
        assertEquals(40, n.spanToAzimuthDeg(), 1e-9);
        assertEquals(60 / 360.0, n.blockedColumnShare(), 1e-9);
    }

    @Test
    void aLowSlopeAFarWallOrANarrowWallDoNotWarn() {
        // Near terrain only up to +1.5° (a gentle slope beside the eye): hides a sliver of the horizon.
        assertTrue(NearTerrain.measure(G, map(0, 180, 30, 1.5), 50).warning().isEmpty());
        // A wall 80 m away is not near.
        assertTrue(NearTerrain.measure(G, map(0, 180, 80, 20), 50).warning().isEmpty());
        // A rock 20° wide beside the eye: under the 10 % share.
        NearTerrain narrow = NearTerrain.measure(G, map(100, 120, 5, 25), 50);
        assertEquals(20 / 360.0, narrow.blockedColumnShare(), 1e-9);
        assertTrue(narrow.warning().isEmpty());
        // Just at the threshold: 36 columns.
        assertTrue(NearTerrain.measure(G, map(100, 136, 5, 25), 50).warning().isPresent());
    }
}
