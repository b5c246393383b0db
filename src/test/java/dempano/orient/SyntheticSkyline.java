package dempano.orient;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraView;
import java.util.function.DoubleUnaryOperator;

/** Skylines of an analytic horizon seen by a known camera: the truth the estimator tests compare with. */
final class SyntheticSkyline {
    private SyntheticSkyline() {
    }

    /** A rugged, non-periodic horizon: elevation (degrees) of azimuth (degrees). */
    static double ridge(double azDeg) {
        double a = Math.toRadians(azDeg);
        return 4 + 2.5 * Math.sin(3 * a + 0.3) + 1.6 * Math.sin(7 * a + 1.1) + 0.9 * Math.sin(17 * a + 2.0)
                + 0.5 * Math.sin(41 * a + 0.7) + 0.25 * Math.sin(97 * a + 1.9);
    }

    static HorizonProfile profile(DoubleUnaryOperator horizon, double ppd) {
        int n = (int) Math.round(360 * ppd);
        double[] el = new double[n];
        for (int c = 0; c < n; c++) {
            el[c] = horizon.applyAsDouble((c + 0.5) / ppd);
        }
        return new HorizonProfile(el, ppd);
    }

    /**
     * A panorama's skyline profile of the horizon as the renderer gives it: per column, the top edge of the first
     * row (rows {@code 1/ppd} apart from {@code topDeg} down) whose centre lies below the horizon at the column centre.
     */
    static HorizonProfile renderedProfile(DoubleUnaryOperator horizon, double ppd, double topDeg) {
        int n = (int) Math.round(360 * ppd);
        double[] el = new double[n];
        for (int c = 0; c < n; c++) {
            double e = horizon.applyAsDouble((c + 0.5) / ppd);
            int r = (int) Math.ceil((topDeg - e) * ppd - 0.5);
            el[c] = topDeg - r / ppd;
        }
        return new HorizonProfile(el, ppd);
    }

    /** A camera render's distance map of the horizon: 1000 m at pixel centres below it, +∞ (sky) above. */
    static float[] distanceMap(DoubleUnaryOperator horizon, CameraView view) {
        int w = view.widthPx(), h = view.heightPx();
        float[] d = new float[w * h];
        double[] ray = new double[3];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                d[y * w + x] = above(view, horizon, x, y, ray) ? Float.POSITIVE_INFINITY : 1000f;
            }
        }
        return d;
    }

    /** The fine stage's camera renders of the horizon, through {@link HorizonProfile#ofCamera}. */
    static CameraSkyline camera(DoubleUnaryOperator horizon) {
        return (k, o) -> {
            CameraView view = new CameraView(k, o);
            return HorizonProfile.ofCamera(distanceMap(horizon, view), view, OrientationEstimator.finePixelsPerDegree(k));
        };
    }

    /** The exact skyline row per column for a camera (bisection on the row), weight 1. */
    static Skyline project(DoubleUnaryOperator horizon, int w, int h, CameraOrientation o, double hfovDeg) {
        return project(horizon, CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg), o);
    }

    /** The same for any camera (principal point, distortion), its image size {@code k}'s. */
    static Skyline project(DoubleUnaryOperator horizon, CameraIntrinsics k, CameraOrientation o) {
        int w = k.widthPx(), h = k.heightPx();
        CameraView view = new CameraView(k, o);
        double[] rows = new double[w], weight = new double[w];
        double[] ray = new double[3];
        for (int x = 0; x < w; x++) {
            double lo = -0.5, hi = h - 0.5;
            if (above(view, horizon, x, lo, ray) == above(view, horizon, x, hi, ray)) {
                rows[x] = Double.NaN;
                continue;
            }
            for (int step = 0; step < 60; step++) {
                double mid = (lo + hi) / 2;
                if (above(view, horizon, x, mid, ray)) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            rows[x] = (lo + hi) / 2;
            weight[x] = 1;
        }
        return new Skyline(w, h, rows, weight);
    }

    private static boolean above(CameraView view, DoubleUnaryOperator horizon, int x, double y, double[] ray) {
        view.rayOf(x, y, ray);
        double az = Math.toDegrees(Math.atan2(ray[0], ray[1]));
        double el = Math.toDegrees(Math.atan2(ray[2], Math.hypot(ray[0], ray[1])));
        return el > horizon.applyAsDouble(az);
    }
}
