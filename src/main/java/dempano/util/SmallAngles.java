package dempano.util;

/**
 * Arc tangents of small arguments without the library call: {@code Math.atan} and {@code Math.atan2} are
 * {@code StrictMath}'s native fdlibm code in JDK 17, called through JNI by both compilers, and the ray probe of
 * the exact distances takes two of them for every point it looks at (latitude and longitude).
 */
public final class SmallAngles {
    /** Below this magnitude {@link #atan} sums its series; above it, it calls {@link Math#atan}. */
    public static final double SERIES_LIMIT = 0.05;

    private SmallAngles() {
    }

    /**
     * atan x, radians: below {@link #SERIES_LIMIT} in magnitude by its Maclaurin series through x¹³ (the first
     * term left out is under 5e-20 of the sum there: within an ulp of {@link StrictMath#atan}, SmallAnglesTest),
     * else {@link Math#atan}. NaN stays NaN, −0 stays −0.
     */
    public static double atan(double x) {
        if (x == 0) {
            return x; // keeps −0 (the series would give +0)
        }
        if (!(Math.abs(x) < SERIES_LIMIT)) {
            return Math.atan(x);
        }
        double x2 = x * x;
        // atan x = x (1 − x²/3 + x⁴/5 − x⁶/7 + x⁸/9 − x¹⁰/11 + x¹²/13), Horner from the smallest term
        return x - x * x2 * (1.0 / 3 - x2 * (1.0 / 5 - x2 * (1.0 / 7 - x2 * (1.0 / 9 - x2 * (1.0 / 11 - x2 * (1.0 / 13))))));
    }

    /**
     * The angle of direction (x, y) from a reference direction, radians in [−π, π]: {@code atan2(y, x) − reference}
     * wrapped, for a reference given by its cosine and sine. The direction is turned back by the reference, then
     * within {@link #SERIES_LIMIT} radians (about 2.9°) of it the angle is {@link #atan}'s series of the small
     * remainder, else {@link Math#atan2} of the turned direction. Within 1e-15 rad of
     * {@code Math.atan2(y, x) − reference} (SmallAnglesTest: at most 9e-16 measured, most of it the rounding of
     * that difference itself near ±π; 6 nm on the ground).
     */
    public static double angleFrom(double y, double x, double cosReference, double sinReference) {
        double along = x * cosReference + y * sinReference, across = y * cosReference - x * sinReference;
        return Math.abs(across) < SERIES_LIMIT * along ? atan(across / along) : Math.atan2(across, along);
    }
}
