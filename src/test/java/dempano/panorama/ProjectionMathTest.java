package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ProjectionMathTest {
    // The linearizers invert the forward projection (truth: the projection formulas themselves, in double).
    @ParameterizedTest
    @CsvSource({"1", "10", "1000", "50000", "100000", "200000", "300000"})
    void linearizersInvertTheProjection(double eyeDepth) {
        double n = 1, f = 300_000;
        double zb = DepthLinearizer.standardDepthBufferValue(eyeDepth, n, f);
        assertTrue(zb >= 0 && zb <= 1, "window depth " + zb);
        assertEquals(eyeDepth, DepthLinearizer.standardEyeDepth(zb, n, f), eyeDepth * 1e-6);
        double rb = DepthLinearizer.reversedDepthBufferValue(eyeDepth, n);
        assertEquals(eyeDepth, DepthLinearizer.reversedEyeDepth(rb, n), eyeDepth * 1e-12);
    }

    @Test
    void depthPrecisionOfEachModeAt50km() {
        // Quantizing the standard depth to 24 bits loses ~100 m at 50 km (the thesis's trap); a float32
        // reversed depth keeps centimetres. Both shown, not hidden.
        double n = 1, f = 300_000, z = 50_000;
        double zb = DepthLinearizer.standardDepthBufferValue(z, n, f);
        double q = Math.round(zb * ((1 << 24) - 1)) / (double) ((1 << 24) - 1);
        double err24 = Math.abs(DepthLinearizer.standardEyeDepth(q, n, f) - z);
        assertTrue(err24 > 10 && err24 < 300, "24-bit error at 50 km: " + err24 + " m");
        float rb = (float) DepthLinearizer.reversedDepthBufferValue(z, n);
        double err32 = Math.abs(DepthLinearizer.reversedEyeDepth(rb, n) - z);
        assertTrue(err32 < 0.01, "reversed float error at 50 km: " + err32 + " m");
    }

    @Test
    void rangeIsDepthTimesRayLength() {
        // A pixel 22.5° off axis: range = depth / cos 22.5°.
        double t = Math.tan(Math.toRadians(22.5));
        assertEquals(1000 / Math.cos(Math.toRadians(22.5)), DepthLinearizer.rangeFromEyeDepth(1000, t, 0), 1e-9);
    }

    @Test
    void columnsAndRowsFollowTheMetadataConvention() {
        PanoramaGeometry g = PanoramaGeometry.of(20, -30, 30);
        assertEquals(7200, g.widthPx());
        assertEquals(1200, g.heightPx());
        assertEquals(0.025, g.azimuthOfColumn(0), 1e-12);
        assertEquals(45.025, g.azimuthOfColumn(900), 1e-12);
        assertEquals(900.0, g.columnOf(45), 1e-9);
        assertEquals(29.975, g.elevationOfRow(0), 1e-12);
        assertEquals(600.0, g.rowOf(0), 1e-9);
        assertEquals(7199.0, Math.floor(g.columnOf(-0.01)), 0);
    }

    // Stitching: each 45° boundary lies exactly on the shared edge of the two views meeting there.
    @Test
    void viewBoundariesFallExactlyOnAzimuthMultiplesOf45() {
        PanoramaGeometry g = PanoramaGeometry.of(20, -30, 30);
        ViewLayout l = ViewLayout.forPanorama(g, 8, 1);
        for (int k = 0; k < 8; k++) {
            double boundary = 45.0 * k;
            assertEquals(k, l.viewOf(boundary));
            double[] inRight = l.project(k, boundary, 0);
            double[] inLeft = l.project((k + 7) % 8, boundary, 0);
            assertEquals(-0.5, inRight[0], 1e-9, "left edge of view " + k);
            assertEquals(l.widthPx() - 0.5, inLeft[0], 1e-9, "right edge of the view before");
            assertEquals(22.5 + 45 * k, l.axisAzimuthDeg(k), 1e-12);
        }
        // Corners of the panorama fit inside every view.
        for (int k = 0; k < 8; k++) {
            double[] top = l.project(k, 45 * k + 1e-9, 30), bottom = l.project(k, 45 * k + 1e-9, -30);
            assertTrue(top[1] <= l.heightPx() - 1 && bottom[1] >= 0, "elevation range covered");
        }
    }

    @Test
    void pixelRaysRoundTrip() {
        ViewLayout l = ViewLayout.forPanorama(PanoramaGeometry.of(20, -30, 30), 8, 1.5);
        double[] p = l.project(3, 150.3, 12.7);
        assertEquals(p[2], l.xTanOfPixel(p[0]), 1e-12);
        assertEquals(p[3], l.yTanOfPixel(p[1]), 1e-12);
    }
}
