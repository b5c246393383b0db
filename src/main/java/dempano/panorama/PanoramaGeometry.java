package dempano.panorama;

/**
 * The equirectangular layout of a panorama. Column c covers azimuth [c/ppd, (c+1)/ppd) degrees
 * clockwise from true north (pixel centre (c + 0.5)/ppd); row r has its centre at elevation
 * {@code topElevationDeg − (r + 0.5)/ppd} degrees above the eye's local horizontal.
 *
 * @param pixelsPerDegree  pixels per degree in both directions (&gt; 0)
 * @param topElevationDeg  elevation of the top edge of row 0, degrees
 * @param heightPx         number of rows
 */
public record PanoramaGeometry(double pixelsPerDegree, double topElevationDeg, int heightPx) {
    /** Azimuth of column 0's left edge, degrees: north. */
    public static final double LEFT_AZIMUTH_DEG = 0;

    public PanoramaGeometry {
        if (!(pixelsPerDegree > 0 && pixelsPerDegree <= 200) || Math.rint(360 * pixelsPerDegree) != 360 * pixelsPerDegree) {
            throw new IllegalArgumentException("pixels per degree must be in (0, 200] and give a whole number of columns"
                    + " over 360°, got " + pixelsPerDegree);
        }
        if (!(topElevationDeg <= 90 && topElevationDeg - heightPx / pixelsPerDegree >= -90) || heightPx < 1) {
            throw new IllegalArgumentException("elevation range must lie within [-90°, 90°]: top " + topElevationDeg
                    + "°, " + heightPx + " rows");
        }
    }

    /** A layout covering [bottomDeg, topDeg] in elevation (rounded outward to whole pixels). */
    public static PanoramaGeometry of(double pixelsPerDegree, double bottomDeg, double topDeg) {
        if (!(topDeg > bottomDeg)) {
            throw new IllegalArgumentException("elevation range needs top > bottom, got " + bottomDeg + ":" + topDeg);
        }
        int rows = (int) Math.ceil((topDeg - bottomDeg) * pixelsPerDegree - 1e-9);
        return new PanoramaGeometry(pixelsPerDegree, topDeg, rows);
    }

    public int widthPx() {
        return (int) Math.round(360 * pixelsPerDegree);
    }

    public double bottomElevationDeg() {
        return topElevationDeg - heightPx / pixelsPerDegree;
    }

    /** Azimuth of a column's centre, degrees in [0, 360). */
    public double azimuthOfColumn(int column) {
        return (column + 0.5) / pixelsPerDegree;
    }

    /** Elevation of a row's centre, degrees. */
    public double elevationOfRow(int row) {
        return topElevationDeg - (row + 0.5) / pixelsPerDegree;
    }

    /** Fractional column whose centre is at integer + 0.5 for a given azimuth (any wrapping). */
    public double columnOf(double azimuthDeg) {
        double az = ((azimuthDeg % 360) + 360) % 360;
        return az * pixelsPerDegree;
    }

    /** Fractional row (row r spans [r, r+1)) of an elevation. */
    public double rowOf(double elevationDeg) {
        return (topElevationDeg - elevationDeg) * pixelsPerDegree;
    }
}
