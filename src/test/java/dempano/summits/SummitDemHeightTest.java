package dempano.summits;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.TileId;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The DEM's height at each summit and whether a filled void lies under it. */
class SummitDemHeightTest {
    private static final int N = 121; // 30″ samples: 1/120 degree

    /** A plane rising 1 m per sample eastward and 2 m per sample southward, with a void of rows/cols 40…60. */
    private static InMemoryDem dem() {
        float[] h = new float[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                boolean hole = r >= 40 && r <= 60 && c >= 40 && c <= 60;
                h[r * N + c] = hole ? Float.NaN : 1000 + c + 2 * r;
            }
        }
        return new InMemoryDem("plane", List.of(HgtTile.of(TileId.of(46, 8), N, h, "plane")));
    }

    private static SummitSighting sighting(double lat, double lon) {
        return new SummitSighting(new Summit("S", lat, lon, 2000), 0, 0, 0, 0, 1000, 1000, 1000, 1000, true);
    }

    @Test
    void heightsComeFromTheDemAndVoidsAreMarked() {
        // Row 10.5, column 20.25 (valid data): bilinear on the plane = 1000 + 20.25 + 21.
        double latValid = 47 - 10.5 / 120.0, lonValid = 8 + 20.25 / 120.0;
        // Row 50, column 50 (the void's middle): the thin-plate fill restores the plane there.
        double latVoid = 47 - 50 / 120.0, lonVoid = 8 + 50 / 120.0;
        // Row 39.5 (between the last valid row and the void's first): next to the void counts.
        double latEdge = 47 - 39.5 / 120.0;
        List<SummitSighting> out = SummitProjector.withDem(List.of(sighting(latValid, lonValid),
                sighting(latVoid, lonVoid), sighting(latEdge, lonVoid), sighting(45.5, 8.5)), dem());
        assertEquals(1041.25, out.get(0).demHeightMetres(), 1e-3);
        assertFalse(out.get(0).inFilledVoid());
        assertEquals(1150, out.get(1).demHeightMetres(), 0.05);
        assertTrue(out.get(1).inFilledVoid());
        assertTrue(out.get(2).inFilledVoid());
        assertEquals(1000 + 50 + 79, out.get(2).demHeightMetres(), 0.05);
        // No tile there: not looked up.
        assertTrue(Double.isNaN(out.get(3).demHeightMetres()));
        assertFalse(out.get(3).inFilledVoid());
        // Everything else is kept.
        assertEquals(out.get(0).summit(), sighting(latValid, lonValid).summit());
        assertTrue(out.get(0).visible());
    }
}
