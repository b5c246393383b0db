package dempano.util;

/**
 * {@code (int) Math.floor(x)} without the call: the client compiler (C1, the start script's) does not inline
 * {@link Math#floor} but calls {@code StrictMath.floor}, which took 8 % of the stitch's CPU time at Mount Washington.
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
}
