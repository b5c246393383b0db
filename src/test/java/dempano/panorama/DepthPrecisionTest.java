package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Depth precision with near plane 1 m at 1–300 km, per mode: the value each mode stores (24-bit
 * window depth; float32 n/z; float32 range), read back and linearized, against the true distance.
 * The bound each mode must stay under is in the table; the 24-bit mode's large error is asserted
 * to be there, not hidden.
 */
class DepthPrecisionTest {
    static final double NEAR = 1, FAR = 330_000;

    @ParameterizedTest(name = "{0} m: standard24 off by {1}–{2} m, reversed32f and shader within {3} m")
    @CsvSource({
        // distance, 24-bit error at least, 24-bit error at most, float modes at most (metres)
        "1000,       0.005,    0.04,   0.0002",
        "10000,      1,        3.5,    0.002",
        "50000,      30,       80,     0.01",
        "100000,     100,      320,    0.02",
        "200000,     500,      1300,   0.04",
        "300000,     1200,     2900,   0.06",
    })
    void errorAtDistance(double z, double min24, double max24, double maxFloat) {
        // Worst case over distances spanning two 24-bit steps above z (rounding depends on the exact value).
        double step = z * z / NEAR * Math.pow(2, -24);
        double worst24 = 0, worstReversed = 0, worstShader = 0;
        for (int i = 0; i < 200; i++) {
            double zi = z + i * 2 * step / 200;
            double d24 = DepthLinearizer.quantize24(DepthLinearizer.standardDepthBufferValue(zi, NEAR, FAR));
            worst24 = Math.max(worst24, Math.abs(DepthLinearizer.standardEyeDepth(d24, NEAR, FAR) - zi));
            float dRev = (float) DepthLinearizer.reversedDepthBufferValue(zi, NEAR);
            worstReversed = Math.max(worstReversed, Math.abs(DepthLinearizer.reversedEyeDepth(dRev, NEAR) - zi));
            float range = (float) zi;
            worstShader = Math.max(worstShader, Math.abs(range - zi));
        }
        // 24-bit: one step of 2⁻²⁴ in window depth is z²/n · 2⁻²⁴ metres; half a step on average.
        assertTrue(worst24 >= min24 && worst24 <= max24, "standard24 at " + z + " m: " + worst24 + " m");
        assertTrue(worstReversed <= maxFloat, "reversed32f at " + z + " m: " + worstReversed + " m");
        assertTrue(worstShader <= maxFloat, "shader at " + z + " m: " + worstShader + " m");
    }
}
