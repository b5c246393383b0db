package dempano.util;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The series arc tangent against {@link StrictMath}: edge cases, and a million random arguments per range. */
class SmallAnglesTest {
    @ParameterizedTest(name = "atan({0})")
    @ValueSource(doubles = {0.0, 1e-300, -1e-300, 1e-8, -1e-8, 0.01, -0.01, 0.049999999999999996, -0.049999999999999996,
            0.05, -0.05, 0.051, 1, -1, 1e10, Double.MIN_VALUE, Double.MAX_VALUE, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY})
    void edgeCasesMatchStrictMath(double x) {
        assertEquals(StrictMath.atan(x), SmallAngles.atan(x), Math.ulp(StrictMath.atan(x)));
    }

    @Test
    void signedZeroAndNaNSurvive() {
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(SmallAngles.atan(-0.0)));
        assertTrue(Double.isNaN(SmallAngles.atan(Double.NaN)));
        assertTrue(Double.isNaN(SmallAngles.angleFrom(Double.NaN, 1, 1, 0)));
    }

    /** Within one ulp of StrictMath.atan over the whole series range (measured: 1 ulp at most). */
    @Test
    void seriesIsWithinAnUlp() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int i = 0; i < 1_000_000; i++) {
            double x = (2 * rnd.nextDouble() - 1) * SmallAngles.SERIES_LIMIT;
            double exact = StrictMath.atan(x);
            assertEquals(exact, SmallAngles.atan(x), Math.ulp(exact), () -> "atan(" + x + ")");
        }
    }

    /**
     * Directions at any angle from references at any angle: the angle from the reference agrees with
     * StrictMath.atan2's difference, wrapped, within 1e-15 rad (measured 9e-16: the turn's rounding, and the
     * difference of atan2 and a reference near ±π itself carries a few ulp of π).
     */
    @Test
    void angleFromAReferenceMatchesTheDifferenceOfAtan2() {
        SplittableRandom rnd = new SplittableRandom(11);
        double worstSmall = 0, worstAny = 0;
        for (int i = 0; i < 1_000_000; i++) {
            double ref = (2 * rnd.nextDouble() - 1) * Math.PI;
            // Half the draws within the series range of the reference, half anywhere.
            double delta = i % 2 == 0 ? (2 * rnd.nextDouble() - 1) * 0.06 : (2 * rnd.nextDouble() - 1) * Math.PI;
            double r = 6.4e6 * (0.5 + rnd.nextDouble());
            double x = r * StrictMath.cos(ref + delta), y = r * StrictMath.sin(ref + delta);
            double expected = StrictMath.atan2(y, x) - ref;
            expected -= 2 * Math.PI * Math.rint(expected / (2 * Math.PI));
            double got = SmallAngles.angleFrom(y, x, StrictMath.cos(ref), StrictMath.sin(ref));
            double err = Math.abs(got - expected);
            if (Math.abs(delta) < 0.06) {
                worstSmall = Math.max(worstSmall, err);
            } else {
                worstAny = Math.max(worstAny, Math.min(err, 2 * Math.PI - err));
            }
        }
        assertTrue(worstSmall < 1e-15, "near the reference: " + worstSmall);
        assertTrue(worstAny < 2e-15, "anywhere: " + worstAny);
    }
}
