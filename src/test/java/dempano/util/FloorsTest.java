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
}
