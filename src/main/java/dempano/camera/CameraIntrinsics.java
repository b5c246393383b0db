package dempano.camera;

/**
 * A camera's intrinsic calibration in OpenCV's model and conventions, so the numbers of an OpenCV calibration
 * ({@code cameraMatrix} = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] and {@code distCoeffs} = (k1, k2, p1, p2, k3))
 * are used as they are.
 *
 * <h2>Conventions</h2>
 * <ul>
 *   <li><b>Camera frame</b> (OpenCV): x to the image's right, y to the image's bottom, z forward along the
 *       optical axis; right-handed.</li>
 *   <li><b>Pixel coordinates</b> (OpenCV): the centre of pixel (column i, row j) is at (i, j); the image covers
 *       [−0.5, w − 0.5] × [−0.5, h − 0.5]; row 0 is the top. The centred principal point is therefore
 *       ((w − 1)/2, (h − 1)/2), which is what OpenCV's {@code getDefaultNewCameraMatrix(…, centerPrincipalPoint
 *       = true)} and {@code initCameraMatrix2D} use (checked with OpenCV 5.0: 640 × 480 gives (319.5, 239.5)).</li>
 *   <li><b>Pixels as displayed</b>: width, height and all pixel coordinates refer to the image after its EXIF
 *       orientation is applied (see {@link PhotoMetadata}). An OpenCV calibration made on the stored
 *       (unrotated) frames of a camera that writes orientation 5–8 must be done on the displayed images
 *       instead.</li>
 *   <li><b>Projection</b>: a ray (X, Y, Z) with Z &gt; 0 has normalized coordinates (X/Z, Y/Z), distorted by
 *       {@link LensDistortion}, then pixel = (fx·x_d + cx, fy·y_d + cy): exactly {@code cv::projectPoints}
 *       with a zero rotation and translation.</li>
 *   <li><b>Field of view</b>: the angle between the rays through the image's outer edges (x = −0.5 and
 *       x = w − 0.5 at row cy for the horizontal one), so a centred pinhole camera has
 *       hfov = 2·atan(w / (2·fx)).</li>
 * </ul>
 *
 * <h2>Inverse (undistortion)</h2>
 * {@link #rayOf} inverts the distortion with Newton's method (analytic Jacobian, started at the distorted
 * point, steps halved until they stay in the valid domain and reduce the residual), stopping when the
 * re-projected point is within {@link #UNDISTORT_TOLERANCE_PX} of the pixel (at most
 * {@link #UNDISTORT_MAX_ITERATIONS} steps). It converges for every pixel that is the image of a point in the
 * distortion's valid domain (see {@link LensDistortion}: there the radial map is strictly increasing, so the
 * inverse is unique; tested out to 99.9 % of the valid radius); other pixels (beyond the fold of a strong barrel
 * polynomial) have no ray and give NaN. OpenCV's {@code undistortPoints} instead runs a fixed number of
 * fixed-point steps (5 by default) and returns whatever it reached, also beyond the fold. With zero distortion
 * {@link #rayOf} is the closed form ((px − cx)/fx, (py − cy)/fy, 1), normalized.
 *
 * @param widthPx    image width as displayed, pixels (≥ 1)
 * @param heightPx   image height as displayed, pixels (≥ 1)
 * @param fxPx       focal length in pixels along x (&gt; 0)
 * @param fyPx       focal length in pixels along y (&gt; 0; = fx for square pixels)
 * @param cxPx       principal point x, pixels, OpenCV convention (centred: (w − 1)/2)
 * @param cyPx       principal point y, pixels, OpenCV convention (centred: (h − 1)/2)
 * @param distortion lens distortion ({@link LensDistortion#NONE} for a pinhole camera)
 */
public record CameraIntrinsics(int widthPx, int heightPx, double fxPx, double fyPx, double cxPx, double cyPx,
                               LensDistortion distortion) {
    /** Diagonal of the 36 × 24 mm frame, mm: √(36² + 24²) = 43.2666 mm. */
    public static final double DIAGONAL_35MM_MM = Math.hypot(36, 24);

    /** When {@link #rayOf} stops: the ray re-projects to within this many pixels of the asked pixel. */
    public static final double UNDISTORT_TOLERANCE_PX = 1e-9;

    /** At most this many Newton steps in {@link #rayOf} (a few suffice in the valid domain; see the tests). */
    public static final int UNDISTORT_MAX_ITERATIONS = 100;

    public CameraIntrinsics {
        if (widthPx < 1 || heightPx < 1) {
            throw new IllegalArgumentException("image size must be at least 1 × 1 pixels, got " + widthPx + " × " + heightPx);
        }
        if (!(fxPx > 0 && fxPx < Double.POSITIVE_INFINITY) || !(fyPx > 0 && fyPx < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("focal lengths in pixels must be positive and finite, got fx " + fxPx
                    + ", fy " + fyPx);
        }
        if (!Double.isFinite(cxPx) || !Double.isFinite(cyPx)) {
            throw new IllegalArgumentException("principal point must be finite, got " + cxPx + ", " + cyPx);
        }
        if (distortion == null) {
            throw new IllegalArgumentException("distortion must be given (LensDistortion.NONE for none)");
        }
    }

    /** A distortion-free camera with square pixels and the principal point at the image centre. */
    public static CameraIntrinsics pinhole(int widthPx, int heightPx, double focalPx) {
        return new CameraIntrinsics(widthPx, heightPx, focalPx, focalPx, centre(widthPx), centre(heightPx),
                LensDistortion.NONE);
    }

    /** The centred principal point coordinate for a size, pixels: (n − 1)/2 (OpenCV convention). */
    public static double centre(int sizePx) {
        return (sizePx - 1) / 2.0;
    }

    /**
     * From the lens's focal length and the sensor's size: fx = fy = focalMm · max(w, h) / sensorWidthMm.
     *
     * @param focalLengthMm the lens's actual focal length, mm (EXIF FocalLength)
     * @param sensorWidthMm the sensor's long side, mm, which the image's long side is taken to span (true of a
     *                      full-frame image and of a 16:9 crop of a 4:3 sensor; not of digital zoom)
     */
    public static CameraIntrinsics fromFocalLength(int widthPx, int heightPx, double focalLengthMm,
                                                   double sensorWidthMm) {
        if (!(focalLengthMm > 0 && focalLengthMm < 1e5) || !(sensorWidthMm > 0 && sensorWidthMm < 1e4)) {
            throw new IllegalArgumentException("focal length and sensor width must be positive millimetres, got "
                    + focalLengthMm + " mm and " + sensorWidthMm + " mm");
        }
        return pinhole(widthPx, heightPx, focalLengthMm * Math.max(widthPx, heightPx) / sensorWidthMm);
    }

    /**
     * From a 35 mm-equivalent focal length, diagonal definition: the focal length that gives the image's
     * diagonal the same angle of view as a 36 × 24 mm frame's diagonal (43.27 mm), i.e.
     * fx = fy = focal35 · √(w² + h²) / 43.27. This is how cameras and phones compute EXIF FocalLengthIn35mmFilm
     * (the CIPA DC-008 tag itself does not define it). For a 3:2 image it equals the width definition
     * focal35 · w / 36; for a 4:3 image the width definition would give fx 4 % smaller.
     *
     * @param focal35mmMm the 35 mm-equivalent focal length, mm
     */
    public static CameraIntrinsics fromFocal35mm(int widthPx, int heightPx, double focal35mmMm) {
        if (!(focal35mmMm > 0 && focal35mmMm < 1e5)) {
            throw new IllegalArgumentException("35 mm-equivalent focal length must be positive millimetres, got "
                    + focal35mmMm);
        }
        return pinhole(widthPx, heightPx, focal35mmMm * Math.hypot(widthPx, heightPx) / DIAGONAL_35MM_MM);
    }

    /**
     * From the horizontal field of view across the displayed image's full width (edge to edge):
     * fx = fy = (w / 2) / tan(hfov / 2).
     *
     * @param horizontalFovDeg degrees, in (0, 180)
     */
    public static CameraIntrinsics fromHorizontalFov(int widthPx, int heightPx, double horizontalFovDeg) {
        if (!(horizontalFovDeg > 0 && horizontalFovDeg < 180)) {
            throw new IllegalArgumentException("horizontal field of view must be in (0°, 180°), got " + horizontalFovDeg);
        }
        return pinhole(widthPx, heightPx, widthPx / 2.0 / Math.tan(Math.toRadians(horizontalFovDeg) / 2));
    }

    /**
     * From OpenCV's arrays as {@code cv::calibrateCamera} returns them.
     *
     * @param cameraMatrix the 3 × 3 camera matrix, row-major: [fx, 0, cx, 0, fy, cy, 0, 0, 1]
     * @param distCoeffs   (k1, k2, p1, p2[, k3[, k4, k5, k6[, s1, s2, s3, s4[, τx, τy]]]]): 4 or 5 values, or
     *                     more when every one after k3 is zero (the terms this model does not have)
     * @throws IllegalArgumentException for a matrix with skew or a wrong last row, or non-zero terms beyond k3
     */
    public static CameraIntrinsics fromOpenCv(int widthPx, int heightPx, double[] cameraMatrix, double[] distCoeffs) {
        if (cameraMatrix == null || cameraMatrix.length != 9 || cameraMatrix[1] != 0 || cameraMatrix[3] != 0
                || cameraMatrix[6] != 0 || cameraMatrix[7] != 0 || cameraMatrix[8] != 1) {
            throw new IllegalArgumentException("the camera matrix must be [fx, 0, cx, 0, fy, cy, 0, 0, 1] (row-major,"
                    + " no skew), got " + java.util.Arrays.toString(cameraMatrix));
        }
        if (distCoeffs == null || distCoeffs.length < 4) {
            throw new IllegalArgumentException("distortion needs at least k1, k2, p1, p2, got "
                    + java.util.Arrays.toString(distCoeffs));
        }
        for (int i = 5; i < distCoeffs.length; i++) {
            if (distCoeffs[i] != 0) {
                throw new IllegalArgumentException("distortion coefficient " + (i + 1) + " (beyond k3: rational,"
                        + " thin-prism or tilt terms) is " + distCoeffs[i] + ": only k1, k2, p1, p2, k3 are supported;"
                        + " calibrate without CALIB_RATIONAL_MODEL, CALIB_THIN_PRISM_MODEL and CALIB_TILTED_MODEL");
            }
        }
        return new CameraIntrinsics(widthPx, heightPx, cameraMatrix[0], cameraMatrix[4], cameraMatrix[2],
                cameraMatrix[5], new LensDistortion(distCoeffs[0], distCoeffs[1], distCoeffs[2], distCoeffs[3],
                distCoeffs.length > 4 ? distCoeffs[4] : 0));
    }

    /**
     * This camera, calibrated on the stored frames, for the image as displayed under an EXIF orientation: what a
     * calibration of a camera that writes orientation tags becomes for {@link PhotoMetadata}'s displayed pixels.
     * The stored pixel (u, v) of a W × H frame is displayed at
     *
     * <table>
     *   <caption>EXIF orientation</caption>
     *   <tr><th>tag</th><th>meaning</th><th>displayed pixel</th><th>displayed size</th></tr>
     *   <tr><td>1</td><td>as stored</td><td>(u, v)</td><td>W × H</td></tr>
     *   <tr><td>2</td><td>mirrored left-right</td><td>(W−1−u, v)</td><td>W × H</td></tr>
     *   <tr><td>3</td><td>turned 180°</td><td>(W−1−u, H−1−v)</td><td>W × H</td></tr>
     *   <tr><td>4</td><td>mirrored top-bottom</td><td>(u, H−1−v)</td><td>W × H</td></tr>
     *   <tr><td>5</td><td>transposed</td><td>(v, u)</td><td>H × W</td></tr>
     *   <tr><td>6</td><td>turned 90° clockwise</td><td>(H−1−v, u)</td><td>H × W</td></tr>
     *   <tr><td>7</td><td>transversed</td><td>(H−1−v, W−1−u)</td><td>H × W</td></tr>
     *   <tr><td>8</td><td>turned 90° counter-clockwise</td><td>(v, W−1−u)</td><td>H × W</td></tr>
     * </table>
     *
     * The result sees the same rays at the corresponding pixels up to a rotation or reflection of the camera frame
     * about its axis (absorbed by the displayed image's own roll): focal lengths swap for 5–8, the principal point
     * moves with its pixel, radial coefficients stay and the tangential pair (p2, p1) turns with the image (it is
     * a vector: the tangential term is r²·q + 2·(q·v)·v with q = (p2, p1), v = (x, y)).
     *
     * @param exifOrientation 1–8; 0 (no tag) is taken as 1
     */
    public CameraIntrinsics displayed(int exifOrientation) {
        // (x', y') = A·(x, y) on normalized coordinates: a signed permutation {a, b, c, d} = [[a, b], [c, d]].
        int[] a = switch (exifOrientation) {
            case 0, 1 -> new int[] {1, 0, 0, 1};
            case 2 -> new int[] {-1, 0, 0, 1};
            case 3 -> new int[] {-1, 0, 0, -1};
            case 4 -> new int[] {1, 0, 0, -1};
            case 5 -> new int[] {0, 1, 1, 0};
            case 6 -> new int[] {0, -1, 1, 0};
            case 7 -> new int[] {0, -1, -1, 0};
            case 8 -> new int[] {0, 1, -1, 0};
            default -> throw new IllegalArgumentException("EXIF orientation must be 1–8, got " + exifOrientation);
        };
        boolean swap = a[0] == 0;
        int w = swap ? heightPx : widthPx, h = swap ? widthPx : heightPx;
        double fx = swap ? fyPx : fxPx, fy = swap ? fxPx : fyPx;
        double[] q = {distortion.p2(), distortion.p1()};
        double q0 = a[0] * q[0] + a[1] * q[1], q1 = a[2] * q[0] + a[3] * q[1];
        // The displayed principal point is the pixel map (table above) applied to the stored one.
        double cx = switch (exifOrientation) {
            case 0, 1, 4 -> cxPx;
            case 2, 3 -> widthPx - 1 - cxPx;
            case 5, 8 -> cyPx;
            default -> heightPx - 1 - cyPx; // 6, 7
        };
        double cy = switch (exifOrientation) {
            case 0, 1, 2 -> cyPx;
            case 3, 4 -> heightPx - 1 - cyPx;
            case 5, 6 -> cxPx;
            default -> widthPx - 1 - cxPx; // 7, 8
        };
        return new CameraIntrinsics(w, h, fx, fy, cx, cy,
                new LensDistortion(distortion.k1(), distortion.k2(), q1, q0, distortion.k3()));
    }

    /** The same camera with another lens distortion. */
    public CameraIntrinsics withDistortion(LensDistortion d) {
        return new CameraIntrinsics(widthPx, heightPx, fxPx, fyPx, cxPx, cyPx, d);
    }

    /**
     * The ray through a pixel, in the camera frame (x right, y down, z forward), as a unit vector.
     *
     * @param px  column, pixels (OpenCV convention: pixel i's centre at i); any value, not only inside the image
     * @param py  row, pixels, 0 on top
     * @param out receives {x, y, z} with z &gt; 0, or three NaN when the pixel has no ray (beyond the fold of the
     *            distortion polynomial, or NaN input)
     */
    public void rayOf(double px, double py, double[] out) {
        double xd = (px - cxPx) / fxPx, yd = (py - cyPx) / fyPx;
        double x, y;
        if (distortion.isNone()) {
            x = xd;
            y = yd;
        } else {
            double[] u = undistort(xd, yd);
            if (u == null) {
                out[0] = out[1] = out[2] = Double.NaN;
                return;
            }
            x = u[0];
            y = u[1];
        }
        double norm = Math.sqrt(x * x + y * y + 1);
        if (!(norm < Double.POSITIVE_INFINITY)) {
            out[0] = out[1] = out[2] = Double.NaN;
            return;
        }
        out[0] = x / norm;
        out[1] = y / norm;
        out[2] = 1 / norm;
    }

    /** {@link #rayOf(double, double, double[])} into a new array. */
    public double[] rayOf(double px, double py) {
        double[] out = new double[3];
        rayOf(px, py, out);
        return out;
    }

    /**
     * The pixel a camera-frame direction projects to (need not be a unit vector): exactly OpenCV's
     * {@code projectPoints}.
     *
     * @param out receives {px, py} in the OpenCV pixel convention, possibly outside the image; NaN when z ≤ 0
     *            (behind the camera or in its focal plane), for non-finite input, or when the direction lies
     *            outside the distortion's valid domain (see {@link LensDistortion})
     */
    public void pixelOf(double x, double y, double z, double[] out) {
        if (!(z > 0) || !Double.isFinite(x) || !Double.isFinite(y) || !(z < Double.POSITIVE_INFINITY)) {
            out[0] = out[1] = Double.NaN;
            return;
        }
        double xn = x / z, yn = y / z;
        if (!distortion.isValid(xn, yn)) {
            out[0] = out[1] = Double.NaN;
            return;
        }
        distortion.distort(xn, yn, out);
        out[0] = fxPx * out[0] + cxPx;
        out[1] = fyPx * out[1] + cyPx;
    }

    /** {@link #pixelOf(double, double, double, double[])} into a new array. */
    public double[] pixelOf(double x, double y, double z) {
        double[] out = new double[2];
        pixelOf(x, y, z, out);
        return out;
    }

    /** Whether a pixel coordinate lies on the image: [−0.5, w − 0.5) × [−0.5, h − 0.5). False for NaN. */
    public boolean contains(double px, double py) {
        return px >= -0.5 && px < widthPx - 0.5 && py >= -0.5 && py < heightPx - 0.5;
    }

    /** Angle between the rays through the left and right image edges at row cy, degrees; NaN if one has no ray. */
    public double horizontalFovDeg() {
        return angleDeg(rayOf(-0.5, cyPx), rayOf(widthPx - 0.5, cyPx));
    }

    /** Angle between the rays through the top and bottom image edges at column cx, degrees; NaN if one has no ray. */
    public double verticalFovDeg() {
        return angleDeg(rayOf(cxPx, -0.5), rayOf(cxPx, heightPx - 0.5));
    }

    /** Angle between the rays through the top-left and bottom-right image corners, degrees; NaN if one has no ray. */
    public double diagonalFovDeg() {
        return angleDeg(rayOf(-0.5, -0.5), rayOf(widthPx - 0.5, heightPx - 0.5));
    }

    /** Angle between two unit vectors, degrees, accurate at every angle (atan2 of cross and dot products). */
    static double angleDeg(double[] a, double[] b) {
        double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        return Math.toDegrees(Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), dot));
    }

    /**
     * Newton's method for the normalized undistorted point whose distortion is (xd, yd); null when none is found
     * in the valid domain. A fast pass keeps the iterates where the radial map still increases (g &gt; 0, a
     * necessary condition) and checks the full domain once at the end; should that fail (coefficients whose g
     * dips below zero and recovers, so an iterate could jump over the fold), a careful pass checks every iterate.
     */
    private double[] undistort(double xd, double yd) {
        if (!Double.isFinite(xd) || !Double.isFinite(yd)) {
            return null;
        }
        double[] fast = newton(xd, yd, false);
        if (fast != null && distortion.isValid(fast[0], fast[1])) {
            return fast;
        }
        return newton(xd, yd, true);
    }

    private boolean inDomain(double x, double y, boolean full) {
        if (full) {
            return distortion.isValid(x, y);
        }
        LensDistortion d = distortion;
        double s = x * x + y * y;
        return 1 + s * (3 * d.k1() + s * (5 * d.k2() + s * 7 * d.k3())) > 0;
    }

    private double[] newton(double xd, double yd, boolean full) {
        LensDistortion d = distortion;
        double k1 = d.k1(), k2 = d.k2(), k3 = d.k3(), p1 = d.p1(), p2 = d.p2();
        double tolerance = UNDISTORT_TOLERANCE_PX / Math.max(fxPx, fyPx);
        double x = xd, y = yd;
        // Start inside the domain: pull the start toward the centre until it is.
        for (int i = 0; i < 60 && !inDomain(x, y, full); i++) {
            x *= 0.5;
            y *= 0.5;
        }
        if (!inDomain(x, y, full)) {
            return null;
        }
        double r2 = x * x + y * y;
        double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
        double rx = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x) - xd;
        double ry = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y - yd;
        // Squared residuals (Math.hypot is slow and the comparisons need no root).
        double tolerance2 = tolerance * tolerance;
        double res = rx * rx + ry * ry;
        for (int it = 0; it < UNDISTORT_MAX_ITERATIONS && res > tolerance2; it++) {
            double dR = k1 + r2 * (2 * k2 + 3 * k3 * r2);
            double j00 = radial + 2 * x * x * dR + 2 * p1 * y + 6 * p2 * x;
            double j01 = 2 * x * y * dR + 2 * p1 * x + 2 * p2 * y; // = j10: the Jacobian is symmetric
            double j11 = radial + 2 * y * y * dR + 6 * p1 * y + 2 * p2 * x;
            double det = j00 * j11 - j01 * j01;
            if (!(Math.abs(det) > 0)) {
                return null;
            }
            double sx = (j11 * rx - j01 * ry) / det;
            double sy = (-j01 * rx + j00 * ry) / det;
            double lambda = 1;
            boolean moved = false;
            for (int h = 0; h < 60; h++, lambda *= 0.5) {
                double nx = x - lambda * sx, ny = y - lambda * sy;
                if (!inDomain(nx, ny, full)) {
                    continue;
                }
                double nr2 = nx * nx + ny * ny;
                double nradial = 1 + nr2 * (k1 + nr2 * (k2 + nr2 * k3));
                double nrx = nx * nradial + 2 * p1 * nx * ny + p2 * (nr2 + 2 * nx * nx) - xd;
                double nry = ny * nradial + p1 * (nr2 + 2 * ny * ny) + 2 * p2 * nx * ny - yd;
                double nres = nrx * nrx + nry * nry;
                if (nres < res) {
                    x = nx;
                    y = ny;
                    r2 = nr2;
                    radial = nradial;
                    rx = nrx;
                    ry = nry;
                    res = nres;
                    moved = true;
                    break;
                }
            }
            if (!moved) {
                // No step inside the domain reduces the residual: the pixel lies beyond the fold (or the residual
                // is at rounding level, which the test below accepts).
                break;
            }
        }
        return res <= tolerance2 ? new double[] {x, y} : null;
    }
}
