package dempano.util;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class DecimalsTest {
    @ParameterizedTest(name = "''{0}'' → {1}")
    @CsvSource({"46, true", "-46.5, true", "+.5, true", "5., true", "1e3, true", "4.049E+3, true", "1e999, true",
        "0x1p5, false", "0x2B, false", "46d, false", "43.8f, false", "100D, false", "NaN, false", "Infinity, false",
        "4_6, false", "'46,5', false", "'', false", "' 46', false", "+-4, false", "., false", "1e, false", "e5, false"})
    void onlyPlainDecimalsAreTaken(String text, boolean plain) {
        assertEquals(plain, Decimals.isPlain(text));
    }

    @ParameterizedTest
    @CsvSource({"400, 10, 400", "0.1, 3, 0.1", "42949672.95, 10, 42949672.95", "8e7, 10, 80000000", "100, 3, 100",
        "123.456, 3, 123", "0.00012345, 2, 0.00012", "-2.50, 6, -2.5", "NaN, 3, NaN", "Infinity, 3, Infinity"})
    void numbersForMessagesAsPeopleWriteThem(double v, int digits, String written) {
        assertEquals(written, Decimals.shortest(v, digits));
    }
}
