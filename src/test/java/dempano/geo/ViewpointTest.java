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
