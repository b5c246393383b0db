package dempano.geo;

/**
 * Standard terrestrial refraction as an apparent lift of distant points: a point at ground distance
 * d appears raised by k·d²/(2R), R being the mean earth radius
 * ({@link Ellipsoid#MEAN_RADIUS_METRES}). k = 0.13 is the usual daytime value (and the reference
 * panorama generator's); k = 0 switches refraction off.
 *
 * @param coefficient k, dimensionless, finite and in [-1, 1]
 */
public record Refraction(double coefficient) {
    /** k = 0.13. */
    public static final Refraction STANDARD = new Refraction(0.13);
    /** No refraction. */
    public static final Refraction NONE = new Refraction(0);

    public Refraction {
        if (!(coefficient >= -1 && coefficient <= 1)) {
            throw new IllegalArgumentException("refraction coefficient must be in [-1, 1], got " + coefficient);
        }
    }

    /** Apparent lift in metres of a point at the given ground distance (metres). */
    public double liftMetres(double groundDistanceMetres) {
        return coefficient * groundDistanceMetres * groundDistanceMetres / (2 * Ellipsoid.MEAN_RADIUS_METRES);
    }

    /**
     * Ground distance (metres) on the mean sphere from a chord between the two points' feet on the
     * ellipsoid; used where a geodesic per vertex would be too slow. Within 0.5 % of the geodesic
     * distance up to 500 km, which changes the lift by under 1 %.
     */
    public static double groundDistanceFromChordMetres(double chordMetres) {
        double r = Ellipsoid.MEAN_RADIUS_METRES;
        return 2 * r * asinOfHalfChord(Math.min(1, chordMetres / (2 * r)));
    }

    /** Below this sine {@link #asinOfHalfChord} sums its series (a chord of 637 km): no wider range is ever asked here. */
    static final double SERIES_LIMIT = 0.05;

    /**
     * asin x, for the half chords of ground distances: by its Maclaurin series through x¹¹ below
     * {@link #SERIES_LIMIT} (the next term is under 5e-18 of the sum there: within an ulp or two of
     * {@link Math#asin}, and a third of its time, which matters in the ray probe and per vertex),
     * else {@link Math#asin}. NaN stays NaN.
     */
    static double asinOfHalfChord(double x) {
        if (!(Math.abs(x) < SERIES_LIMIT)) {
            return Math.asin(x);
        }
        double x2 = x * x;
        // asin x = x (1 + x²/6 + 3x⁴/40 + 5x⁶/112 + 35x⁸/1152 + 63x¹⁰/2816 + …), Horner from the smallest term
        return x + x * x2 * (1.0 / 6 + x2 * (3.0 / 40 + x2 * (5.0 / 112 + x2 * (35.0 / 1152 + x2 * (63.0 / 2816)))));
    }

    /** Ground distance (metres, as above) between two points' feet on the ellipsoid, given in ECEF metres. */
    public static double groundDistanceBetweenFeetMetres(double[] footA, double[] footB) {
        double dx = footA[0] - footB[0], dy = footA[1] - footB[1], dz = footA[2] - footB[2];
        return groundDistanceFromChordMetres(Math.sqrt(dx * dx + dy * dy + dz * dz));
    }
}
