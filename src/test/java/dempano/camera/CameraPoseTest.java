package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileSelection;
import dempano.geo.Viewpoint;
import org.junit.jupiter.api.Test;

/** Camera orientation against closed-form cases and an independent axis-angle composition; pose to viewpoint. */
class CameraPoseTest {
    static final double[] EAST = {1, 0, 0}, NORTH = {0, 1, 0}, UP = {0, 0, 1};

    /** Camera axis j (0 = x right, 1 = y down, 2 = z forward) in ENU. */
    static double[] axis(CameraOrientation o, int j) {
        double[] m = o.cameraToEnu();
        return new double[] {m[j], m[3 + j], m[6 + j]};
    }

    static void assertVector(double[] expected, double[] actual, String what) {
        for (int i = 0; i < 3; i++) {
            assertEquals(expected[i], actual[i], 1e-15, what + " component " + i);
        }
    }

    static double[] neg(double[] v) {
        return new double[] {-v[0], -v[1], -v[2]};
    }

    @Test
    void closedFormCases() {
        // Level, facing north: right = east, down = down, forward = north.
        CameraOrientation north = new CameraOrientation(0, 0, 0);
        assertVector(EAST, axis(north, 0), "right");
        assertVector(neg(UP), axis(north, 1), "down");
        assertVector(NORTH, axis(north, 2), "forward");
        // Heading 90: the optical axis points east; right points south.
        CameraOrientation east = new CameraOrientation(90, 0, 0);
        assertVector(EAST, axis(east, 2), "forward");
        assertVector(neg(NORTH), axis(east, 0), "right");
        assertVector(neg(UP), axis(east, 1), "down");
        // Pitch 90: the optical axis points up; the image's top points backward (south for heading 0).
        CameraOrientation zenith = new CameraOrientation(0, 90, 0);
        assertVector(UP, axis(zenith, 2), "forward");
        assertVector(EAST, axis(zenith, 0), "right");
        assertVector(NORTH, axis(zenith, 1), "down = −(image up) = north");
        // Pitch −90 at heading 90: straight down, the image's top points east (ahead).
        CameraOrientation nadir = new CameraOrientation(90, -90, 0);
        assertVector(neg(UP), axis(nadir, 2), "forward");
        assertVector(neg(EAST), axis(nadir, 1), "down = west");
        // Roll 90, facing north: the camera turned clockwise (from behind) onto its right side: its right points
        // down and the image's top points east.
        CameraOrientation roll = new CameraOrientation(0, 0, 90);
        assertVector(NORTH, axis(roll, 2), "forward");
        assertVector(neg(UP), axis(roll, 0), "right");
        assertVector(neg(EAST), axis(roll, 1), "down = west");
        // Heading 30, pitch 0: forward (sin 30, cos 30, 0).
        double s = Math.sin(Math.toRadians(30)), c = Math.cos(Math.toRadians(30));
        assertVector(new double[] {s, c, 0}, axis(new CameraOrientation(30, 0, 0), 2), "forward");
        // Pitch 30 facing north: forward (0, cos 30, sin 30).
        assertVector(new double[] {0, c, s}, axis(new CameraOrientation(0, 30, 0), 2), "forward");
    }

    /** Right-handed rotation of v about a unit axis by an angle (Rodrigues). */
    static double[] rotate(double[] v, double[] k, double deg) {
        double a = Math.toRadians(deg), c = Math.cos(a), s = Math.sin(a);
        double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
        double[] kxv = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
        double[] out = new double[3];
        for (int i = 0; i < 3; i++) {
            out[i] = v[i] * c + kxv[i] * s + k[i] * kv * (1 - c);
        }
        return out;
    }

    @Test
    void compositionIsHeadingThenPitchThenRoll() {
        // Independent construction: the level north-facing camera's axes, rotated extrinsically by roll about
        // north (right-handed = clockwise seen from behind), pitch about east (right-handed = nose up), then
        // heading about down (right-handed about down = clockwise seen from above). Extrinsic roll → pitch →
        // heading is intrinsic heading → pitch → roll.
        double[][] start = {EAST, neg(UP), NORTH};
        double[] down = neg(UP);
        for (double heading : new double[] {0, 37, 90, 200, 333}) {
            for (double pitch : new double[] {-90, -45, -3, 0, 12, 60, 90}) {
                for (double roll : new double[] {-170, -30, 0, 8, 90, 180}) {
                    CameraOrientation o = new CameraOrientation(heading, pitch, roll);
                    for (int j = 0; j < 3; j++) {
                        double[] v = rotate(start[j], NORTH, roll);
                        v = rotate(v, EAST, pitch);
                        v = rotate(v, down, heading);
                        double[] a = axis(o, j);
                        for (int i = 0; i < 3; i++) {
                            assertEquals(v[i], a[i], 1e-15, o + " axis " + j);
                        }
                    }
                }
            }
        }
    }

    @Test
    void rotationIsOrthonormalAndItsTransposeIsTheInverse() {
        CameraOrientation o = new CameraOrientation(123.4, -17.8, 5.6);
        double[] m = o.cameraToEnu();
        double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
                + m[2] * (m[3] * m[7] - m[4] * m[6]);
        assertEquals(1, det, 1e-15);
        double[] enu = new double[3], cam = new double[3];
        CameraOrientation.cameraToEnu(m, 0.3, -0.2, 0.9, enu);
        CameraOrientation.enuToCamera(m, enu[0], enu[1], enu[2], cam);
        assertEquals(0.3, cam[0], 1e-15);
        assertEquals(-0.2, cam[1], 1e-15);
        assertEquals(0.9, cam[2], 1e-15);
    }

    @Test
    void anglesComeBackFromTheRotation() {
        for (double heading : new double[] {0, 1, 90, 181, 359.5}) {
            for (double pitch : new double[] {-89, -10, 0, 45, 89}) {
                for (double roll : new double[] {-179, -90, 0, 15, 180}) {
                    CameraOrientation o = new CameraOrientation(heading, pitch, roll);
                    CameraOrientation back = CameraOrientation.fromCameraToEnu(o.cameraToEnu());
                    assertEquals(heading, back.headingDeg(), 1e-9, o.toString());
                    assertEquals(pitch, back.pitchDeg(), 1e-9, o.toString());
                    assertEquals(roll, back.rollDeg(), 1e-9, o.toString());
                }
            }
        }
        // Gimbal lock: straight up with heading 40 and roll 20 turns the image like heading 60 and roll 0
        // (both rotate about the vertical; the image's top points away from the heading).
        CameraOrientation locked = CameraOrientation.fromCameraToEnu(new CameraOrientation(40, 90, 20).cameraToEnu());
        assertEquals(90, locked.pitchDeg(), 1e-6);
        double[] a = new CameraOrientation(40, 90, 20).cameraToEnu(), b = locked.cameraToEnu();
        for (int i = 0; i < 9; i++) {
            assertEquals(a[i], b[i], 1e-7);
        }
    }

    @Test
    void positiveRollTurnsTheHorizonCounterClockwiseInThePhoto() {
        // Level camera facing north, rolled 10° clockwise: a horizon point 20° right of the axis appears above
        // the centre row, by tan(20°)·sin(10°)·f to first order... exactly: its camera coordinates are the ENU
        // direction (sin 20°, cos 20°, 0) in the rolled frame.
        CameraView view = new CameraView(CameraIntrinsics.pinhole(1001, 801, 1000), new CameraOrientation(0, 0, 10));
        double[] p = view.pixelOf(Math.sin(Math.toRadians(20)), Math.cos(Math.toRadians(20)), 0);
        double x = Math.tan(Math.toRadians(20));
        assertEquals(500 + 1000 * x * Math.cos(Math.toRadians(10)), p[0], 1e-9);
        assertEquals(400 - 1000 * x * Math.sin(Math.toRadians(10)), p[1], 1e-9, "above the centre row");
        // The horizon line through the centre rises to the right at 10°: counter-clockwise in the image.
        assertEquals(10, Math.toDegrees(Math.atan2(400 - p[1], p[0] - 500)), 1e-9);
    }

    @Test
    void orientationRejectsImpossibleAngles() {
        assertThrows(IllegalArgumentException.class, () -> new CameraOrientation(0, 90.5, 0));
        assertThrows(IllegalArgumentException.class, () -> new CameraOrientation(Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new CameraOrientation(0, 0, Double.POSITIVE_INFINITY));
    }

    @Test
    void poseStandsOnTheDemOrAtItsAltitudeLikeAViewpoint() {
        // A plane DEM at 500 m (1° tile at 46 N, 8 E).
        Mosaic mosaic = Mosaic.of(Synthetic.dem((lat, lon) -> 500, 46, 8, 1, 1),
                TileSelection.around(46.5, 8.5, 5000), MissingTilePolicy.AUTO);
        CameraOrientation level = new CameraOrientation(0, 0, 0);
        Viewpoint onDem = new CameraPose(46.5, 8.5, 3, Double.NaN, 1.5, level).viewpoint(mosaic);
        assertEquals(503, onDem.standingAltitudeMetres(), 1e-9);
        assertEquals(504.5, onDem.eyeAltitudeMetres(), 1e-9);
        Viewpoint absolute = new CameraPose(46.5, 8.5, 0, 812, 0, level).viewpoint(mosaic);
        assertEquals(812, absolute.eyeAltitudeMetres(), 1e-9);
        assertTrue(Double.isNaN(absolute.offsetMetres()));
        assertThrows(IllegalArgumentException.class,
                () -> new CameraPose(46.5, 8.5, 0, 300, 0, level).viewpoint(mosaic), "below the DEM surface");
        assertThrows(IllegalArgumentException.class, () -> new CameraPose(91, 0, 0, Double.NaN, 0, level));
        assertThrows(IllegalArgumentException.class, () -> new CameraPose(46, 8, 0, Double.NaN, -1, level));
    }
}
