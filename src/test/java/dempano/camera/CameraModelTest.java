package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The camera model against OpenCV and closed forms.
 *
 * <p>The tables were computed with OpenCV 5.0.0 (pip package opencv-python-headless) by this script; the
 * {@code undistortPoints} values were checked by re-projecting them (error ≤ 5e-13 px):
 *
 * <pre>
 * import cv2, numpy as np
 * cams = {
 *  "PHONE": (4000, 3000, 3100.0, 3105.0, 2010.3, 1490.8, [-0.12, 0.08, 0.0011, -0.0007, -0.02]),
 *  "WIDE":  (1920, 1080, 1000.0, 1000.0, 959.5, 539.5, [-0.30, 0.10, 0.0005, 0.0003, -0.01]),
 *  "TELE":  (6000, 4000, 12000.0, 12000.0, 2999.5, 1999.5, [0.25, -0.5, 0.0, 0.0, 0.0]),
 * }
 * pts = {
 *  "PHONE": [(0,0,1),(0.5,0.3,1),(-0.6,0.45,1),(0.62,-0.47,1),(-0.1,-0.2,2.5),(0.3,0.01,1.0)],
 *  "WIDE":  [(0.9,0.5,1),(-0.95,-0.52,1),(0.2,-0.4,1),(-0.3,0.1,0.7),(1.0,0.0,1)],
 *  "TELE":  [(0.24,0.16,1),(-0.2,0.1,1),(0.05,-0.12,1)],
 * }
 * upx = {"PHONE": [(0,0),(3999,2999),(2500.25,100.75),(17.5,2900)], "WIDE": [(0,0),(1919,1079),(1500,300)],
 *        "TELE": [(0,0),(5999,3999)]}
 * for name, (w, h, fx, fy, cx, cy, d) in cams.items():
 *     K = np.array([[fx,0,cx],[0,fy,cy],[0,0,1]]); D = np.array(d)
 *     img, _ = cv2.projectPoints(np.array(pts[name], dtype=np.float64).reshape(-1,1,3), np.zeros(3), np.zeros(3), K, D)
 *     print(name, pts[name], img.reshape(-1,2).tolist())
 *     und = cv2.undistortPoints(np.array(upx[name], dtype=np.float64).reshape(-1,1,2), K, D, None, None, None,
 *                               (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 1000, 1e-15))
 *     print(name, upx[name], und.reshape(-1,2).tolist())
 * cv2.getDefaultNewCameraMatrix(np.diag([1000., 1000., 1.]), (640, 480), True)   # principal point (319.5, 239.5)
 * </pre>
 */
class CameraModelTest {
    static final CameraIntrinsics PHONE = new CameraIntrinsics(4000, 3000, 3100, 3105, 2010.3, 1490.8,
            new LensDistortion(-0.12, 0.08, 0.0011, -0.0007, -0.02));
    static final CameraIntrinsics WIDE = new CameraIntrinsics(1920, 1080, 1000, 1000, 959.5, 539.5,
            new LensDistortion(-0.30, 0.10, 0.0005, 0.0003, -0.01));
    static final CameraIntrinsics TELE = new CameraIntrinsics(6000, 4000, 12000, 12000, 2999.5, 1999.5,
            new LensDistortion(0.25, -0.5, 0, 0, 0));
    /** k1 = −0.5 alone: the radial map r·(1 − 0.5·r²) turns over at r = √(2/3) (39.2° off axis). */
    static final CameraIntrinsics BARREL = new CameraIntrinsics(1000, 800, 500, 500, 499.5, 399.5,
            LensDistortion.radial(-0.5, 0, 0));

    /** camera, X, Y, Z (camera frame), px, py: {@code cv2.projectPoints} with zero rotation and translation. */
    static final Object[][] PROJECT_POINTS = {
            {PHONE, 0.0, 0.0, 1.0, 2010.3, 1490.8},
            {PHONE, 0.5, 0.3, 1.0, 3509.376176, 2393.30108848},
            {PHONE, -0.6, 0.45, 1.0, 230.76512578124994, 2828.6080922558594},
            {PHONE, 0.62, -0.47, 1.0, 3835.5352758322883, 105.99229420504685},
            {PHONE, -0.1, -0.2, 2.5, 1886.41592638976, 1242.694326735616},
            {PHONE, 0.3, 0.01, 1.0, 2930.2695582957613, 1521.8293769671327},
            {WIDE, 0.9, 0.5, 1.0, 1664.958856, 931.77492},
            {WIDE, -0.95, -0.52, 1.0, 229.8016447981455, 140.48001094214283},
            {WIDE, 0.2, -0.4, 1.0, 1148.288, 162.14399999999995},
            {WIDE, -0.3, 0.1, 0.7, 555.5292999879787, 674.279348983599},
            {WIDE, 1.0, 0.0, 1.0, 1750.4, 540.0},
            {TELE, 0.24, 0.16, 1.0, 5929.435974399999, 3952.7906495999996},
            {TELE, -0.2, 0.1, 1.0, 572.5, 3213.0},
            {TELE, 0.05, -0.12, 1.0, 3601.949317, 553.6216392000003},
    };

    /** camera, px, py, x, y (normalized undistorted): {@code cv2.undistortPoints} iterated to 1e-15. */
    static final Object[][] UNDISTORT_POINTS = {
            {PHONE, 0.0, 0.0, -0.6840645584904246, -0.5077121044603864},
            {PHONE, 3999.0, 2999.0, 0.6774086840979877, 0.5116697432182208},
            {PHONE, 2500.25, 100.75, 0.16235597552283662, -0.45966736207144904},
            {PHONE, 17.5, 2900.0, -0.6754793296523871, 0.4764578657056276},
            {WIDE, 0.0, 0.0, -1.3410712885714242, -0.7551429407391436},
            {WIDE, 1919.0, 1079.0, 1.3335606331478236, 0.7487459671543452},
            {WIDE, 1500.0, 300.0, 0.6103539748406803, -0.27077161313237097},
            {TELE, 0.0, 0.0, -0.24554367572218155, -0.16368214022553826},
            {TELE, 5999.0, 3999.0, 0.24554367572218155, 0.16368214022553826},
    };

    @Test
    void pixelOfMatchesOpenCvProjectPoints() {
        for (Object[] row : PROJECT_POINTS) {
            CameraIntrinsics cam = (CameraIntrinsics) row[0];
            double[] p = cam.pixelOf((double) row[1], (double) row[2], (double) row[3]);
            assertEquals((double) row[4], p[0], 1e-8, "px of " + row[1] + ", " + row[2] + ", " + row[3]);
            assertEquals((double) row[5], p[1], 1e-8, "py of " + row[1] + ", " + row[2] + ", " + row[3]);
        }
    }

    @Test
    void rayOfInvertsOpenCvProjectPoints() {
        for (Object[] row : PROJECT_POINTS) {
            CameraIntrinsics cam = (CameraIntrinsics) row[0];
            double[] ray = cam.rayOf((double) row[4], (double) row[5]);
            double[] truth = unit((double) row[1], (double) row[2], (double) row[3]);
            assertEquals(1, norm(ray), 1e-15);
            // A ray within 1e-9 px of the pixel is within 1e-9/f rad of the truth; allow 1e-11 rad.
            assertTrue(CameraIntrinsics.angleDeg(ray, truth) < Math.toDegrees(1e-11),
                    "ray of the OpenCV pixel of " + row[1] + ", " + row[2] + ", " + row[3] + ": angle "
                            + CameraIntrinsics.angleDeg(ray, truth) + "°");
        }
    }

    @Test
    void rayOfMatchesOpenCvUndistortPoints() {
        for (Object[] row : UNDISTORT_POINTS) {
            CameraIntrinsics cam = (CameraIntrinsics) row[0];
            double[] ray = cam.rayOf((double) row[1], (double) row[2]);
            assertEquals((double) row[3], ray[0] / ray[2], 1e-12, "x of pixel " + row[1] + ", " + row[2]);
            assertEquals((double) row[4], ray[1] / ray[2], 1e-12, "y of pixel " + row[1] + ", " + row[2]);
        }
    }

    @Test
    void zeroDistortionIsThePinholeClosedForm() {
        CameraIntrinsics cam = new CameraIntrinsics(640, 480, 800, 820, 300.25, 250.75, LensDistortion.NONE);
        double[][] pixels = {{0, 0}, {639, 479}, {300.25, 250.75}, {-1000, 3000}, {17.3, 401.9}};
        for (double[] p : pixels) {
            double[] ray = cam.rayOf(p[0], p[1]);
            double[] truth = unit((p[0] - 300.25) / 800, (p[1] - 250.75) / 820, 1);
            for (int i = 0; i < 3; i++) {
                assertEquals(truth[i], ray[i], 1e-15);
            }
            double[] back = cam.pixelOf(ray[0] * 7, ray[1] * 7, ray[2] * 7);
            assertEquals(p[0], back[0], 1e-9);
            assertEquals(p[1], back[1], 1e-9);
        }
        // 89.9° off axis still has a pixel (far off the image): the pinhole model has no domain limit.
        double t = Math.tan(Math.toRadians(89.9));
        assertEquals(300.25 + 800 * t, cam.pixelOf(t, 0, 1)[0], 1e-6 * t);
    }

    @Test
    void centredPrincipalPointIsOpenCvs() {
        CameraIntrinsics cam = CameraIntrinsics.pinhole(640, 480, 1000);
        assertEquals(319.5, cam.cxPx());
        assertEquals(239.5, cam.cyPx());
        double[] axis = cam.rayOf(319.5, 239.5);
        assertEquals(0, axis[0], 0);
        assertEquals(0, axis[1], 0);
        assertEquals(1, axis[2], 0);
        // Symmetric: the left edge (−0.5) and the right edge (639.5) are equally far off axis.
        assertEquals(-cam.rayOf(-0.5, 239.5)[0], cam.rayOf(639.5, 239.5)[0], 1e-16);
    }

    @Test
    void focalLengthFactoriesFollowTheirDefinitions() {
        // Horizontal field of view across the full width.
        CameraIntrinsics h = CameraIntrinsics.fromHorizontalFov(4000, 3000, 60);
        assertEquals(2000 / Math.tan(Math.toRadians(30)), h.fxPx(), 1e-9);
        assertEquals(60, h.horizontalFovDeg(), 1e-12);
        assertEquals(2 * Math.toDegrees(Math.atan(1500 / h.fxPx())), h.verticalFovDeg(), 1e-12);
        // 35 mm-equivalent, diagonal definition: the diagonal angle equals a 36 × 24 mm frame's.
        CameraIntrinsics e = CameraIntrinsics.fromFocal35mm(4000, 3000, 26);
        assertEquals(2 * Math.toDegrees(Math.atan(Math.hypot(36, 24) / 2 / 26)), e.diagonalFovDeg(), 1e-12);
        assertEquals(26 * 5000 / Math.hypot(36, 24), e.fxPx(), 1e-9);
        // For a 3:2 image the diagonal and the width definitions agree: fx = f35·w/36.
        assertEquals(50 * 6000 / 36.0, CameraIntrinsics.fromFocal35mm(6000, 4000, 50).fxPx(), 1e-9);
        assertEquals(50 * 6000 / 36.0, CameraIntrinsics.fromFocal35mm(4000, 6000, 50).fxPx(), 1e-9);
        // Real focal length and sensor width (the long side): a 4.25 mm lens on a 5.6 mm-wide sensor.
        CameraIntrinsics f = CameraIntrinsics.fromFocalLength(4000, 3000, 4.25, 5.6);
        assertEquals(4.25 * 4000 / 5.6, f.fxPx(), 1e-9);
        assertEquals(f.fxPx(), CameraIntrinsics.fromFocalLength(3000, 4000, 4.25, 5.6).fxPx(), 0, "portrait");
        assertEquals(2 * Math.toDegrees(Math.atan(5.6 / 2 / 4.25)), f.horizontalFovDeg(), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.fromHorizontalFov(100, 100, 180));
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.fromFocal35mm(100, 100, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.fromFocalLength(100, 100, 4, 0));
    }

    @Test
    void roundTripsOverTheWholeImage() {
        for (CameraIntrinsics cam : new CameraIntrinsics[] {PHONE, WIDE, TELE}) {
            double worst = 0;
            for (int j = 0; j <= 30; j++) {
                for (int i = 0; i <= 40; i++) {
                    double px = -0.5 + i * cam.widthPx() / 40.0, py = -0.5 + j * cam.heightPx() / 30.0;
                    double[] ray = cam.rayOf(px, py);
                    assertFalse(Double.isNaN(ray[0]), "no ray at " + px + ", " + py + " of " + cam);
                    double[] back = cam.pixelOf(ray[0], ray[1], ray[2]);
                    worst = Math.max(worst, Math.hypot(back[0] - px, back[1] - py));
                }
            }
            assertTrue(worst < 1e-8, "pixel → ray → pixel off by " + worst + " px for " + cam);
        }
        // Rays → pixels → rays, random rays within 40° of the axis.
        Random rnd = new Random(17);
        for (CameraIntrinsics cam : new CameraIntrinsics[] {PHONE, WIDE}) {
            for (int k = 0; k < 2000; k++) {
                double[] ray = unit(rnd.nextDouble() * 1.6 - 0.8, rnd.nextDouble() * 1.6 - 0.8, 1);
                double[] p = cam.pixelOf(ray[0], ray[1], ray[2]);
                double[] back = cam.rayOf(p[0], p[1]);
                assertTrue(CameraIntrinsics.angleDeg(ray, back) < 1e-9, "ray → pixel → ray for " + cam);
            }
        }
    }

    @Test
    void strongBarrelHasRaysOnlyInsideTheFold() {
        LensDistortion d = BARREL.distortion();
        double rMax = Math.sqrt(2 / 3.0);
        assertEquals(rMax, d.maxValidRadius(), 1e-12);
        double rdMax = rMax * (1 - 0.5 * rMax * rMax); // 0.5443: the largest distorted radius the lens makes
        // A pixel just inside the fold: its ray's radius solves r − 0.5·r³ = rd with r < rMax.
        double rd = 0.99 * rdMax;
        double[] ray = BARREL.rayOf(499.5 + 500 * rd, 399.5);
        double r = ray[0] / ray[2];
        assertEquals(rd, r - 0.5 * r * r * r, 1e-12);
        assertTrue(r > 0 && r < rMax, "radius " + r);
        assertEquals(0, ray[1], 1e-15);
        // Diagonal too.
        double[] diag = BARREL.rayOf(499.5 + 500 * rd / Math.sqrt(2), 399.5 - 500 * rd / Math.sqrt(2));
        double rr = Math.hypot(diag[0], diag[1]) / diag[2];
        assertEquals(rd, rr - 0.5 * rr * rr * rr, 1e-12);
        // A pixel beyond the largest distorted radius has no ray.
        assertTrue(Double.isNaN(BARREL.rayOf(499.5 + 500 * 1.01 * rdMax, 399.5)[0]));
        assertTrue(Double.isNaN(BARREL.rayOf(0, 0)[0]), "the corner is beyond the fold");
        // A ray beyond the fold (r = 0.9 > 0.816) has no pixel, though the polynomial (and cv2.projectPoints)
        // would fold it back to 0.9·(1 − 0.405) = 0.536, onto the image.
        assertTrue(Double.isNaN(BARREL.pixelOf(0.9, 0, 1)[0]));
        assertFalse(Double.isNaN(BARREL.pixelOf(0.8, 0, 1)[0]));
        // Field of view: the horizontal edges are beyond the fold.
        assertTrue(Double.isNaN(BARREL.horizontalFovDeg()));
    }

    @Test
    void validDomainEdgeIsTheFirstTurnOfTheRadialMap() {
        // WIDE: g(s) = 1 − 0.9·s + 0.5·s² − 0.07·s³ (k1 −0.3, k2 0.1, k3 −0.01) first turns at s ≈ 5.
        double r = WIDE.distortion().maxValidRadius();
        double s = r * r;
        assertEquals(0, 1 - 0.9 * s + 0.5 * s * s - 0.07 * s * s * s, 1e-12);
        for (double t = 0; t < s; t += s / 1000) {
            assertTrue(1 - 0.9 * t + 0.5 * t * t - 0.07 * t * t * t > 0);
        }
        assertTrue(WIDE.distortion().isValid(0.99 * r, 0));
        assertFalse(WIDE.distortion().isValid(1.01 * r, 0));
        // k1 < 0 with k2 > 0 large enough never turns: g = 1 − 0.6·s + 0.2·s² has no real root.
        assertEquals(Double.POSITIVE_INFINITY, LensDistortion.radial(-0.2, 0.04, 0).maxValidRadius());
        // A dip that closes again (g < 0 only on a band of s) still limits the domain at its first root.
        LensDistortion dip = LensDistortion.radial(-1, 0.3, 0); // g = 1 − 3s + 1.5s²: roots 0.423, 1.577
        assertEquals((3 - Math.sqrt(3)) / 3, dip.maxValidRadius() * dip.maxValidRadius(), 1e-12);
        assertFalse(dip.isValid(Math.sqrt(2), 0), "beyond the band, g > 0 again, but the map folded on the way");
        // Pincushion never folds.
        assertEquals(Double.POSITIVE_INFINITY, LensDistortion.radial(0.3, 0, 0).maxValidRadius());
        double[] far = TELE.withDistortion(LensDistortion.radial(0.3, 0, 0)).rayOf(1e5, -4e4);
        double[] back = TELE.withDistortion(LensDistortion.radial(0.3, 0, 0)).pixelOf(far[0], far[1], far[2]);
        assertEquals(1e5, back[0], 1e-6);
        assertEquals(-4e4, back[1], 1e-6);
    }

    @Test
    void raysBehindTheCameraAndNaNHaveNoPixel() {
        for (CameraIntrinsics cam : new CameraIntrinsics[] {CameraIntrinsics.pinhole(100, 100, 50), PHONE}) {
            assertTrue(Double.isNaN(cam.pixelOf(0, 0, -1)[0]), "straight behind");
            assertTrue(Double.isNaN(cam.pixelOf(0.1, 0.2, -5)[1]), "behind");
            assertTrue(Double.isNaN(cam.pixelOf(1, 0, 0)[0]), "in the focal plane");
            assertTrue(Double.isNaN(cam.pixelOf(Double.NaN, 0, 1)[0]));
            assertTrue(Double.isNaN(cam.pixelOf(0, 0, Double.POSITIVE_INFINITY)[0]));
            assertTrue(Double.isNaN(cam.rayOf(Double.NaN, 3)[2]));
            assertTrue(Double.isNaN(cam.rayOf(3, Double.POSITIVE_INFINITY)[0]));
        }
        assertFalse(PHONE.contains(Double.NaN, 0));
        assertTrue(PHONE.contains(-0.5, -0.5));
        assertFalse(PHONE.contains(3999.5, 0));
    }

    /** The EXIF orientation pixel map, written from the EXIF standard's descriptions. */
    static double[] displayedPixel(int orientation, double u, double v, int w, int h) {
        return switch (orientation) {
            case 1 -> new double[] {u, v};
            case 2 -> new double[] {w - 1 - u, v};
            case 3 -> new double[] {w - 1 - u, h - 1 - v};
            case 4 -> new double[] {u, h - 1 - v};
            case 5 -> new double[] {v, u};
            case 6 -> new double[] {h - 1 - v, u};
            case 7 -> new double[] {h - 1 - v, w - 1 - u};
            case 8 -> new double[] {v, w - 1 - u};
            default -> throw new IllegalArgumentException();
        };
    }

    @Test
    void aStoredFrameCalibrationTurnsWithTheExifOrientation() {
        // Orientation 6 (turned clockwise) of a pinhole: the stored top-left pixel is displayed top-right.
        CameraIntrinsics stored = new CameraIntrinsics(400, 300, 350, 360, 210.5, 140.25, LensDistortion.NONE);
        CameraIntrinsics six = stored.displayed(6);
        assertEquals(300, six.widthPx());
        assertEquals(400, six.heightPx());
        assertEquals(360, six.fxPx());
        assertEquals(350, six.fyPx());
        assertEquals(299 - 140.25, six.cxPx());
        assertEquals(210.5, six.cyPx());
        // For every orientation, rays at corresponding pixels keep their angles to each other (the displayed
        // camera is the stored one turned or mirrored about its axis), with a distortion that has tangential terms.
        Random rnd = new Random(6);
        for (int o = 1; o <= 8; o++) {
            CameraIntrinsics d = PHONE.displayed(o);
            double[] pp = displayedPixel(o, PHONE.cxPx(), PHONE.cyPx(), 4000, 3000);
            assertEquals(pp[0], d.cxPx(), 1e-9, "orientation " + o);
            assertEquals(pp[1], d.cyPx(), 1e-9, "orientation " + o);
            for (int k = 0; k < 200; k++) {
                double u1 = rnd.nextDouble() * 4000 - 0.5, v1 = rnd.nextDouble() * 3000 - 0.5;
                double u2 = rnd.nextDouble() * 4000 - 0.5, v2 = rnd.nextDouble() * 3000 - 0.5;
                double[] q1 = displayedPixel(o, u1, v1, 4000, 3000), q2 = displayedPixel(o, u2, v2, 4000, 3000);
                double stored12 = CameraIntrinsics.angleDeg(PHONE.rayOf(u1, v1), PHONE.rayOf(u2, v2));
                double shown12 = CameraIntrinsics.angleDeg(d.rayOf(q1[0], q1[1]), d.rayOf(q2[0], q2[1]));
                assertEquals(stored12, shown12, 1e-10, "orientation " + o);
                double axis1 = CameraIntrinsics.angleDeg(PHONE.rayOf(u1, v1), new double[] {0, 0, 1});
                assertEquals(axis1, CameraIntrinsics.angleDeg(d.rayOf(q1[0], q1[1]), new double[] {0, 0, 1}), 1e-10);
            }
        }
        assertThrows(IllegalArgumentException.class, () -> PHONE.displayed(9));
    }

    @Test
    void openCvArraysAreTakenAsTheyAre() {
        CameraIntrinsics c = CameraIntrinsics.fromOpenCv(4000, 3000, new double[] {3100, 0, 2010.3, 0, 3105, 1490.8, 0, 0, 1},
                new double[] {-0.12, 0.08, 0.0011, -0.0007, -0.02});
        assertEquals(PHONE, c);
        assertEquals(0, CameraIntrinsics.fromOpenCv(10, 10, new double[] {5, 0, 4.5, 0, 5, 4.5, 0, 0, 1},
                new double[] {0.1, 0, 0, 0}).distortion().k3());
        assertEquals(PHONE, CameraIntrinsics.fromOpenCv(4000, 3000, new double[] {3100, 0, 2010.3, 0, 3105, 1490.8, 0, 0, 1},
                new double[] {-0.12, 0.08, 0.0011, -0.0007, -0.02, 0, 0, 0}));
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.fromOpenCv(10, 10,
                new double[] {5, 0, 4.5, 0, 5, 4.5, 0, 0, 1}, new double[] {0.1, 0, 0, 0, 0, 0.3, 0, 0}), "k4");
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.fromOpenCv(10, 10,
                new double[] {5, 0.2, 4.5, 0, 5, 4.5, 0, 0, 1}, new double[] {0, 0, 0, 0}), "skew");
    }

    @Test
    void undistortionConvergesUpToTheFold() {
        // Rays in every direction out to 99.9 % of the valid radius: each has a pixel, and that pixel's ray is it.
        // DIP's g = 1 − 3s + 1.5s² is negative only for s in (0.423, 1.577): beyond the band the radial map rises
        // again, so Newton may jump over the fold into it; the domain check must bring it back.
        CameraIntrinsics dip = BARREL.withDistortion(LensDistortion.radial(-1, 0.3, 0));
        // Distorted radius 0.3 has preimages inside (r ≈ 0.33) and beyond the fold: the inside one is the ray.
        double[] inside = dip.rayOf(499.5 + 500 * 0.3, 399.5);
        double ri = inside[0] / inside[2];
        assertEquals(0.3, ri * (1 - ri * ri + 0.3 * ri * ri * ri * ri), 1e-12);
        assertTrue(ri < dip.distortion().maxValidRadius(), "radius " + ri);
        // Distorted radius 0.5 exceeds the most the inner branch makes (≈ 0.41): only the folded branch reaches it.
        assertTrue(Double.isNaN(dip.rayOf(499.5 + 500 * 0.5, 399.5)[0]));
        for (CameraIntrinsics cam : new CameraIntrinsics[] {BARREL, WIDE, dip}) {
            double rMax = cam.distortion().maxValidRadius();
            int checked = 0;
            for (double f : new double[] {0.01, 0.3, 0.7, 0.9, 0.99, 0.999}) {
                for (int k = 0; k < 72; k++) {
                    double a = Math.toRadians(5 * k);
                    double x = f * rMax * Math.cos(a), y = f * rMax * Math.sin(a);
                    if (!cam.distortion().isValid(x, y)) {
                        continue; // tangential terms fold the map slightly inside the radial bound
                    }
                    double[] p = cam.pixelOf(x, y, 1);
                    double[] ray = cam.rayOf(p[0], p[1]);
                    assertTrue(CameraIntrinsics.angleDeg(unit(x, y, 1), ray) < 1e-8,
                            "at " + f + " of the valid radius, " + 5 * k + "°: " + CameraIntrinsics.angleDeg(unit(x, y, 1), ray));
                    checked++;
                }
            }
            assertTrue(checked > 400, checked + " rays checked");
        }
    }

    @Test
    void jacobianMatchesCentralDifferences() {
        LensDistortion d = PHONE.distortion();
        double[] j = new double[4], plus = new double[2], minus = new double[2];
        double h = 1e-6;
        for (double[] p : new double[][] {{0.3, -0.2}, {-0.55, 0.41}, {0.01, 0.6}}) {
            d.jacobian(p[0], p[1], j);
            d.distort(p[0] + h, p[1], plus);
            d.distort(p[0] - h, p[1], minus);
            assertEquals((plus[0] - minus[0]) / (2 * h), j[0], 1e-8);
            assertEquals((plus[1] - minus[1]) / (2 * h), j[2], 1e-8);
            d.distort(p[0], p[1] + h, plus);
            d.distort(p[0], p[1] - h, minus);
            assertEquals((plus[0] - minus[0]) / (2 * h), j[1], 1e-8);
            assertEquals((plus[1] - minus[1]) / (2 * h), j[3], 1e-8);
        }
    }

    @Test
    void constructorRejectsImpossibleCameras() {
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.pinhole(0, 10, 5));
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.pinhole(10, 10, -5));
        assertThrows(IllegalArgumentException.class, () -> CameraIntrinsics.pinhole(10, 10, Double.NaN));
        assertThrows(IllegalArgumentException.class,
                () -> new CameraIntrinsics(10, 10, 5, 5, Double.NaN, 4.5, LensDistortion.NONE));
        assertThrows(IllegalArgumentException.class, () -> new CameraIntrinsics(10, 10, 5, 5, 4.5, 4.5, null));
        assertThrows(IllegalArgumentException.class, () -> new LensDistortion(0, Double.NaN, 0, 0, 0));
    }

    static double[] unit(double x, double y, double z) {
        double n = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / n, y / n, z / n};
    }

    static double norm(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
}
