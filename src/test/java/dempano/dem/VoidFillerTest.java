package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class VoidFillerTest {
    private static float[] plane(int n) {
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                h[r * n + c] = 100 + 2 * r + 5 * c;
            }
        }
        return h;
    }

    @Test
    void singleVoidInAPlaneIsExact() {
        // Opposite directions are symmetric, so IDW reproduces a plane exactly at a lone void.
        int n = 21;
        float[] h = plane(n);
        float truth = h[10 * n + 10];
        h[10 * n + 10] = Float.NaN;
        VoidReport rep = VoidFiller.fill(h, n);
        assertEquals(new VoidReport(1, 1, 1, 1), rep);
        assertEquals(truth, h[10 * n + 10], 1e-4);
    }

    @Test
    void voidOnTheEdgeIsFilled() {
        int n = 11;
        float[] h = plane(n);
        h[0] = Float.NaN;
        h[n * n - 1] = Float.NaN;
        VoidReport rep = VoidFiller.fill(h, n);
        assertEquals(2, rep.regions());
        assertFalse(Float.isNaN(h[0]) || Float.isNaN(h[n * n - 1]));
        assertTrue(h[0] >= 100 && h[0] <= 107, "corner " + h[0]);
    }

    @Test
    void voidSeeingNoValidSampleOnItsLinesIsFilledByALaterPass() {
        // Only one valid sample, off every line through (0, 3): (1, 0).
        int n = 5;
        float[] h = new float[n * n];
        java.util.Arrays.fill(h, Float.NaN);
        h[1 * n + 0] = 42;
        VoidFiller.fill(h, n);
        for (float v : h) {
            assertEquals(42, v, 1e-5);
        }
    }

    @Test
    void entirelyVoidBecomesSeaLevel() {
        float[] h = new float[9];
        java.util.Arrays.fill(h, Float.NaN);
        VoidReport rep = VoidFiller.fill(h, 3);
        assertEquals(9, rep.voidCells());
        for (float v : h) {
            assertEquals(0, v, 0);
        }
    }
}
