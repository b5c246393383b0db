package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.PanoramaGeometry;
import org.junit.jupiter.api.Test;

/** The camera and the panorama as target images: round trips, and agreement where both see the same direction. */
class TargetImageTest {
    static final PanoramaGeometry GEOMETRY = PanoramaGeometry.of(10, -30, 30);
    static final PanoramaTarget PANORAMA = new PanoramaTarget(GEOMETRY);

    static double[] enu(double azimuthDeg, double elevationDeg) {
        double a = Math.toRadians(azimuthDeg), e = Math.toRadians(elevationDeg);
        return new double[] {Math.sin(a) * Math.cos(e), Math.cos(a) * Math.cos(e), Math.sin(e)};
    }

    static void assertSameDirection(double[] expected, double[] actual, double toleranceDeg, String what) {
        double angle = CameraIntrinsics.angleDeg(expected, actual);
        assertTrue(angle <= toleranceDeg, what + ": " + angle + "° apart");
    }

    @Test
    void panoramaPixelCentresAreTheGeometrysColumnAndRowCentres() {
        assertEquals(3600, PANORAMA.widthPx());
        assertEquals(600, PANORAMA.heightPx());
        for (int c : new int[] {0, 1, 899, 1800, 3599}) {
            for (int r : new int[] {0, 299, 599}) {
                double[] ray = PANORAMA.rayOf(c, r);
                assertSameDirection(enu(GEOMETRY.azimuthOfColumn(c), GEOMETRY.elevationOfRow(r)), ray, 1e-12,
                        "pixel " + c + ", " + r);
                double[] p = PANORAMA.pixelOf(ray[0], ray[1], ray[2]);
                assertEquals(c, p[0], 1e-8);
                assertEquals(r, p[1], 1e-8);
                // The geometry's own fractional column/row (centre at integer + 0.5) is ours + 0.5.
                assertEquals(GEOMETRY.columnOf(GEOMETRY.azimuthOfColumn(c)) - 0.5, p[0], 1e-9);
                assertEquals(GEOMETRY.rowOf(GEOMETRY.elevationOfRow(r)) - 0.5, p[1], 1e-9);
            }
        }
        // North is the left edge of column 0 and wraps: just west of north is at the right edge.
        assertEquals(-0.5, PANORAMA.pixelOf(0, 1, 0)[0], 1e-12);
        double[] westOfNorth = PANORAMA.pixelOf(-1e-6, 1, 0);
        assertEquals(3599.5, westOfNorth[0], 1e-3);
        assertTrue(westOfNorth[0] < 3599.5 && PANORAMA.contains(westOfNorth[0], westOfNorth[1]));
        // Elevations off the covered range are off the image; the zero vector has no pixel.
        assertFalse(PANORAMA.contains(PANORAMA.pixelOf(0, 1, 1)[0], PANORAMA.pixelOf(0, 1, 1)[1]), "45° up");
        assertTrue(Double.isNaN(PANORAMA.pixelOf(0, 0, 0)[0]));
    }

    @Test
    void cameraRoundTripsThroughEnu() {
        CameraView view = new CameraView(CameraModelTest.PHONE, new CameraOrientation(211.5, 7.25, -3.5));
        double worst = 0;
        for (int j = 0; j <= 20; j++) {
            for (int i = 0; i <= 20; i++) {
                double px = -0.5 + i * 200, py = -0.5 + j * 150;
                double[] ray = view.rayOf(px, py);
                assertEquals(1, CameraModelTest.norm(ray), 1e-14);
                double[] back = view.pixelOf(ray[0] * 1000, ray[1] * 1000, ray[2] * 1000);
                worst = Math.max(worst, Math.hypot(back[0] - px, back[1] - py));
            }
        }
        assertTrue(worst < 1e-8, "pixel → ENU → pixel off by " + worst + " px");
        // The direction opposite the optical axis has no pixel.
        double[] axis = view.rayOf(CameraModelTest.PHONE.cxPx(), CameraModelTest.PHONE.cyPx());
        assertTrue(Double.isNaN(view.pixelOf(-axis[0], -axis[1], -axis[2])[0]));
        // ... while the panorama has one for it.
        assertFalse(Double.isNaN(PANORAMA.pixelOf(-axis[0], -axis[1], -axis[2])[0]));
    }

    @Test
    void cameraAndPanoramaAgreeWhereTheCameraLooks() {
        // A distortion-free camera: its principal point sees azimuth = heading, elevation = pitch whatever the roll.
        for (double roll : new double[] {0, 12, -90}) {
            CameraView view = new CameraView(CameraIntrinsics.pinhole(1200, 800, 1100), new CameraOrientation(37, 5, roll));
            double[] ray = view.rayOf(599.5, 399.5);
            assertSameDirection(enu(37, 5), ray, 1e-12, "principal point, roll " + roll);
            double[] p = PANORAMA.pixelOf(ray[0], ray[1], ray[2]);
            assertEquals(GEOMETRY.columnOf(37) - 0.5, p[0], 1e-9);
            assertEquals(GEOMETRY.rowOf(5) - 0.5, p[1], 1e-9);
            assertSameDirection(ray, PANORAMA.rayOf(p[0], p[1]), 1e-12, "panorama ray at the same pixel");
        }
        // Level camera facing north: the pixel f·tan 20° right of the centre sees azimuth 20°, elevation 0; the pixel
        // f·tan 10° above the centre sees azimuth 0, elevation 10°.
        CameraView level = new CameraView(CameraIntrinsics.pinhole(2001, 1001, 1000), new CameraOrientation(0, 0, 0));
        double[] right = level.rayOf(1000 + 1000 * Math.tan(Math.toRadians(20)), 500);
        double[] pr = PANORAMA.pixelOf(right[0], right[1], right[2]);
        assertEquals(20 * 10 - 0.5, pr[0], 1e-9);
        assertEquals(30 * 10 - 0.5, pr[1], 1e-9);
        double[] up = level.rayOf(1000, 500 - 1000 * Math.tan(Math.toRadians(10)));
        double[] pu = PANORAMA.pixelOf(up[0], up[1], up[2]);
        assertEquals(-0.5, pu[0], 1e-9);
        assertEquals((30 - 10) * 10 - 0.5, pu[1], 1e-9);
        // A panorama pixel's ray seen by a camera pointing at it lands on the camera's principal point.
        double[] pano = PANORAMA.rayOf(1234, 321);
        double az = GEOMETRY.azimuthOfColumn(1234), el = GEOMETRY.elevationOfRow(321);
        CameraView aimed = new CameraView(CameraModelTest.WIDE, new CameraOrientation(az, el, 33));
        double[] pc = aimed.pixelOf(pano[0], pano[1], pano[2]);
        assertEquals(CameraModelTest.WIDE.cxPx(), pc[0], 1e-8);
        assertEquals(CameraModelTest.WIDE.cyPx(), pc[1], 1e-8);
    }
}
