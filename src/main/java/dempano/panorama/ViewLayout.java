package dempano.panorama;

/**
 * The perspective views that cover a target image. For a panorama (the horizon ring, {@code viewAxes}
 * null): {@code views} views of 360/views degrees each, rotated clockwise from north (view 0 spans
 * azimuth 0° to 360/views°, as in the thesis), each tall enough to cover the panorama's elevation range
 * at its corners. For any other {@link dempano.camera.TargetImage} (a camera): a few views around its
 * optical axis, oriented by {@code viewAxes} ({@link #forTarget}). Every view has the same frustum:
 * x ∈ [−halfWidthTan, halfWidthTan], y ∈ [bottomTan, topTan] at unit depth. Pure math: maps directions
 * to view pixels and view pixels to rays.
 *
 * @param views        number of views (the ring: ≥ 4, so that each spans under 90°)
 * @param widthPx      view width, pixels
 * @param heightPx     view height, pixels
 * @param topTan       image-plane top edge (y at unit depth)
 * @param bottomTan    image-plane bottom edge
 * @param halfWidthTan image-plane right edge (x at unit depth; the left edge is its negative)
 * @param viewAxes     per view, its right, up and forward unit vectors in the eye's east-north-up frame
 *                     (9 numbers: right e n u, up e n u, forward e n u); null = the horizon ring, whose view
 *                     k looks level at azimuth {@link #axisAzimuthDeg(int)}
 */
public record ViewLayout(int views, int widthPx, int heightPx, double topTan, double bottomTan, double halfWidthTan,
                         double[][] viewAxes) {
    /** Largest angle, degrees, between a ray and the axis of a single camera view before the view is split. */
    public static final double MAX_SINGLE_VIEW_OFF_AXIS_DEG = 60;
    /** Largest angle, degrees, a camera view's ray may make with the views' common up-down plane: beyond it no perspective view covers it well. */
    public static final double MAX_CAMERA_TILT_DEG = 75;
    /** How the message of a camera too wide for {@link #forTarget} begins (callers add where the field of view came from). */
    public static final String TOO_WIDE = "field of view too wide for perspective views";
    /**
     * How the message of a camera whose pixels are too fine for {@link #forTarget} begins (callers add where the field
     * of view came from).
     */
    public static final String TOO_NARROW = "field of view too narrow for single-precision views";
    /**
     * Finest pixel a camera may have, radians (0.02″; a focal length of 10⁷ pixels, 40 m behind 4 µm pixels): the views
     * hold directions and vertices in single precision (a part in 1.7·10⁷), and with pixels of 6·10⁻⁹ rad terrain 4 m
     * off was drawn as sky in 3 903 of 60 000 pixels; 3·10⁻⁸ rad still matched the CPU reference.
     */
    public static final double FINEST_PIXEL_RAD = 1e-7;
    /** View pixels of margin around a camera's rays, for the resampler's 4×4 neighbourhoods. */
    public static final int CAMERA_MARGIN_PX = 2;

    /** The horizon ring: views looking level, view k at azimuth (k + 0.5)·360/views. */
    public ViewLayout(int views, int widthPx, int heightPx, double topTan, double bottomTan) {
        this(views, widthPx, heightPx, topTan, bottomTan, Math.tan(Math.toRadians(180.0 / views)), null);
    }

    public ViewLayout {
        if (viewAxes != null && viewAxes.length != views) {
            throw new IllegalArgumentException("one axis frame per view: " + views + " views, " + viewAxes.length + " frames");
        }
    }

    /** Whether this is the panorama's horizon ring (level views around the horizon). */
    public boolean ring() {
        return viewAxes == null;
    }

    /** View k's right, up and forward unit vectors in the east-north-up frame (9 numbers, a new array). */
    public double[] axes(int view) {
        if (viewAxes != null) {
            return viewAxes[view].clone();
        }
        double az = Math.toRadians(axisAzimuthDeg(view));
        double s = Math.sin(az), c = Math.cos(az);
        return new double[] {c, -s, 0, 0, 0, 1, s, c, 0};
    }

    /**
     * The azimuths a view sees, {fromDeg, spanDeg} clockwise from north, or null when it sees every azimuth
     * (straight up or down lies in it). Exact for the ring; for other views the bound of its frame's edge.
     */
    public double[] azimuthSectorDeg(int view) {
        if (viewAxes == null) {
            return new double[] {view * 360.0 / views, 360.0 / views};
        }
        double[] a = viewAxes[view];
        for (int sign = -1; sign <= 1; sign += 2) { // straight up or down within the frustum: every azimuth
            double z = a[8] * sign, x = a[2] * sign, y = a[5] * sign;
            if (z > 1e-9 && Math.abs(x / z) <= halfWidthTan && y / z <= topTan && y / z >= bottomTan) {
                return null;
            }
        }
        int n = 64;
        double[] az = new double[4 * n];
        for (int i = 0; i < n; i++) {
            double f = (double) i / n;
            double[][] edge = {{-halfWidthTan + 2 * halfWidthTan * f, topTan}, {halfWidthTan, topTan - (topTan - bottomTan) * f},
                    {halfWidthTan - 2 * halfWidthTan * f, bottomTan}, {-halfWidthTan, bottomTan + (topTan - bottomTan) * f}};
            for (int k = 0; k < 4; k++) {
                double x = edge[k][0], y = edge[k][1];
                double e = a[0] * x + a[3] * y + a[6], no = a[1] * x + a[4] * y + a[7];
                az[k * n + i] = dempano.geo.Angles.wrap360(Math.toDegrees(Math.atan2(e, no)));
            }
        }
        java.util.Arrays.sort(az);
        double gap = az[0] + 360 - az[az.length - 1];
        int start = 0; // the sector starts after the largest gap
        for (int i = 1; i < az.length; i++) {
            if (az[i] - az[i - 1] > gap) {
                gap = az[i] - az[i - 1];
                start = i;
            }
        }
        double margin = 1; // the edge's samples lie up to a fraction of a degree inside the true bound
        return new double[] {az[start] - margin, 360 - gap + 2 * margin};
    }

    /**
     * The views that cover a target image's rays: one view around its centre's ray when every ray lies within
     * {@link #MAX_SINGLE_VIEW_OFF_AXIS_DEG} of it, else views side by side, turned about the image's up
     * direction, at most 80° apart. Resolution: wherever the target has a ray, a view pixel spans at most
     * {@code 1/supersampling} of the target's pixel there (both measured on a grid over the image; a view pixel
     * off the axis spans a smaller angle than at it), so every target pixel is sampled at least as finely as it
     * is wide; {@link #CAMERA_MARGIN_PX} view pixels of margin on every side.
     *
     * @throws IllegalArgumentException when the target's rays are too wide for perspective views (more than
     *                                  {@link #MAX_CAMERA_TILT_DEG} above or below the views' plane, or a
     *                                  view would exceed 16384 pixels)
     */
    public static ViewLayout forTarget(dempano.camera.TargetImage t, double supersampling) {
        return forTarget(t, supersampling, 1024);
    }

    /**
     * Whether perspective views can cover a target image at all, checked cheaply: {@link #forTarget}'s rules on a grid
     * of 64 × 64 steps (the image's edges, whose rays are the widest, included) instead of up to 1024 × 1024 (a quarter
     * of a second on a 24 MP photo). A lens whose extreme ray lies between the coarse grid's samples passes here and is
     * refused by {@link #forTarget}.
     *
     * @throws IllegalArgumentException as {@link #forTarget} does, beginning with {@link #TOO_WIDE} for a field of view
     *                                  too wide
     */
    public static void checkCoverable(dempano.camera.TargetImage t, double supersampling) {
        forTarget(t, supersampling, 64);
    }

    private static ViewLayout forTarget(dempano.camera.TargetImage t, double supersampling, int maxGridSteps) {
        if (!(supersampling >= 0.25 && supersampling <= 8)) {
            throw new IllegalArgumentException("supersampling must be in [0.25, 8], got " + supersampling);
        }
        int w = t.widthPx(), h = t.heightPx();
        // A grid over the image, its edges included, half a pixel apart (edges and centres) on images up to 512
        // pixels and 1/1024 of the image on larger ones (a lens model's domain can end inside the image: its edge rays are the widest):
        // rays, and the angular size of the pixels there.
        int nx = Math.min(2 * w, maxGridSteps), ny = Math.min(2 * h, maxGridSteps);
        java.util.List<double[]> rays = new java.util.ArrayList<>();
        double finestRad = Double.POSITIVE_INFINITY;
        double[] r0 = new double[3], r1 = new double[3];
        for (int i = 0; i <= nx; i++) {
            for (int j = 0; j <= ny; j++) {
                double px = -0.5 + (double) w * i / nx, py = -0.5 + (double) h * j / ny;
                double[] r = t.rayOf(px, py);
                if (Double.isNaN(r[0])) {
                    continue;
                }
                t.rayOf(px + (i < nx ? 1 : -1), py, r0);
                t.rayOf(px, py + (j < ny ? 1 : -1), r1);
                double pixelRad = Double.POSITIVE_INFINITY;
                for (double[] q : new double[][] {r0, r1}) {
                    if (!Double.isNaN(q[0])) {
                        pixelRad = Math.min(pixelRad, angleRad(r, q));
                    }
                }
                finestRad = Math.min(finestRad, pixelRad);
                rays.add(new double[] {r[0], r[1], r[2], pixelRad}); // the ray, and its pixel's angular size
            }
        }
        double[] centre = t.rayOf((w - 1) / 2.0, (h - 1) / 2.0);
        double[] below = t.rayOf((w - 1) / 2.0, (h - 1) / 2.0 + 1);
        if (finestRad < FINEST_PIXEL_RAD && !rays.isEmpty()) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    TOO_NARROW + ": a pixel spans %.2g rad (%.2g″), at least %.0g rad (%.2f″) is needed", finestRad,
                    Math.toDegrees(finestRad) * 3600, FINEST_PIXEL_RAD, Math.toDegrees(FINEST_PIXEL_RAD) * 3600));
        }
        if (rays.isEmpty() || Double.isNaN(centre[0]) || Double.isNaN(below[0]) || !(finestRad > 0)) {
            throw new IllegalArgumentException("the target image has no rays at its centre: " + t);
        }
        // The image's own frame: forward through its centre, up towards the row above, right = forward × up.
        double[] fwd = centre, up = new double[3];
        for (int k = 0; k < 3; k++) {
            up[k] = centre[k] - below[k];
        }
        double dot = up[0] * fwd[0] + up[1] * fwd[1] + up[2] * fwd[2];
        for (int k = 0; k < 3; k++) {
            up[k] -= dot * fwd[k];
        }
        normalize(up);
        double[] right = cross(fwd, up);
        double maxOffAxis = 0, yawMin = 0, yawMax = 0;
        for (double[] r : rays) {
            maxOffAxis = Math.max(maxOffAxis, angleRad(r, fwd));
            double x = dotProduct(r, right), y = dotProduct(r, up), z = dotProduct(r, fwd);
            double tilt = Math.toDegrees(Math.atan2(y, Math.hypot(x, z)));
            if (Math.abs(tilt) > MAX_CAMERA_TILT_DEG) {
                throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                        TOO_WIDE + ": a ray %.1f° off the image's horizontal plane"
                                + " (at most %.0f°)", tilt, MAX_CAMERA_TILT_DEG));
            }
            double yaw = Math.atan2(x, z);
            yawMin = Math.min(yawMin, yaw);
            yawMax = Math.max(yawMax, yaw);
        }
        int views = Math.toDegrees(maxOffAxis) <= MAX_SINGLE_VIEW_OFF_AXIS_DEG ? 1
                : (int) Math.ceil(Math.toDegrees(yawMax - yawMin) / 80);
        if (views > 4) {
            throw new IllegalArgumentException(TOO_WIDE + ": "
                    + Math.round(Math.toDegrees(yawMax - yawMin)) + "° across");
        }
        double step = (yawMax - yawMin) / views;
        double[][] axes = new double[views][];
        for (int k = 0; k < views; k++) {
            double yaw = views == 1 ? 0 : yawMin + (k + 0.5) * step, c = Math.cos(yaw), s = Math.sin(yaw);
            double[] a = new double[9];
            for (int q = 0; q < 3; q++) {
                a[q] = c * right[q] - s * fwd[q];
                a[3 + q] = up[q];
                a[6 + q] = c * fwd[q] + s * right[q];
            }
            axes[k] = a;
        }
        double xMax = 0, yMin = Double.POSITIVE_INFINITY, yMax = Double.NEGATIVE_INFINITY, tanStep = Double.POSITIVE_INFINITY;
        for (double[] r : rays) {
            double[] a = axes[nearestView(axes, r[0], r[1], r[2])];
            double z = a[6] * r[0] + a[7] * r[1] + a[8] * r[2];
            double x = (a[0] * r[0] + a[1] * r[1] + a[2] * r[2]) / z, y = (a[3] * r[0] + a[4] * r[1] + a[5] * r[2]) / z;
            // A view step of δ (tangent units) at (x, y) spans δ·√(1 + y²)/(1 + x² + y²) rad across x and
            // δ·√(1 + x²)/(1 + x² + y²) rad across y: δ is chosen so the smaller is at most the target's pixel.
            double shrink = Math.min(Math.sqrt(1 + y * y), Math.sqrt(1 + x * x)) / (1 + x * x + y * y);
            tanStep = Math.min(tanStep, r[3] / shrink);
            if (views > 1) {
                // Between grid samples a ray can lie on the border between two views, where y/z is largest: bound
                // y by the ray's tilt seen at the sector's edge, and x by the sector's half width.
                double tilt = Math.atan2(dotProduct(r, up), Math.hypot(dotProduct(r, right), dotProduct(r, fwd)));
                y = Math.tan(tilt) / Math.cos(step / 2);
                x = Math.tan(step / 2);
            }
            xMax = Math.max(xMax, Math.abs(x));
            yMin = Math.min(yMin, y);
            yMax = Math.max(yMax, y);
        }
        // 1 % finer than the finest pixel sampled: the grid can miss the finest spot by a fraction of a pixel.
        double perPixel = tanStep / supersampling / 1.01;
        double half = xMax + CAMERA_MARGIN_PX * perPixel;
        int vw = (int) Math.ceil(2 * half / perPixel);
        perPixel = 2 * half / vw;
        double top = yMax + CAMERA_MARGIN_PX * perPixel;
        int vh = (int) Math.ceil((top - yMin + CAMERA_MARGIN_PX * perPixel) / perPixel);
        if (vw > MAX_VIEW_PX || vh > MAX_VIEW_PX) {
            throw new IllegalArgumentException("views of " + vw + "×" + vh + " pixels would be needed (at most " + MAX_VIEW_PX + "):"
                    + " lower the supersampling or the image size");
        }
        return new ViewLayout(views, vw, vh, top, top - vh * perPixel, half, axes);
    }

    /**
     * The lowest elevation angle any view's frame reaches, degrees above the eye's horizontal: −90 when straight
     * down lies in a view; for the ring, its bottom edge at the views' corners.
     */
    public double lowestElevationDeg() {
        double lowest = 90;
        int n = 64;
        for (int k = 0; k < views; k++) {
            double[] a = axes(k);
            if (a[8] < 0) { // straight down in front of the view: is it in the frame?
                double x = a[2] / a[8], y = a[5] / a[8];
                if (Math.abs(x) <= halfWidthTan && y <= topTan && y >= bottomTan) {
                    return -90;
                }
            }
            for (int i = 0; i <= n; i++) {
                double f = (double) i / n;
                double[][] edge = {{-halfWidthTan + 2 * halfWidthTan * f, topTan}, {halfWidthTan, topTan - (topTan - bottomTan) * f},
                        {halfWidthTan - 2 * halfWidthTan * f, bottomTan}, {-halfWidthTan, bottomTan + (topTan - bottomTan) * f}};
                for (double[] xy : edge) {
                    double e = a[0] * xy[0] + a[3] * xy[1] + a[6], no = a[1] * xy[0] + a[4] * xy[1] + a[7];
                    double u = a[2] * xy[0] + a[5] * xy[1] + a[8];
                    lowest = Math.min(lowest, Math.toDegrees(Math.atan2(u, Math.hypot(e, no))));
                }
            }
        }
        return lowest;
    }

    /** The view whose axis is nearest a direction (east, north, up) among {@code axes} (largest cosine). */
    static int nearestView(double[][] axes, double e, double n, double u) {
        int best = 0;
        double bestCos = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < axes.length; k++) {
            double c = axes[k][6] * e + axes[k][7] * n + axes[k][8] * u;
            if (c > bestCos) {
                bestCos = c;
                best = k;
            }
        }
        return best;
    }

    /** The view whose axis is nearest a direction in the east-north-up frame (for the ring: {@link #viewOf}). */
    public int viewOfRay(double east, double north, double up) {
        return viewAxes == null ? viewOf(Math.toDegrees(Math.atan2(east, north))) : nearestView(viewAxes, east, north, up);
    }

    /**
     * Fractional pixel coordinates (pixel centres at integers, GL rows from the bottom) in view k of a direction
     * in the east-north-up frame.
     *
     * @param out receives {px, py, xTan, yTan}; NaN when the direction is not in front of the view
     */
    public void projectRay(int view, double east, double north, double up, double[] out) {
        double[] a = viewAxes != null ? viewAxes[view] : axes(view);
        double z = a[6] * east + a[7] * north + a[8] * up;
        if (!(z > 0)) {
            out[0] = out[1] = out[2] = out[3] = Double.NaN;
            return;
        }
        double xTan = (a[0] * east + a[1] * north + a[2] * up) / z, yTan = (a[3] * east + a[4] * north + a[5] * up) / z;
        out[0] = (xTan + halfWidthTan) / (2 * halfWidthTan) * widthPx - 0.5;
        out[1] = (yTan - bottomTan) / (topTan - bottomTan) * heightPx - 0.5;
        out[2] = xTan;
        out[3] = yTan;
    }

    private static double angleRad(double[] a, double[] b) {
        double[] c = cross(a, b);
        return Math.atan2(Math.sqrt(dotProduct(c, c)), dotProduct(a, b));
    }

    private static double dotProduct(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static void normalize(double[] v) {
        double l = Math.sqrt(dotProduct(v, v));
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }

    /** The largest view side, pixels: an OpenGL renderbuffer's limit on llvmpipe and most GPUs. */
    public static final int MAX_VIEW_PX = 16384;

    /** Views rendered by default, as in the thesis. */
    public static final int DEFAULT_VIEWS = 8;

    /**
     * Views for a panorama: resolution chosen so that a view pixel is at most
     * {@code 1/supersampling} of a panorama pixel everywhere in the view.
     */
    public static ViewLayout forPanorama(PanoramaGeometry g, int views, double supersampling) {
        if (views < 4 || views > 360 || 360 % views != 0) {
            throw new IllegalArgumentException("views must divide 360 and be in [4, 360], got " + views);
        }
        if (!(supersampling >= 0.25 && supersampling <= 8)) {
            throw new IllegalArgumentException("supersampling must be in [0.25, 8], got " + supersampling);
        }
        double half = Math.toRadians(180.0 / views);
        double halfTan = Math.tan(half);
        // Angular pixel size is largest at the axis: 2·tan(half)/W rad must be ≤ (1/ppd)° / ss.
        double panoPixelRad = Math.toRadians(1 / g.pixelsPerDegree());
        int w = (int) Math.ceil(2 * halfTan / panoPixelRad * supersampling);
        double top = Math.max(Math.tan(Math.toRadians(Math.min(89, g.topElevationDeg()))) / Math.cos(half),
                Math.tan(Math.toRadians(Math.min(89, g.topElevationDeg()))));
        double bottom = Math.min(Math.tan(Math.toRadians(Math.max(-89, g.bottomElevationDeg()))) / Math.cos(half),
                Math.tan(Math.toRadians(Math.max(-89, g.bottomElevationDeg()))));
        // One pixel of margin above and below for interpolation.
        double perPixel = 2 * halfTan / w;
        top += perPixel;
        bottom -= perPixel;
        int h = (int) Math.ceil((top - bottom) / perPixel);
        if (w > MAX_VIEW_PX || h > MAX_VIEW_PX) {
            // An OpenGL renderbuffer's limit (llvmpipe's and most GPUs'): jME would fail on the GL thread instead.
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "views of %d×%d pixels would be"
                    + " needed (at most %d): a view's height grows as the tangent of the elevation range's ends"
                    + " (%.1f°…%.1f° here); narrow the elevation range or lower the pixels per degree (%s) or the"
                    + " supersampling (%s)", w, h, MAX_VIEW_PX, g.bottomElevationDeg(), g.topElevationDeg(),
                    g.pixelsPerDegree(), supersampling));
        }
        return new ViewLayout(views, w, h, top, top - h * perPixel);
    }

    /** Azimuth of view k's axis, degrees: (k + 0.5)·360/views. */
    public double axisAzimuthDeg(int view) {
        return (view + 0.5) * 360.0 / views;
    }

    /** Image-plane x (tangent) of a view pixel column's centre. */
    public double xTanOfPixel(double px) {
        return -halfWidthTan() + (px + 0.5) * 2 * halfWidthTan() / widthPx;
    }

    /** Image-plane y (tangent) of a view pixel row's centre; row 0 at the bottom (GL order). */
    public double yTanOfPixel(double py) {
        return bottomTan + (py + 0.5) * (topTan - bottomTan) / heightPx;
    }

    /** Which view a direction falls in. */
    public int viewOf(double azimuthDeg) {
        double az = dempano.geo.Angles.wrap360(azimuthDeg);
        return Math.min(views - 1, (int) Math.floor(az * views / 360));
    }

    /**
     * Fractional pixel coordinates (pixel centres at integers) in a view of a direction.
     *
     * @return {px, py, xTan, yTan}; py counts from the bottom row
     */
    public double[] project(int view, double azimuthDeg, double elevationDeg) {
        double alpha = Math.toRadians(azimuthDeg - axisAzimuthDeg(view));
        double el = Math.toRadians(elevationDeg);
        double xTan = Math.tan(alpha);
        double yTan = Math.tan(el) / Math.cos(alpha);
        double px = (xTan + halfWidthTan()) / (2 * halfWidthTan()) * widthPx - 0.5;
        double py = (yTan - bottomTan) / (topTan - bottomTan) * heightPx - 0.5;
        return new double[] {px, py, xTan, yTan};
    }
}
