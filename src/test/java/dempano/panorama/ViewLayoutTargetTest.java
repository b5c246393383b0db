package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraView;
import dempano.camera.LensDistortion;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The views that cover a camera's rays: pure math, no GL. */
class ViewLayoutTargetTest {
    @ParameterizedTest(name = "hfov {2}°, k1 {3}, heading {4}, pitch {5}, roll {6}, principal point +{7} px")
    @CsvSource({
            "600, 400, 50, 0, 0, 0, 0, 0",
            "600, 400, 70, -0.25, 57, -8, 20, 0",
            "400, 300, 40, 0.1, 300, 30, -30, 37",
            "800, 300, 150, 0, 10, -30, 30, 0",
            "300, 500, 100, -0.05, 90, 60, 0, -20"})
    void everyPixelsRayFallsInsideItsViewAtLeastAsFinelySampled(int w, int h, double hfov, double k1, double heading,
                                                                 double pitch, double roll, double shiftPx) {
        CameraIntrinsics base = CameraIntrinsics.fromHorizontalFov(w, h, hfov);
        CameraIntrinsics k = new CameraIntrinsics(w, h, base.fxPx(), base.fyPx(), base.cxPx() + shiftPx, base.cyPx(),
                LensDistortion.radial(k1, 0, 0));
        CameraView cam = new CameraView(k, new CameraOrientation(heading, pitch, roll));
        ViewLayout l = ViewLayout.forTarget(cam, 1);
        assertTrue(!l.ring() && (hfov < 100 ? l.views() == 1 : l.views() > 1), l.toString());
        double[] p = new double[4], ray = new double[3], next = new double[3], q = new double[4];
        double coarsestRatio = 0;
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                cam.rayOf(col, row, ray);
                if (Double.isNaN(ray[0])) {
                    continue;
                }
                int v = l.viewOfRay(ray[0], ray[1], ray[2]);
                l.projectRay(v, ray[0], ray[1], ray[2], p);
                // Inside the frame with the margin the resampler's 4×4 neighbourhood needs (1 pixel and a half).
                assertTrue(p[0] >= 1.5 && p[0] <= l.widthPx() - 2.5 && p[1] >= 1.5 && p[1] <= l.heightPx() - 2.5,
                        col + "," + row + " at " + p[0] + "," + p[1] + " in " + l.widthPx() + "×" + l.heightPx());
                if (col + 1 < w) { // one camera pixel to the right spans at least one view pixel
                    cam.rayOf(col + 1, row, next);
                    if (!Double.isNaN(next[0])) {
                        l.projectRay(v, next[0], next[1], next[2], q);
                        coarsestRatio = Math.max(coarsestRatio, 1 / Math.hypot(q[0] - p[0], q[1] - p[1]));
                    }
                }
            }
        }
        assertTrue(coarsestRatio <= 1 + 1e-6, "a camera pixel spans less than a view pixel: " + coarsestRatio);
        // And not needlessly finer: for a pinhole camera aligned with its single view, the view pixel is the camera's.
        if (k1 == 0 && l.views() == 1 && hfov < 60) {
            assertTrue(coarsestRatio > 0.98, "view oversampled: " + coarsestRatio);
        }
    }

    @Test
    void theRingsAxesProjectAsItsPanoramaFormulas() {
        ViewLayout ring = ViewLayout.forPanorama(PanoramaGeometry.of(20, -30, 30), 8, 1);
        assertTrue(ring.ring());
        Random rnd = new Random(17);
        double[] p = new double[4];
        for (int i = 0; i < 1000; i++) {
            double az = rnd.nextDouble() * 360, el = rnd.nextDouble() * 60 - 30;
            int v = ring.viewOf(az);
            double[] expected = ring.project(v, az, el);
            double a = Math.toRadians(az), e = Math.toRadians(el);
            ring.projectRay(v, Math.cos(e) * Math.sin(a), Math.cos(e) * Math.cos(a), Math.sin(e), p);
            assertEquals(v, ring.viewOfRay(Math.cos(e) * Math.sin(a), Math.cos(e) * Math.cos(a), Math.sin(e)));
            for (int k = 0; k < 4; k++) {
                assertEquals(expected[k], p[k], 1e-9 * Math.max(1, Math.abs(expected[k])));
            }
            double[] sector = ring.azimuthSectorDeg(v);
            assertEquals(v * 45.0, sector[0], 1e-12);
            assertEquals(45.0, sector[1], 1e-12);
        }
    }

    @Test
    void aViewsAzimuthSectorHoldsEveryRayOfItsFrame() {
        CameraView cam = new CameraView(CameraIntrinsics.fromHorizontalFov(300, 200, 60), new CameraOrientation(350, -20, 15));
        ViewLayout l = ViewLayout.forTarget(cam, 1);
        double[] sector = l.azimuthSectorDeg(0);
        double[] ray = new double[3];
        double lowest = 90;
        for (int row = 0; row < 200; row += 7) {
            for (int col = 0; col < 300; col += 7) {
                cam.rayOf(col, row, ray);
                lowest = Math.min(lowest, Math.toDegrees(Math.asin(ray[2])));
                double az = Math.toDegrees(Math.atan2(ray[0], ray[1]));
                double rel = ((az - sector[0]) % 360 + 360) % 360;
                assertTrue(rel <= sector[1], az + "° outside " + sector[0] + "+" + sector[1]);
            }
        }
        assertTrue(sector[1] < 80, "sector " + sector[1]);
        for (int[] corner : new int[][] {{0, 0}, {299, 0}, {0, 199}, {299, 199}}) {
            cam.rayOf(corner[0], corner[1], ray);
            lowest = Math.min(lowest, Math.toDegrees(Math.asin(ray[2])));
        }
        // Looking straight down: every azimuth, and the lowest elevation is the nadir.
        ViewLayout down = ViewLayout.forTarget(new CameraView(CameraIntrinsics.fromHorizontalFov(100, 100, 40),
                new CameraOrientation(0, -90, 0)), 1);
        assertNull(down.azimuthSectorDeg(0));
        assertEquals(-90, down.lowestElevationDeg(), 1e-12);
        // The views' lowest ray: at or below the camera's lowest, by no more than the margin and the grid's step.
        assertTrue(l.lowestElevationDeg() <= lowest && l.lowestElevationDeg() > lowest - 1,
                l.lowestElevationDeg() + " vs " + lowest);
    }

    @Test
    void aFieldOfViewTooWideForPerspectiveViewsIsRefusedWithItsReason() {
        CameraView fisheye = new CameraView(CameraIntrinsics.fromHorizontalFov(400, 400, 170), new CameraOrientation(0, 0, 0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ViewLayout.forTarget(fisheye, 1));
        assertTrue(e.getMessage().contains("too wide"), e.getMessage());
        // The cheap check (a 64-step grid, edges included) refuses it with the same message, and passes a 24 MP photo's
        // 60° view, as the full layout does.
        IllegalArgumentException cheap = assertThrows(IllegalArgumentException.class, () -> ViewLayout.checkCoverable(fisheye, 1));
        assertTrue(cheap.getMessage().startsWith(ViewLayout.TOO_WIDE), cheap.getMessage());
        CameraView photo = new CameraView(CameraIntrinsics.fromHorizontalFov(6000, 4000, 60), new CameraOrientation(10, -5, 3));
        ViewLayout.checkCoverable(photo, 1);
        ViewLayout.forTarget(photo, 1);
    }

    /**
     * Pixels finer than single-precision views resolve (10⁻⁷ rad) are refused with that reason (a 300-pixel view 10⁻⁴°
     * wide drew terrain 4 m off as sky; a focal length of 10³⁰⁰ pixels was said to have no rays at its centre); a
     * 2 000 mm lens behind 4 µm pixels (2·10⁻⁶ rad) and the finest accepted are laid out.
     */
    @Test
    void pixelsTooFineForSinglePrecisionViewsAreRefusedWithTheirReason() {
        CameraOrientation level = new CameraOrientation(0, -40, 0);
        for (CameraIntrinsics k : new CameraIntrinsics[] {CameraIntrinsics.fromHorizontalFov(300, 200, 1e-4),
                CameraIntrinsics.pinhole(300, 200, 1e300), CameraIntrinsics.pinhole(300, 200, 1.01e7)}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ViewLayout.forTarget(new CameraView(k, level), 1));
            assertTrue(e.getMessage().startsWith(ViewLayout.TOO_NARROW), e.getMessage());
        }
        ViewLayout.forTarget(new CameraView(CameraIntrinsics.fromFocalLength(6000, 4000, 2000, 0.004 * 6000), level), 1);
        ViewLayout.forTarget(new CameraView(CameraIntrinsics.pinhole(300, 200, 0.99e7), level), 1);
    }
}
