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
        return 2 * r * Math.asin(Math.min(1, chordMetres / (2 * r)));
    }

    /** Ground distance (metres, as above) between two points' feet on the ellipsoid, given in ECEF metres. */
    public static double groundDistanceBetweenFeetMetres(double[] footA, double[] footB) {
        double dx = footA[0] - footB[0], dy = footA[1] - footB[1], dz = footA[2] - footB[2];
        return groundDistanceFromChordMetres(Math.sqrt(dx * dx + dy * dy + dz * dz));
    }
}
