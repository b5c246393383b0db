package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileId;
import java.util.List;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;

/** Snap and clear-view corrections against terrain whose summit and required lift are known in closed form. */
class ViewpointAdjustmentTest {
    /** SRTM3 spacing: 1200 intervals per degree. */
    private static final int N = 1201;
    private static final double R = Ellipsoid.MEAN_RADIUS_METRES;
    private static final double LAT = 46.5, LON = 8.5; // a grid sample: row 600, column 600
    private static final double M_PER_DEG_LAT = R * Math.PI / 180;
    private static final double M_PER_DEG_LON = M_PER_DEG_LAT * Math.cos(Math.toRadians(LAT));

    private static Mosaic mosaic(DoubleBinaryOperator f) {
        float[] h = new float[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                h[r * N + c] = (float) f.applyAsDouble(47 - r / (N - 1.0), 8 + c / (N - 1.0));
            }
        }
        return Mosaic.around(new InMemoryDem("synthetic", List.of(HgtTile.of(new TileId(46, 8), N, h, "synthetic"))),
                LAT, LON, 5000, MissingTilePolicy.ERROR);
    }

    /** A cone with its apex (3000 m) on the sample at (LAT, LON), falling 0.4 m per metre. */
    static double cone(double lat, double lon) {
        double d = Math.hypot((lat - LAT) * M_PER_DEG_LAT, (lon - LON) * M_PER_DEG_LON);
        return Math.max(500, 3000 - 0.4 * d);
    }

    @Test
    void snapFindsTheConesApexFromBesideIt() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        double north = 30, east = 20; // metres from the apex
        double lat = LAT + north / M_PER_DEG_LAT, lon = LON + east / M_PER_DEG_LON;
        ViewpointAdjustment.GridPoint top = ViewpointAdjustment.highestWithin(m, lat, lon, 100);
        assertEquals(LAT, top.latDeg(), 1e-9);
        assertEquals(LON, top.lonDeg(), 1e-9);
        assertEquals(3000, top.heightMetres(), 1e-3);
        assertEquals(Math.hypot(north, east), top.distanceMetres(), 0.01);
    }

    @Test
    void snapWithinASmallRadiusStopsAtTheHighestSampleInsideIt() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        // 100 m east of the apex; the samples 63.8 m apart east-west: within 50 m lies the sample 1 column nearer
        // the apex (36.2 m away), and nothing higher.
        double dx = M_PER_DEG_LON / 1200;
        double lon = LON + 100 / M_PER_DEG_LON;
        ViewpointAdjustment.GridPoint top = ViewpointAdjustment.highestWithin(m, LAT, lon, 50);
        assertEquals(LON + 1 / 1200.0, top.lonDeg(), 1e-9);
        assertEquals(LAT, top.latDeg(), 1e-9);
        assertEquals(3000 - 0.4 * dx, top.heightMetres(), 1e-3);
        assertEquals(100 - dx, top.distanceMetres(), 0.01);
    }

    @Test
    void onTheTopTheSnapStaysPut() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        ViewpointAdjustment.GridPoint top = ViewpointAdjustment.highestWithin(m, LAT, LON, 200);
        assertEquals(0, top.distanceMetres());
        assertEquals(LON, top.lonDeg(), 0);
        ViewpointAdjustment.Adjusted a = ViewpointAdjustment.apply(m, Viewpoint.onDem(m, LAT, LON, 0, 2), 200,
                Double.NaN, Refraction.STANDARD);
        assertEquals(3002, a.eye().eyeAltitudeMetres(), 1e-3);
        assertEquals(0, a.move().shiftMetres());
    }

    @Test
    void clearViewLiftOnAPlaneSlopeIsComputableByHand() {
        double g = 0.2; // rising 0.2 m per metre eastward
        Mosaic m = mosaic((lat, lon) -> 1000 + g * (lon - 8) * M_PER_DEG_LON);
        double dx = M_PER_DEG_LON / 1200;
        double radius = 5 * dx + 1; // the sample 5 columns east is the highest inside
        double ground = 1000 + g * (LON - 8) * M_PER_DEG_LON;
        double d = 5 * dx, k = 0.13;
        double expectedEye = ground + g * d - (1 - k) * d * d / (2 * R) + 0.5;
        assertEquals(expectedEye, ViewpointAdjustment.clearViewEyeAltitudeMetres(m, LAT, LON, radius, new Refraction(k)),
                1e-3);
        ViewpointAdjustment.Adjusted a = ViewpointAdjustment.apply(m, Viewpoint.onDem(m, LAT, LON, 0, 2), Double.NaN,
                radius, new Refraction(k));
        assertEquals(expectedEye, a.eye().eyeAltitudeMetres(), 1e-3);
        assertEquals(expectedEye - ground - 2, a.move().liftMetres(), 1e-3);
        assertEquals(expectedEye - ground - 2, a.eye().offsetMetres(), 1e-3); // the lift is an offset on the DEM
        assertEquals(LON, a.eye().lonDeg(), 0);
        assertEquals(0, a.move().shiftMetres());
        assertTrue(a.move().describe().contains("--clear-view-m"), a.move().describe());
    }

    @Test
    void anEyeAlreadyClearIsNotLowered() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        ViewpointAdjustment.Adjusted a = ViewpointAdjustment.apply(m, Viewpoint.onDem(m, LAT, LON, 0, 2), Double.NaN,
                300, Refraction.STANDARD);
        assertEquals(0, a.move().liftMetres());
        assertEquals(3002, a.eye().eyeAltitudeMetres(), 1e-3);
    }

    @Test
    void snapThenClearView() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        double lon = LON + 40 / M_PER_DEG_LON;
        Viewpoint beside = Viewpoint.onDem(m, LAT, lon, 0, 2);
        assertEquals(2984, beside.groundElevationMetres(), 0.5);
        // Clear view alone lifts the eye over the apex 40 m away: 3000 − drop + 0.5.
        ViewpointAdjustment.Adjusted lifted = ViewpointAdjustment.apply(m, beside, Double.NaN, 100, Refraction.NONE);
        assertEquals(3000 - 40.0 * 40 / (2 * R) + 0.5, lifted.eye().eyeAltitudeMetres(), 0.01);
        // With the snap first the eye is on the apex, 2 m above it, and needs no lift.
        ViewpointAdjustment.Adjusted both = ViewpointAdjustment.apply(m, beside, 100, 100, Refraction.NONE);
        assertEquals(LON, both.eye().lonDeg(), 1e-9);
        assertEquals(3002, both.eye().eyeAltitudeMetres(), 1e-3);
        assertEquals(40, both.move().shiftMetres(), 0.01);
        assertEquals(0, both.move().liftMetres());
        assertEquals(beside.eyeAltitudeMetres(), both.move().fromEyeAltitudeMetres(), 1e-9);
        assertNull(ViewpointAdjustment.apply(m, beside, Double.NaN, Double.NaN, Refraction.NONE).move());
    }

    @Test
    void badRadiiAreClearErrors() {
        Mosaic m = mosaic(ViewpointAdjustmentTest::cone);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ViewpointAdjustment.highestWithin(m, LAT, LON, -5));
        assertTrue(e.getMessage().contains("--snap-to-summit-m"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> ViewpointAdjustment.clearViewEyeAltitudeMetres(m, LAT, LON, 0, Refraction.NONE));
        assertTrue(e.getMessage().contains("--clear-view-m"), e.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> dempano.PanoramaRequest.at(LAT, LON).withSnapToSummitMetres(Double.POSITIVE_INFINITY));
    }
}
