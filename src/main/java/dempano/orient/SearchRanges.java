package dempano.orient;

/**
 * Where a photo's estimate searches, for values the flags and the metadata leave open or give only roughly
 * ({@code --heading-range-deg}, {@code --hfov-range-deg}, {@code --focal35-range-mm}); NaN = not given.
 *
 * @param headingRangeDeg the heading lies within ± this of the one given (flag or EXIF compass), degrees, (0, 180]
 * @param hfovMinDeg      smallest horizontal field of view searched, degrees; with {@code hfovMaxDeg},
 *                        0 &lt; min ≤ max &lt; 180
 * @param hfovMaxDeg      largest, degrees
 * @param focal35MinMm    shortest 35 mm-equivalent focal length (diagonal definition), mm, &gt; 0: a zoom lens's range,
 *                        turned into a field-of-view range with the image's shape ({@link #hfovRangeDeg}); with
 *                        {@code focal35MaxMm}, min ≤ max; not with a field-of-view range
 * @param focal35MaxMm    longest, mm
 */
public record SearchRanges(double headingRangeDeg, double hfovMinDeg, double hfovMaxDeg, double focal35MinMm,
                           double focal35MaxMm) {
    /** Nothing given: a given heading taken as it is, any field of view the estimator searches. */
    public static final SearchRanges NONE = new SearchRanges(Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);

    public SearchRanges {
        if (!Double.isNaN(headingRangeDeg) && !(headingRangeDeg > 0 && headingRangeDeg <= 180)) {
            throw new IllegalArgumentException("--heading-range-deg must be in (0°, 180°], got " + headingRangeDeg);
        }
        if (Double.isNaN(hfovMinDeg) != Double.isNaN(hfovMaxDeg)
                || !Double.isNaN(hfovMinDeg) && !(hfovMinDeg > 0 && hfovMinDeg <= hfovMaxDeg && hfovMaxDeg < 180)) {
            throw new IllegalArgumentException("--hfov-range-deg must be MIN,MAX with 0 < MIN ≤ MAX < 180 degrees, got "
                    + hfovMinDeg + "," + hfovMaxDeg);
        }
        if (Double.isNaN(focal35MinMm) != Double.isNaN(focal35MaxMm) || !Double.isNaN(focal35MinMm)
                && !(focal35MinMm > 0 && focal35MinMm <= focal35MaxMm && focal35MaxMm < 1e5)) {
            throw new IllegalArgumentException("--focal35-range-mm must be MIN,MAX with 0 < MIN ≤ MAX millimetres, got "
                    + focal35MinMm + "," + focal35MaxMm);
        }
        if (!Double.isNaN(hfovMinDeg) && !Double.isNaN(focal35MinMm)) {
            throw new IllegalArgumentException("give --hfov-range-deg or --focal35-range-mm, not both");
        }
    }

    /** The same with a heading range (NaN: none). */
    public SearchRanges withHeadingRangeDeg(double v) {
        return new SearchRanges(v, hfovMinDeg, hfovMaxDeg, focal35MinMm, focal35MaxMm);
    }

    /** Whether a field-of-view or focal-length range is given. */
    public boolean hasFovRange() {
        return !Double.isNaN(hfovMinDeg) || !Double.isNaN(focal35MinMm);
    }

    /**
     * The horizontal field-of-view range searched for an image of {@code widthPx} × {@code heightPx} pixels, degrees
     * {min, max}: the one given, or the focal range's (the camera model's {@link
     * dempano.camera.CameraIntrinsics#fromFocal35mm 35 mm equivalent}: f spans the image's diagonal as f spans
     * 43.27 mm; the longer focal length the narrower);
     * null where neither is given.
     */
    public double[] hfovRangeDeg(int widthPx, int heightPx) {
        if (!Double.isNaN(hfovMinDeg)) {
            return new double[] {hfovMinDeg, hfovMaxDeg};
        }
        if (Double.isNaN(focal35MinMm)) {
            return null;
        }
        return new double[] {hfovOf(focal35MaxMm, widthPx, heightPx), hfovOf(focal35MinMm, widthPx, heightPx)};
    }

    private static double hfovOf(double focal35Mm, int widthPx, int heightPx) {
        return dempano.camera.CameraIntrinsics.fromFocal35mm(widthPx, heightPx, focal35Mm).horizontalFovDeg();
    }

    /** How the range reads in a log line, e.g. "24–70 mm (35 mm equivalent): 28.8°–73.7°". */
    public String describeFov(int widthPx, int heightPx) {
        double[] r = hfovRangeDeg(widthPx, heightPx);
        String fov = String.format(java.util.Locale.ROOT, "%.1f°–%.1f°", r[0], r[1]);
        return Double.isNaN(focal35MinMm) ? fov + " (--hfov-range-deg)" : String.format(java.util.Locale.ROOT,
                "%s, a focal length of %s–%s mm (35 mm equivalent, --focal35-range-mm)", fov,
                dempano.camera.PhotoMetadata.num(focal35MinMm), dempano.camera.PhotoMetadata.num(focal35MaxMm));
    }
}
