package dempano.panorama;

/**
 * Depth-buffer values back to eye-space depth (metres along the view axis), and eye depth to range
 * along a pixel's ray. Pure math, no GL; all in double precision.
 */
public final class DepthLinearizer {
    private DepthLinearizer() {
    }

    /**
     * Depth-buffer value written by the standard OpenGL projection (clip z in [-1, 1], window depth
     * in [0, 1]) for an eye depth, metres. The forward direction of the projection.
     */
    public static double standardDepthBufferValue(double eyeDepthMetres, double nearMetres, double farMetres) {
        double n = nearMetres, f = farMetres, z = -eyeDepthMetres; // eye space looks down -z
        double zn = ((f + n) / (f - n)) + (2 * f * n) / ((f - n) * z);
        return (zn + 1) / 2;
    }

    /**
     * The thesis's linearization (chapter 3.3): z_e = 2fn / (f + n − (2z_b − 1)(f − n)).
     *
     * @return eye depth, metres (positive in front of the eye)
     */
    public static double standardEyeDepth(double depthBufferValue, double nearMetres, double farMetres) {
        double zn = 2 * depthBufferValue - 1;
        return 2 * farMetres * nearMetres / (farMetres + nearMetres - zn * (farMetres - nearMetres));
    }

    /**
     * What a 24-bit fixed-point depth buffer stores of a window depth in [0, 1]: the nearest of
     * 2²⁴ − 1 steps. Mesa's llvmpipe may keep more bits than the 24 asked for, so the thesis's
     * method applies this explicitly, reproducing a 24-bit GPU on any driver (idempotent where the
     * buffer is 24-bit already).
     */
    public static double quantize24(double depthBufferValue) {
        double steps = (1 << 24) - 1;
        return Math.rint(Math.max(0, Math.min(1, depthBufferValue)) * steps) / steps;
    }

    /** Reversed-Z with an infinite far plane: window depth = n / z_e. */
    public static double reversedDepthBufferValue(double eyeDepthMetres, double nearMetres) {
        return nearMetres / eyeDepthMetres;
    }

    /** Inverse of {@link #reversedDepthBufferValue}: z_e = n / z_b; +∞ for z_b = 0 (cleared: sky). */
    public static double reversedEyeDepth(double depthBufferValue, double nearMetres) {
        return depthBufferValue <= 0 ? Double.POSITIVE_INFINITY : nearMetres / depthBufferValue;
    }

    /**
     * Range along the ray through a point of the image plane at unit distance, given the eye depth:
     * an off-axis ray is longer than its depth by √(1 + x² + y²).
     *
     * @param xTan horizontal image-plane coordinate (tangent of the angle off the axis)
     * @param yTan vertical image-plane coordinate
     */
    public static double rangeFromEyeDepth(double eyeDepthMetres, double xTan, double yTan) {
        return eyeDepthMetres * Math.sqrt(1 + xTan * xTan + yTan * yTan);
    }
}
