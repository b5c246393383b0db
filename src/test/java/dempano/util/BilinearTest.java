package dempano.util;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BilinearTest {
    @ParameterizedTest(name = "({0}, {1})")
    @CsvSource({"0, 0", "0, 1", "1, 0", "1, 1", "0.5, 0.5", "0.25, 0.75", "-0.5, 1.5"})
    void aBilinearSurfaceIsReproduced(double fr, double fc) {
        // h = 100 + 7·r − 3·c + 2·r·c: bilinear, so interpolation from the corners gives it back (and extends it).
        java.util.function.DoubleBinaryOperator h = (r, c) -> 100 + 7 * r - 3 * c + 2 * r * c;
        assertEquals(h.applyAsDouble(fr, fc), Bilinear.interpolate(h.applyAsDouble(0, 0), h.applyAsDouble(0, 1),
                h.applyAsDouble(1, 0), h.applyAsDouble(1, 1), fr, fc), 1e-12);
    }

    @ParameterizedTest
    @CsvSource({"0, 0, 1", "0, 1, 2", "1, 0, 3", "1, 1, 4", "0.5, 0.5, 2.5"})
    void cornersAreExactAndTheCentreIsTheMean(double fr, double fc, double expected) {
        assertEquals(expected, Bilinear.interpolate(1, 2, 3, 4, fr, fc), 0);
    }
}
