package dempano.panorama;

/**
 * The equirectangular layout of a panorama. Column c covers azimuth [c/ppd, (c+1)/ppd) degrees
 * clockwise from true north (pixel centre (c + 0.5)/ppd); row r has its centre at elevation
 * {@code topElevationDeg − (r + 0.5)/ppd} degrees above the eye's local horizontal.
 *
 * @param pixelsPerDegree  pixels per degree in both directions, in (0, 200], such that 360·ppd is a whole
 *                         number of columns; stored as {@link #checkedPixelsPerDegree normalized}
 *                         ({@code round(360·ppd)/360}), so 1.1 (whose binary value times 360 is
 *                         396.00000000000006) gives exactly 396 columns
 * @param topElevationDeg  elevation of the top edge of row 0, degrees
 * @param heightPx         number of rows
 */
public record PanoramaGeometry(double pixelsPerDegree, double topElevationDeg, int heightPx) {
    /** Azimuth of column 0's left edge, degrees: north. */
    public static final double LEFT_AZIMUTH_DEG = 0;

    /** How far 360·ppd may be from a whole number, relative to it: binary rounding of decimals like 1.1. */
    public static final double WHOLE_COLUMNS_TOLERANCE = 1e-9;

    public PanoramaGeometry {
        pixelsPerDegree = checkedPixelsPerDegree(pixelsPerDegree);
        if (!(topElevationDeg <= 90 && topElevationDeg - heightPx / pixelsPerDegree >= -90) || heightPx < 1) {
            throw new IllegalArgumentException("elevation range must lie within [-90°, 90°]: top " + topElevationDeg
                    + "°, " + heightPx + " rows");
        }
    }

    /**
     * A resolution checked and normalized: accepted when it is in (0, 200] and 360·ppd lies within a
     * relative {@link #WHOLE_COLUMNS_TOLERANCE} of a whole number n (decimals such as 1.1, 0.7 or 2.2
     * are not exact in binary); returns n/360, the value every width and angle is computed from.
     *
     * @throws IllegalArgumentException otherwise (NaN and infinities included), naming the rule and the value
     */
    public static double checkedPixelsPerDegree(double pixelsPerDegree) {
        double columns = 360 * pixelsPerDegree;
        double whole = Math.rint(columns);
        if (!(pixelsPerDegree > 0 && pixelsPerDegree <= 200) || whole < 1
                || Math.abs(columns - whole) > WHOLE_COLUMNS_TOLERANCE * whole) {
            throw new IllegalArgumentException("pixels per degree must be in (0, 200] and give a whole number of columns"
                    + " over 360° (360 × ppd a whole number), got " + pixelsPerDegree
                    + (pixelsPerDegree > 0 && pixelsPerDegree <= 200 ? " (360 × ppd = " + columns + ")" : ""));
        }
        return whole / 360;
    }

    /** A layout covering [bottomDeg, topDeg] in elevation (rounded outward to whole pixels). */
    public static PanoramaGeometry of(double pixelsPerDegree, double bottomDeg, double topDeg) {
        pixelsPerDegree = checkedPixelsPerDegree(pixelsPerDegree);
        if (!(topDeg > bottomDeg)) {
            throw new IllegalArgumentException("elevation range needs top > bottom, got " + bottomDeg + ":" + topDeg);
        }
        if (!(topDeg <= 90 && bottomDeg >= -90)) {
            throw new IllegalArgumentException("elevation range must lie within [-90°, 90°], got " + bottomDeg + ":" + topDeg);
        }
        int rows = (int) Math.ceil((topDeg - bottomDeg) * pixelsPerDegree - 1e-9);
        double reached = topDeg - rows / pixelsPerDegree;
        if (reached < -90) {
            // Whole rows of 1/ppd degree from the top: the last one may reach further down than the range asked.
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT, "elevation range %s:%s at %s pixels"
                    + " per degree takes %d whole rows from the top, which reach down to %.4f°, below -90°: raise the"
                    + " bottom or choose pixels per degree that fit the range in whole rows", bottomDeg, topDeg,
                    pixelsPerDegree, rows, reached));
        }
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
        double az = dempano.geo.Angles.wrap360(azimuthDeg);
        return az * pixelsPerDegree;
    }

    /** Fractional row (row r spans [r, r+1)) of an elevation. */
    public double rowOf(double elevationDeg) {
        return (topElevationDeg - elevationDeg) * pixelsPerDegree;
    }
}
