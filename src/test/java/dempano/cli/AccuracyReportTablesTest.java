package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.panorama.DistanceComparison;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class AccuracyReportTablesTest {
    @ParameterizedTest
    @CsvSource(delimiter = ';', value = {
        "1359; -0.2012; 0; 1359 m (−20.12 %)",
        "1812; 0.0652; 0; 1812 m (+6.52 %)",
        "26204; -0.1386; 647; 26204 m (−13.86 %), sky 647",
        "NaN; NaN; 7200; sky"})
    void aHorizonCellReadsDistanceSignedErrorAndSkyColumns(double metres, double signed, long sky, String expected) {
        var row = new DistanceComparison.HorizonRow(0, 7200, sky, 1701, metres, signed, Math.abs(signed));
        assertEquals(expected, AccuracyReport.horizonCell(row));
    }

    @Test
    void theIncidenceTableNamesItsBinsWithTheirPixelCounts() {
        List<DistanceComparison.IncidenceBin> bins = List.of(
                new DistanceComparison.IncidenceBin(0, 0.5, 12, 0.01, 0.2),
                new DistanceComparison.IncidenceBin(0.5, 2, 0, Double.NaN, Double.NaN),
                new DistanceComparison.IncidenceBin(2, 10, 5, 1e-5, 1e-4),
                new DistanceComparison.IncidenceBin(10, Double.POSITIVE_INFINITY, 7, 0, 0));
        var row = new AccuracyReport.Row(null, null, 1, null, bins, List.of(), Double.NaN);
        String table = AccuracyReport.incidenceTable(List.of(row));
        assertTrue(table.contains("| setting | < 0.5° (12 px) | 0.5–2° (0 px) | 2–10° (5 px) | ≥ 10° (7 px) |"), table);
        assertTrue(table.contains("| CPU reference | 1.00 % / 20.00 % | – / – | 1.0e-03 % / 1.0e-02 % | 0.0e+00 % / 0.0e+00 % |"), table);
    }
}
