package dempano.util;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class FloorsTest {
    @Test
    void agreesWithMathFloorOnEdgeCases() {
        double[] xs = {0.0, -0.0, 0.5, -0.5, 1, -1, 1 - 1e-16, -1 + 1e-16, -1e-300, Double.MIN_VALUE, -Double.MIN_VALUE,
                2.5, -2.5, 1e9 + 0.5, -1e9 - 0.5, Integer.MAX_VALUE, Integer.MAX_VALUE + 0.5, Integer.MAX_VALUE + 1.0,
                Integer.MIN_VALUE, Integer.MIN_VALUE - 0.5, Integer.MIN_VALUE - 1.0, Integer.MIN_VALUE + 0.5, -3e9, 3e9,
                1e300, -1e300, Double.MAX_VALUE, -Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.NaN, Math.nextDown(0.0), Math.nextUp(-1.0), Math.nextDown(-1.0)};
        for (double x : xs) {
            assertEquals((int) Math.floor(x), Floors.floorInt(x), "x = " + x);
        }
    }

    @Test
    void agreesWithMathFloorOnRandomDoubles() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int k = 0; k < 1_000_000; k++) {
            double x = switch (k % 3) {
                case 0 -> (rnd.nextDouble() - 0.5) * 1e4; // pixel and grid coordinates
                case 1 -> (rnd.nextDouble() - 0.5) * 1e10; // beyond the int range too
                default -> Double.longBitsToDouble(rnd.nextLong()); // any bit pattern
            };
            assertEquals((int) Math.floor(x), Floors.floorInt(x), "x = " + x);
        }
    }

    @Test
    void roundsNonNegativeValuesAsMathRound() {
        double[] xs = {0, -0.0, -1e-17, -0.25, -0.5, 0.5, 1.5, 2.5, 254.5, 255, 0.49999999999999994, Math.nextDown(0.5), Math.nextUp(0.5),
                Math.nextDown(254.5), Math.nextUp(254.5), 8388607.5, Double.MIN_VALUE,
                Math.nextDown((double) Integer.MAX_VALUE), Integer.MAX_VALUE - 1.5};
        for (double x : xs) {
            assertEquals(Math.round(x), Floors.roundNonNegative(x), "x = " + x);
        }
        SplittableRandom rnd = new SplittableRandom(11);
        for (int k = 0; k < 1_000_000; k++) {
            double x = k % 2 == 0 ? 255 * rnd.nextDouble() : Math.floor(256 * rnd.nextDouble()) + 0.5 + (rnd.nextInt(3) - 1) * 1e-14;
            assertEquals(Math.round(x), Floors.roundNonNegative(x), "x = " + x);
        }
    }

    @Test
    void refusesWhatItCannotRoundExactly() {
        for (double x : new double[] {Math.nextDown(-0.5), -1, Double.NaN, Integer.MAX_VALUE, 1e10, Double.POSITIVE_INFINITY}) {
            org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> Floors.roundNonNegative(x),
                    "x = " + x);
        }
    }
}
