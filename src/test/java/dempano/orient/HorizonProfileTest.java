package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraView;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** Skyline profiles of camera renders against the analytic horizon they were rendered from. */
class HorizonProfileTest {
    @Test
    void aCameraRendersSkylineFollowsTheHorizonWithinHalfARenderPixel() {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(960, 640, 40);
        CameraView view = new CameraView(k, new CameraOrientation(100, 3, 4));
        double ppd = OrientationEstimator.finePixelsPerDegree(k);
        HorizonProfile p = HorizonProfile.ofCamera(SyntheticSkyline.distanceMap(SyntheticSkyline::ridge, view), view, ppd);
        double[] err = new double[151];
        for (int i = 0; i < err.length; i++) {
            double az = 85 + 30.0 * i / (err.length - 1);
            err[i] = Math.abs(p.elevationDeg(az) - SyntheticSkyline.ridge(az)) * ppd;
        }
        Arrays.sort(err);
        // The top edge of the first terrain pixel is within half a pixel of the boundary along the column; the
        // column is rolled 4°, so the horizon's slope (at most 1.4) adds up to sin 4° × 1.4 of the half pixel,
        // and the linear interpolation between columns a little more.
        assertTrue(err[err.length - 1] < 0.75, "worst " + err[err.length - 1] + " render px");
        assertTrue(err[err.length / 2] < 0.35, "median " + err[err.length / 2] + " render px");
        // The other 320° of the circle were not rendered.
        assertTrue(Double.isNaN(p.elevationDeg(200)) && Double.isNaN(p.elevationDeg(60)) && Double.isNaN(p.elevationDeg(140)));
        assertEquals(Math.round(360 * ppd), p.columns());
    }

    @Test
    void aDistanceMapOfTheWrongSizeIsAClearError() {
        CameraView view = new CameraView(CameraIntrinsics.fromHorizontalFov(40, 30, 40), new CameraOrientation(0, 0, 0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> HorizonProfile.ofCamera(new float[10], view, 10));
        assertTrue(e.getMessage().contains("40 × 30"), e.getMessage());
    }
}
