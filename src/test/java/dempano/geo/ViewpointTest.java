package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileId;
import java.util.List;
import org.junit.jupiter.api.Test;

class ViewpointTest {
    private static Mosaic plane() {
        int n = 121;
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                h[r * n + c] = 1000 + 10 * c; // rises 10 m per sample eastward
            }
        }
        return Mosaic.around(new InMemoryDem("plane", List.of(HgtTile.of(new TileId(46, 8), n, h, "plane"))),
                46.5, 8.5, 5000, MissingTilePolicy.ERROR);
    }

    /**
     * A viewpoint whose ground is a filled void (a summit the DEM lost: its height invented, hundreds of metres low) is
     * said, where its altitude comes from the DEM; one sample away from the void, or with an absolute altitude, nothing.
     */
    @Test
    void aViewpointStandingInAFilledVoidIsSaid() {
        int n = 121;
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                // A void 11 × 11 samples around the tile's centre (sample 60, 60 = 46.5 N, 8.5 E).
                h[r * n + c] = Math.abs(r - 60) <= 5 && Math.abs(c - 60) <= 5 ? Float.NaN : 1000 + 10 * c;
            }
        }
        Mosaic m = Mosaic.around(new InMemoryDem("voids", List.of(HgtTile.of(new TileId(46, 8), n, h, "voids"))),
                46.5, 8.5, 5000, MissingTilePolicy.ERROR);
        String w = Viewpoint.onDem(m, 46.5, 8.5, 0, 2).filledVoidWarning(m).orElseThrow();
        assertTrue(w.startsWith("the viewpoint stands in a void of the DEM, filled by interpolation: its ground (1600.0 m)"), w);
        // The void's last column is sample 65; between samples 65 and 66 one of the four is still a void.
        assertTrue(Viewpoint.onDem(m, 46.5, 8 + 65.5 / 120, 0, 2).filledVoidWarning(m).isPresent());
        assertTrue(Viewpoint.onDem(m, 46.5, 8 + 66.5 / 120, 0, 2).filledVoidWarning(m).isEmpty(), "beside the void");
        assertTrue(Viewpoint.atAltitude(m, 46.5, 8.5, 1700, 2).filledVoidWarning(m).isEmpty(), "an altitude given");
    }

    @Test
    void altitudeFromDemPlusOffsetPlusEyeHeight() {
        Viewpoint v = Viewpoint.onDem(plane(), 46.5, 8.5, 30, 1.7);
        assertEquals(1600, v.groundElevationMetres(), 1e-9);
        assertEquals(1630, v.standingAltitudeMetres(), 1e-9);
        assertEquals(1631.7, v.eyeAltitudeMetres(), 1e-9);
        // A negative offset lowers the eye, down to the surface (0.5 m of tolerance) and no further.
        assertEquals(1599.7, Viewpoint.onDem(plane(), 46.5, 8.5, -2, 1.7).eyeAltitudeMetres(), 1e-9);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Viewpoint.onDem(plane(), 46.5, 8.5, -30, 1.7));
        assertTrue(e.getMessage().contains("28.3 m below the DEM surface"), e.getMessage());
    }

    @Test
    void explicitAltitudeIgnoresDemButKeepsEyeHeight() {
        Viewpoint v = Viewpoint.atAltitude(plane(), 46.5, 8.5, 3000, 2);
        assertEquals(1600, v.groundElevationMetres(), 1e-9);
        assertEquals(3002, v.eyeAltitudeMetres(), 1e-9);
        assertTrue(Double.isNaN(v.offsetMetres()));
    }

    @Test
    void badValuesAreClearErrors() {
        Mosaic m = plane();
        assertThrows(IllegalArgumentException.class, () -> Viewpoint.onDem(m, 46.5, 8.5, Double.NaN, 2));
        assertThrows(IllegalArgumentException.class, () -> Viewpoint.onDem(m, 46.5, 8.5, 0, -1));
        assertThrows(IllegalArgumentException.class, () -> Viewpoint.atAltitude(m, 46.5, 8.5, Double.POSITIVE_INFINITY, 2));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Viewpoint.onDem(m, 40, 8.5, 0, 2));
        assertTrue(e.getMessage().contains("no height"), e.getMessage());
    }
}
