package dempano.geo;

/**
 * Angles in degrees brought into one turn: one implementation for the azimuths, headings and longitudes that had a
 * copy each. Not GeographicLib's {@code GeoMath.AngNormalize}: its (−180°, 180°] puts the antimeridian at +180°,
 * where the tile grid and the azimuth sectors want −180° (the western edge of the westernmost tile). Stateless.
 */
public final class Angles {
    private Angles() {
    }

    /**
     * {@code deg} in [0°, 360°), degrees: exact (a floating-point remainder is), −0° gives 0°, NaN and ±∞ give NaN.
     * A tiny negative angle whose sum with 360° rounds to 360° gives 0°.
     */
    public static double wrap360(double deg) {
        double d = deg % 360;
        if (d < 0) {
            d += 360;
        }
        return d >= 360 ? 0 : d + 0.0;
    }

    /**
     * {@code deg} in [−180°, 180°), degrees (+180° gives −180°); NaN and ±∞ give NaN. Computed as
     * {@code wrap360(deg + 180) − 180}, so exact where {@code deg + 180} is.
     */
    public static double wrap180(double deg) {
        return wrap360(deg + 180) - 180;
    }
}
