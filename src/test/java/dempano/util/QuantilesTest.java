package dempano.util;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class QuantilesTest {
    @Test
    void medianOfOddAndEvenCountsLeavesTheInputAlone() {
        double[] odd = {5, 1, 3}, even = {4, 1, 3, 2};
        assertEquals(3, Quantiles.median(odd));
        assertEquals(2.5, Quantiles.median(even));
        assertArrayEquals(new double[] {5, 1, 3}, odd, "not sorted in place");
        assertEquals(Double.NaN, Quantiles.median(new double[0]));
        assertEquals(7, Quantiles.median(new double[] {7}));
        // NaN sorts last: one NaN among three moves the median up, not to NaN.
        assertEquals(2, Quantiles.median(new double[] {Double.NaN, 2, 1}));
    }

    @Test
    void aQuantileOfAnArithmeticSequenceIsItsPosition() {
        // Sorted 0, 1, …, n − 1: the type-7 quantile at q is q·(n − 1) exactly (linear between order statistics).
        for (int n : new int[] {1, 2, 5, 100, 1001}) {
            double[] d = new double[n];
            float[] f = new float[n];
            for (int i = 0; i < n; i++) {
                d[i] = i;
                f[i] = i;
            }
            for (double q : new double[] {0, 0.01, 0.25, 0.5, 0.95, 0.99, 1}) {
                assertEquals(q * (n - 1), Quantiles.ofSorted(d, q), 1e-9, n + " at " + q);
                assertEquals(q * (n - 1), Quantiles.ofSorted(f, q), 1e-9, n + " at " + q);
            }
        }
        assertEquals(Double.NaN, Quantiles.ofSorted(new double[0], 0.5));
        assertEquals(Double.NaN, Quantiles.ofSorted(new float[0], 0.5));
        // The median as a quantile is the median.
        double[] s = {1, 2, 10, 40};
        assertEquals(Quantiles.median(s), Quantiles.ofSorted(s, 0.5), 1e-12);
    }
}
