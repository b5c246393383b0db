package dempano.util;

/**
 * {@code (int) Math.floor(x)} and {@code Math.round(x)} without the calls: the client compiler (C1, the start
 * script's) inlines neither but calls {@code StrictMath.floor} (8 % of the stitch's CPU time at Mount Washington) and
 * {@code Math.round} (2 % of a batch's, in the distance picture's colours).
 */
public final class Floors {
    private Floors() {
    }

    /**
     * Exactly {@code (int) Math.floor(x)} for every double: the largest int not above x, {@link Integer#MIN_VALUE}
     * below its range (and for −∞), {@link Integer#MAX_VALUE} above it (and for +∞), 0 for NaN.
     */
    public static int floorInt(double x) {
        int i = (int) x; // toward zero, saturating, NaN → 0
        // Only a negative non-integer is truncated upward; below the int range the cast already saturated.
        return x < i && i != Integer.MIN_VALUE ? i - 1 : i;
    }

    /**
     * Exactly {@code (int) Math.round(x)} (round half up) for x in [−½, 2³¹ − 1): values that are non-negative but
     * for rounding noise. The whole part and the fraction are exact in a double there, so the fraction decides;
     * {@code (int) (x + 0.5)} is not exact (0.49999999999999994 + 0.5 rounds to 1).
     *
     * @throws IllegalArgumentException outside that range (NaN included)
     */
    public static int roundNonNegative(double x) {
        if (!(x >= -0.5 && x < Integer.MAX_VALUE)) {
            throw new IllegalArgumentException("not in [-0.5, 2^31 - 1): " + x);
        }
        int i = (int) x;
        return x - i >= 0.5 ? i + 1 : i;
    }
}
