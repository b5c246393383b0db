package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class AnglesTest {
    @ParameterizedTest(name = "wrap360({0}) = {1}")
    @CsvSource({
            "0, 0", "-0.0, 0", "359.5, 359.5", "360, 0", "720, 0", "-360, 0", "-90, 270", "-450, 270", "1e9, 280",
            "-1e-14, 0", // 360 − 1e-14 rounds to 360
            "-1e-12, 359.999999999999", "45.25, 45.25", "405.25, 45.25",
    })
    void wrap360(double deg, double expected) {
        double got = Angles.wrap360(deg);
        assertEquals(expected, got, 1e-9);
        assertTrue(got >= 0 && got < 360, "in [0, 360): " + got);
        assertEquals(0, Double.compare(Math.abs(got), got), "no −0: " + got);
    }

    @ParameterizedTest(name = "wrap180({0}) = {1}")
    @CsvSource({
            "0, 0", "180, -180", "-180, -180", "179.5, 179.5", "181, -179", "-181, 179", "540, -180", "360, 0",
            "-71.48, -71.48", "288.52, -71.48",
    })
    void wrap180(double deg, double expected) {
        double got = Angles.wrap180(deg);
        assertEquals(expected, got, 1e-12);
        assertTrue(got >= -180 && got < 180, "in [-180, 180): " + got);
    }

    @Test
    void notANumberAndInfinitiesGiveNotANumber() {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            assertTrue(Double.isNaN(Angles.wrap360(bad)), "wrap360(" + bad + ")");
            assertTrue(Double.isNaN(Angles.wrap180(bad)), "wrap180(" + bad + ")");
        }
    }

    @Test
    void aWholeNumberOfTurnsAwayIsTheSameAngleExactly() {
        java.util.Random rnd = new java.util.Random(5);
        for (int i = 0; i < 10_000; i++) {
            double a = rnd.nextDouble() * 360; // exact multiples of 360 added to a value below 2^44: exact sums
            int turns = rnd.nextInt(21) - 10;
            assertEquals(a == 360 ? 0 : a, Angles.wrap360(a + 360.0 * turns), Math.ulp(360.0) * 16, a + " + " + turns + " turns");
        }
    }
}
