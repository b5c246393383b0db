package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

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

    /** Space-separated floats; "inf" for sky, "nan" for NaN. */
    static float[] floats(String s) {
        String[] parts = s.trim().split("\\s+");
        float[] out = new float[parts.length];
        for (int i = 0; i < parts.length; i++) {
            out[i] = switch (parts[i]) {
                case "inf" -> INF;
                case "nan" -> Float.NaN;
                default -> Float.parseFloat(parts[i]);
            };
        }
        return out;
    }

    // One row of pixels; the share of far (> 20 km) compared pixels whose relative error exceeds 1 %.
    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
        "30000 40500 50400 66000; 30000 40000 50000 60000; 0.5",   // errors 0, 1.25 %, 0.8 %, 10 %
        "2000 30000;              1000 30000;              0",     // 100 % on a near pixel does not count
        "inf 40000 45000;         30000 40000 40000;       0.5",   // sky read is a mismatch, not a far pixel
        "30000 20001;             20000 20001;             0",     // exactly 20 km is not far
        "2000 1000;               1000 2000;               NaN"})  // nothing far
    void farShareOver1Percent(String got, String ref, double expectedShare) {
        float[] d = floats(got), r = floats(ref);
        assertEquals(expectedShare, DistanceComparison.of(d, r, d.length).farShareOver1Percent(), 1e-12);
    }

    // Eight pixels at incidences 0.1 … 45° with errors of 10, 30, 0, 20, 5, 5, 100, 300 m on 1000 m, then a
    // pixel with an unknown incidence and one read as sky (both left out).
    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
        // lower bounds; pixels per bin; medians; 99th percentiles
        "0 0.5 2 10; 2 2 2 2; 0.02 0.01 0.005 0.2; 0.0298 0.0198 0.005 0.298",
        "1 5;        2 3;     0.0125 0.1;          0.01985 0.296",
        "0 90;       8 0;     0.015 NaN;           0.2860 NaN"})
    void errorsBinnedByIncidence(String lower, String pixels, String medians, String p99s) {
        float[] ref = floats("1000 1000 1000 1000 1000 1000 1000 1000 1000 1000");
        float[] got = floats("1010 1030 1000 1020 1005 1005 1100 1300 1500 inf");
        float[] inc = floats("0.1 0.4 0.5 1.9 2 9.99 10 45 nan 30");
        float[] lowerDeg = floats(lower), n = floats(pixels), med = floats(medians), p99 = floats(p99s);
        double[] bounds = new double[lowerDeg.length];
        for (int k = 0; k < bounds.length; k++) {
            bounds[k] = Double.parseDouble(Float.toString(lowerDeg[k]));
        }
        List<DistanceComparison.IncidenceBin> bins = DistanceComparison.byIncidence(got, ref, inc, bounds);
        assertEquals(bounds.length, bins.size());
        for (int k = 0; k < bins.size(); k++) {
            DistanceComparison.IncidenceBin b = bins.get(k);
            assertEquals(bounds[k], b.fromDeg());
            assertEquals(k + 1 < bounds.length ? bounds[k + 1] : Double.POSITIVE_INFINITY, b.toDeg());
            assertEquals((long) n[k], b.pixels(), "pixels in bin " + k);
            assertEquals(med[k], b.medianRelative(), 1e-6, "median in bin " + k);
            assertEquals(p99[k], b.p99Relative(), 1e-6, "p99 in bin " + k);
        }
    }

    // Truth skylines at rows 1, 2, 0; the tested map is 10 % near on column 0's horizon row, reads sky on
    // column 1's and 2 % far on column 2's; row 2 under the horizon is 10 % far in columns 0 and 2.
    static final float[] TRUTH = {
        INF, INF, 500,
        1000, INF, 400,
        800, 2000, 300,
        600, 1500, 200};
    static final float[] TESTED = {
        INF, INF, 510,
        900, INF, 400,
        800, INF, 330,
        660, 1500, 200};

    @ParameterizedTest
    @CsvSource({
        // rows below skyline, columns, sky, median truth m, median m, median signed, max |relative|
        "0, 3, 1, 1000, 705, -0.04, 0.1",
        "1, 3, 0, 800, 800, 0, 0",
        "2, 2, 0, 450, 495, 0.1, 0.1"})
    void rowsUnderTheHorizon(int k, long columns, long sky, double truthMetres, double metres, double signed, double maxAbs) {
        DistanceComparison.HorizonRow row = DistanceComparison.belowHorizon(TESTED, TRUTH, 3, 3).get(k);
        assertEquals(k, row.rowsBelowSkyline());
        assertEquals(columns, row.columns());
        assertEquals(sky, row.skyMismatchColumns());
        assertEquals(truthMetres, row.medianTruthMetres(), 1e-9);
        assertEquals(metres, row.medianMetres(), 1e-9);
        assertEquals(signed, row.medianSignedRelative(), 1e-7);
        assertEquals(maxAbs, row.maxAbsRelative(), 1e-7);
    }

    @ParameterizedTest
    @CsvSource({
        // tolerance, rows skipped under the skyline, share
        "0.001, 1, 0.6666666666666666", // col 0: 800 ok, 660 not; col 1: 1500 ok; col 2: 400 ok, 330 not, 200 ok
        "0.001, 0, 0.4444444444444444", // plus the three horizon pixels, none within (one read as sky)
        "0.11, 0, 0.8888888888888888",  // everything but the sky read
        "0.001, 4, NaN"})               // no pixel left
    void shareWithinAToleranceUnderTheHorizon(double tolerance, int skip, double share) {
        assertEquals(share, DistanceComparison.shareWithin(TESTED, TRUTH, 3, tolerance, skip), 1e-12);
    }
}
