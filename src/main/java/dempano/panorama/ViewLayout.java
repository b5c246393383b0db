package dempano.panorama;

/**
 * The perspective views that make up a panorama: {@code views} views of 360/views degrees each,
 * rotated clockwise from north (view 0 spans azimuth 0° to 360/views°, as in the thesis), each tall
 * enough to cover the panorama's elevation range at its corners. Pure math: maps panorama directions
 * to view pixels and view pixels to rays.
 *
 * @param views      number of views (≥ 4, so that each spans under 90°)
 * @param widthPx    view width, pixels
 * @param heightPx   view height, pixels
 * @param topTan     image-plane top edge (y at unit depth)
 * @param bottomTan  image-plane bottom edge
 */
public record ViewLayout(int views, int widthPx, int heightPx, double topTan, double bottomTan) {
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
        return new ViewLayout(views, w, h, top, top - h * perPixel);
    }

    public double halfWidthTan() {
        return Math.tan(Math.toRadians(180.0 / views));
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
        double az = ((azimuthDeg % 360) + 360) % 360;
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
