package dempano.camera;

/**
 * Brown–Conrady lens distortion with exactly OpenCV's five coefficients and formula (the {@code distCoeffs}
 * vector {@code (k1, k2, p1, p2, k3)} of {@code cv::calibrateCamera}/{@code cv::projectPoints}), so a camera
 * calibrated with OpenCV is used as it is. On normalized image coordinates (x, y) = (X/Z, Y/Z) of a ray in the
 * camera frame (x right, y down, z forward), with r² = x² + y²:
 *
 * <pre>
 *   x_d = x·(1 + k1·r² + k2·r⁴ + k3·r⁶) + 2·p1·x·y + p2·(r² + 2·x²)
 *   y_d = y·(1 + k1·r² + k2·r⁴ + k3·r⁶) + p1·(r² + 2·y²) + 2·p2·x·y
 * </pre>
 *
 * and the pixel is (fx·x_d + cx, fy·y_d + cy). All coefficients are dimensionless (they act on normalized
 * coordinates, not pixels). OpenCV's further terms (k4–k6 rational model, thin prism s1–s4, tilt τx, τy) are
 * not supported: a calibration that used them must be redone with the five-coefficient model.
 *
 * <h2>Domain</h2>
 * Real lenses are described by the polynomial only near the image: far out, a barrel polynomial (k1 &lt; 0)
 * turns over and maps rays of a larger angle back inward, so two rays would share a pixel. The model's
 * <em>valid domain</em> is the set of normalized points whose radius r satisfies
 * <ol>
 *   <li>the radial map r ↦ r·(1 + k1·r² + k2·r⁴ + k3·r⁶) is strictly increasing on [0, r], i.e.
 *       g(s) = 1 + 3·k1·s + 5·k2·s² + 7·k3·s³ &gt; 0 for every s = r'² in [0, r²], and</li>
 *   <li>the Jacobian determinant of (x, y) ↦ (x_d, y_d) is positive at the point (the tangential terms do not
 *       fold the map there).</li>
 * </ol>
 * Inside it the radial map is one-to-one; with tangential coefficients of a real lens (|p1|, |p2| ≲ 0.01) the
 * whole map is then one-to-one too. {@link #isValid} tests this; {@link CameraIntrinsics} answers NaN outside.
 *
 * @param k1 radial coefficient of r²
 * @param k2 radial coefficient of r⁴
 * @param p1 tangential (decentering) coefficient
 * @param p2 tangential (decentering) coefficient
 * @param k3 radial coefficient of r⁶
 */
public record LensDistortion(double k1, double k2, double p1, double p2, double k3) {
    /** No distortion: the pinhole camera. */
    public static final LensDistortion NONE = new LensDistortion(0, 0, 0, 0, 0);

    public LensDistortion {
        if (!Double.isFinite(k1) || !Double.isFinite(k2) || !Double.isFinite(p1) || !Double.isFinite(p2)
                || !Double.isFinite(k3)) {
            throw new IllegalArgumentException("distortion coefficients must be finite numbers, got k1 " + k1
                    + ", k2 " + k2 + ", p1 " + p1 + ", p2 " + p2 + ", k3 " + k3);
        }
    }

    /** Radial-only distortion (p1 = p2 = 0). */
    public static LensDistortion radial(double k1, double k2, double k3) {
        return new LensDistortion(k1, k2, 0, 0, k3);
    }

    /** Whether every coefficient is zero (a pinhole camera, valid everywhere). */
    public boolean isNone() {
        return k1 == 0 && k2 == 0 && p1 == 0 && p2 == 0 && k3 == 0;
    }

    /**
     * Distorts a normalized point.
     *
     * @param out receives {x_d, y_d} (normalized, dimensionless); NaN in, NaN out. No domain check: see {@link #isValid}.
     */
    public void distort(double x, double y, double[] out) {
        double r2 = x * x + y * y;
        double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
        out[0] = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
        out[1] = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
    }

    /**
     * The Jacobian of {@link #distort} at a normalized point.
     *
     * @param out receives {∂x_d/∂x, ∂x_d/∂y, ∂y_d/∂x, ∂y_d/∂y}
     */
    public void jacobian(double x, double y, double[] out) {
        double r2 = x * x + y * y;
        double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
        double dRadialDr2 = k1 + r2 * (2 * k2 + 3 * k3 * r2);
        // ∂(r²)/∂x = 2x, ∂(r²)/∂y = 2y.
        out[0] = radial + 2 * x * x * dRadialDr2 + 2 * p1 * y + 6 * p2 * x;
        out[1] = 2 * x * y * dRadialDr2 + 2 * p1 * x + 2 * p2 * y;
        out[2] = 2 * x * y * dRadialDr2 + 2 * p1 * x + 2 * p2 * y;
        out[3] = radial + 2 * y * y * dRadialDr2 + 6 * p1 * y + 2 * p2 * x;
    }

    /** g(s) = d/dr [r·radial(r)] at r² = s: 1 + 3·k1·s + 5·k2·s² + 7·k3·s³. */
    private double radialSlope(double s) {
        return 1 + s * (3 * k1 + s * (5 * k2 + s * 7 * k3));
    }

    /**
     * Whether the normalized point (x, y) lies in the model's valid domain (see the class Javadoc): the radial
     * map increases strictly from the centre out to the point's radius, and the Jacobian determinant is
     * positive there. Exact (closed form: g's extremes on [0, r²] are at the ends or at the roots of the
     * quadratic g'), not sampled. False for NaN or infinite input.
     */
    public boolean isValid(double x, double y) {
        double s = x * x + y * y;
        if (!Double.isFinite(s)) {
            return false;
        }
        if (isNone()) {
            return true;
        }
        if (!(radialSlope(s) > 0)) {
            return false;
        }
        // g'(s) = 3·k1 + 10·k2·s + 21·k3·s²: g is positive on [0, s] iff it is at both ends (g(0) = 1) and at
        // every critical point inside.
        double a = 21 * k3, b = 10 * k2, c = 3 * k1;
        if (a == 0) {
            if (b != 0 && !positiveAtCriticalPoint(-c / b, s)) {
                return false;
            }
        } else {
            double disc = b * b - 4 * a * c;
            if (disc >= 0) {
                // Numerically stable roots of a·t² + b·t + c.
                double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
                double r1 = q / a;
                double r2 = q != 0 ? c / q : r1;
                if (!positiveAtCriticalPoint(r1, s) || !positiveAtCriticalPoint(r2, s)) {
                    return false;
                }
            }
        }
        // Jacobian determinant (see jacobian), inline: this runs for every projected ray.
        double r2 = s;
        double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
        double dRadialDr2 = k1 + r2 * (2 * k2 + 3 * k3 * r2);
        double j00 = radial + 2 * x * x * dRadialDr2 + 2 * p1 * y + 6 * p2 * x;
        double j01 = 2 * x * y * dRadialDr2 + 2 * p1 * x + 2 * p2 * y;
        double j11 = radial + 2 * y * y * dRadialDr2 + 6 * p1 * y + 2 * p2 * x;
        return j00 * j11 - j01 * j01 > 0;
    }

    /** False when a critical point of g lies inside (0, s) and g is not positive there. */
    private boolean positiveAtCriticalPoint(double root, double s) {
        return !(root > 0 && root < s) || radialSlope(root) > 0;
    }

    /**
     * The largest normalized radius of the valid domain along the radial direction, ignoring the tangential
     * terms: the smallest r &gt; 0 where the radial map stops increasing (first positive root of g(r²)), or
     * +∞ when it never does (k1, k2, k3 ≥ 0, for example). tan⁻¹ of it is the widest off-axis angle the model
     * covers, e.g. k1 = −0.5 alone gives r = √(1/1.5) = 0.816 (39.2°).
     */
    public double maxValidRadius() {
        if (isNone()) {
            return Double.POSITIVE_INFINITY;
        }
        // g is monotonic between consecutive critical points (roots of g'), so its first positive root is
        // bracketed by the first of the intervals [0, c1], [c1, c2], [c2, ∞) whose far end has g ≤ 0.
        double[] ends = new double[4];
        int n = 0;
        ends[n++] = 0;
        double a = 21 * k3, b = 10 * k2, c = 3 * k1;
        if (a == 0) {
            if (b != 0 && -c / b > 0) {
                ends[n++] = -c / b;
            }
        } else {
            double disc = b * b - 4 * a * c;
            if (disc >= 0) {
                double sq = Math.sqrt(disc);
                double q = -0.5 * (b + Math.copySign(sq, b));
                double r1 = q / a;
                double r2 = q != 0 ? c / q : r1;
                double lo = Math.min(r1, r2), hi = Math.max(r1, r2);
                if (lo > 0) {
                    ends[n++] = lo;
                }
                if (hi > 0 && hi != lo) {
                    ends[n++] = hi;
                }
            }
        }
        ends[n++] = 1e30;
        for (int i = 1; i < n; i++) {
            if (!(radialSlope(ends[i]) > 0)) {
                double lo = ends[i - 1], hi = ends[i];
                for (int it = 0; it < 2000 && hi - lo > 1e-16 * hi; it++) {
                    double mid = 0.5 * (lo + hi);
                    if (radialSlope(mid) > 0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return Math.sqrt(lo);
            }
        }
        return Double.POSITIVE_INFINITY;
    }
}
