package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class DistanceComparisonTest {
    static final float INF = Float.POSITIVE_INFINITY;

    @Test
    void relativeErrorsSkyMismatchAndSkylineOnA3x3Map() {
        // Columns: reference skyline rows 1, 0, 3 (all sky); the test map is one row lower in column 0
        // and sees terrain in the reference's sky in column 2.
        float[] ref = {
            INF, 100, INF,
            100, 200, INF,
            400, 300, INF};
        float[] got = {
            INF, 101, INF,
            INF, 200, INF,
            440, 300, 50};
        DistanceComparison c = DistanceComparison.of(got, ref, 3);
        assertEquals(4, c.comparedPixels()); // (1,0) (1,1) (0,2) (1,2)
        // Relative errors: 0.01, 0, 0.1, 0 → sorted 0, 0, 0.01, 0.1.
        assertEquals(0.005, c.medianRelative(), 1e-7);
        assertEquals(0.1, c.maxRelative(), 1e-7);
        assertEquals(0.01 + 0.95 * 3 % 1 * (0.1 - 0.01), c.p95Relative(), 1e-6);
        assertEquals(0.25, c.shareOver5Percent());
        assertEquals(2, c.skyMismatchPixels());
        // Skylines: got 2, 0, 2 vs ref 1, 0, 3 → |Δ| 1, 0, 1.
        assertEquals(2 / 3.0, c.skylineMeanAbsPx(), 1e-12);
        assertEquals(1, c.skylineMaxAbsPx());
        assertEquals(2 / 3.0, c.skylineColumnsOff(), 1e-12);
    }

    @Test
    void identicalMapsHaveNoError() {
        float[] a = {INF, 5, 7, 9};
        DistanceComparison c = DistanceComparison.of(a, a.clone(), 2);
        assertEquals(0, c.maxRelative());
        assertEquals(0, c.skylineMeanAbsPx());
        assertEquals(0, c.skyMismatchPixels());
    }

    @Test
    void allSkyGivesNaNStatistics() {
        float[] a = {INF, INF};
        DistanceComparison c = DistanceComparison.of(a, a.clone(), 2);
        assertEquals(0, c.comparedPixels());
        assertEquals(Double.NaN, c.medianRelative());
    }
}
