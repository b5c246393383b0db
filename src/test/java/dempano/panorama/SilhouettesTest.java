package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Silhouette lines from distance columns built analytically: planes seen at grazing angles, ridges, sky. */
class SilhouettesTest {
    static final double EYE_HEIGHT = 50; // metres above a flat plain

    /** Distance to a flat plain seen at an angle below the horizontal (rows 0.05° apart, 20 ppd). */
    static float plain(int row, int horizonRow) {
        double below = (row - horizonRow + 0.5) / 20.0;
        return below <= 0 ? Float.POSITIVE_INFINITY : (float) (EYE_HEIGHT / Math.sin(Math.toRadians(below)));
    }

    static float[] column(int height, java.util.function.IntFunction<Float> d) {
        float[] a = new float[height];
        for (int r = 0; r < height; r++) {
            a[r] = d.apply(r);
        }
        return a;
    }

    static int[] edges(float[] col) {
        return java.util.stream.IntStream.range(0, col.length).filter(r -> Silhouettes.isEdge(col, 1, col.length, 0, r)).toArray();
    }

    @Test
    void aPlainAtGrazingIncidenceHasOnlyItsSkyline() {
        // Row to row the distance grows by up to 3× near the horizon, yet it is one surface.
        float[] col = column(200, r -> plain(r, 40));
        assertTrue(col[41] / col[42] > 1.3, "grazing: " + col[41] / col[42]);
        assertEquals(java.util.List.of(40), java.util.Arrays.stream(edges(col)).boxed().toList());
    }

    @Test
    void aNearRidgeInFrontOfFarMountainsIsOutlinedAtItsTopRow() {
        // Far mountains (30 km, rows 30–59), then a ridge 2 km away from row 60 down, nearer further down.
        float[] col = column(200, r -> r < 30 ? Float.POSITIVE_INFINITY : r < 60 ? 30_000f - 50 * (r - 30) : 2_000f - 5f * (r - 60));
        assertEquals(java.util.List.of(30, 60), java.util.Arrays.stream(edges(col)).boxed().toList());
    }

    @Test
    void smallStepsAreTextureNotEdges() {
        float[] col = column(100, r -> r < 10 ? Float.POSITIVE_INFINITY : (r == 50 ? 10_000f : 10_300f - r));
        for (int r : edges(col)) {
            assertEquals(10, r, "only the skyline");
        }
        assertFalse(Silhouettes.isEdge(col, 1, 100, 0, 0), "row 0 has nothing above it");
    }

    @Test
    void drawingDarkensOnlyEdgePixelsAndKeepsAlpha() {
        float[] d = column(100, r -> plain(r, 40));
        int[] argb = new int[100];
        java.util.Arrays.fill(argb, 0xff80a0c0);
        Silhouettes.draw(argb, d, 1, 100);
        assertEquals(0xff80a0c0, argb[39]);
        assertEquals(0xff000000 | (int) (0x80 * 0.45) << 16 | (int) (0xa0 * 0.45) << 8 | (int) (0xc0 * 0.45), argb[40]);
        assertEquals(0xff80a0c0, argb[41]);
    }
}
