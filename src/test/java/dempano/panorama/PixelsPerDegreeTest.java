package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRequest;
import java.math.BigDecimal;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** --ppd values: decimal resolutions whose 360·ppd is whole are accepted despite binary rounding. */
class PixelsPerDegreeTest {
    @ParameterizedTest
    @ValueSource(strings = {"1.1", "0.7", "2.2", "20", "0.5", "0.1", "12.3", "199.9", "200", "0.025"})
    void wholeColumnCountsAreAcceptedAndExact(String ppd) {
        // Truth: the decimal product 360 × ppd, computed exactly (BigDecimal), rounded to a whole number of columns.
        int width = new BigDecimal("360").multiply(new BigDecimal(ppd)).setScale(0, java.math.RoundingMode.HALF_EVEN)
                .intValueExact();
        double value = Double.parseDouble(ppd);
        PanoramaGeometry g = PanoramaGeometry.of(value, -10, 10);
        assertEquals(width, g.widthPx(), ppd);
        assertEquals(width / 360.0, g.pixelsPerDegree(), 0, ppd);
        assertEquals(360.0, g.azimuthOfColumn(width - 1) + 0.5 / g.pixelsPerDegree(), 1e-9, ppd);
        assertEquals(Math.ceil(20 * width / 360.0 - 1e-6), g.heightPx(), 1, ppd);
        PanoramaRequest r = PanoramaRequest.at(46.43, 8.09).withPixelsPerDegree(value);
        assertEquals(g.pixelsPerDegree(), r.pixelsPerDegree(), 0, "request and geometry hold the same ppd");
    }

    @ParameterizedTest
    @CsvSource({"1.1, 396", "0.7, 252", "2.2, 792", "20, 7200", "0.5, 180"})
    void theIssuesExamples(double ppd, int width) {
        assertEquals(width, new PanoramaGeometry(ppd, 10, 4).widthPx());
    }

    @ParameterizedTest
    @ValueSource(doubles = {1.0001, 0.3333, 20.001, 1.1 + 1e-6, 0.001, 0, -1, 200.5, Double.NaN,
            Double.POSITIVE_INFINITY, Double.MIN_VALUE})
    void otherValuesAreRefusedNamingTheRule(double ppd) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PanoramaGeometry.of(ppd, -10, 10));
        assertTrue(e.getMessage().contains("whole number of columns") && e.getMessage().contains(String.valueOf(ppd)),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> PanoramaRequest.at(46.43, 8.09).withPixelsPerDegree(ppd));
        assertTrue(e.getMessage().contains("whole number of columns"), e.getMessage());
    }
}
