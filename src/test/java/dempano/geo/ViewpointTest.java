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
    /** Tile N46E008 of 121² samples, height(row, column) metres (row 0 north), as a mosaic around its centre. */
    private static Mosaic tile(String name, java.util.function.IntBinaryOperator height) {
        int n = 121;
        float[] h = new float[n * n];
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                int v = height.applyAsInt(r, c);
                h[r * n + c] = v == VOID ? Float.NaN : v;
            }
        }
        return Mosaic.around(new InMemoryDem(name, List.of(HgtTile.of(new TileId(46, 8), n, h, name))),
                46.5, 8.5, 5000, MissingTilePolicy.ERROR);
    }

    private static Mosaic plane() {
        return tile("plane", (r, c) -> 1000 + 10 * c); // rises 10 m per sample eastward
    }

    /** A height of {@link #tile} that is a void. */
    private static final int VOID = Integer.MIN_VALUE;

    /**
     * A viewpoint whose ground is a filled void (a summit the DEM lost: its height invented, hundreds of metres low) is
     * said, where its altitude comes from the DEM; one sample away from the void, or with an absolute altitude, nothing.
     */
    @Test
    void aViewpointStandingInAFilledVoidIsSaid() {
        // A void 11 × 11 samples around the tile's centre (sample 60, 60 = 46.5 N, 8.5 E).
        Mosaic m = tile("voids", (r, c) -> Math.abs(r - 60) <= 5 && Math.abs(c - 60) <= 5 ? VOID : 1000 + 10 * c);
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
        // A negative offset lowers the eye, down to 0.1 m above the surface and no further: on it (an eye height of 0)
        // the ground under it cannot be drawn (GL showed sky where the CPU reference met the ground at its feet).
        assertEquals(1600.1, Viewpoint.onDem(plane(), 46.5, 8.5, -1.6, 1.7).eyeAltitudeMetres(), 1e-9);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Viewpoint.onDem(plane(), 46.5, 8.5, -30, 1.7));
        assertTrue(e.getMessage().contains("28.3 m below the DEM surface"), e.getMessage());
        for (double[] offsetAndHeight : new double[][] {{0, 0}, {-1.65, 1.7}, {-2, 1.7}}) {
            EyeBelowGroundException low = org.junit.jupiter.api.Assertions.assertThrows(EyeBelowGroundException.class,
                    () -> Viewpoint.onDem(plane(), 46.5, 8.5, offsetAndHeight[0], offsetAndHeight[1]));
            assertTrue(low.getMessage().contains(offsetAndHeight[0] + offsetAndHeight[1] < 0 ? "below the DEM surface"
                    : "above the DEM surface (1600.00 m) at 46.500000, 8.500000, where the ground under it cannot be drawn"),
                    low.getMessage());
        }
    }

    /**
     * The ground is the drawn surface (the triangle of the cell holding the point), not the bilinear height: on samples
     * alternating 1050 / 950 m every cell's diagonal joins two 1050 m corners, so the drawn surface is 1050 m at every
     * cell's centre where the bilinear height is 1000 m, and an eye 2 m above that stood 48 m inside the drawn terrain.
     */
    @Test
    void theGroundIsTheDrawnSurfaceNotTheBilinearHeight() {
        Mosaic m = tile("twisted", (r, c) -> (r + c) % 2 == 0 ? 1050 : 950);
        for (int[] cell : new int[][] {{60, 60}, {60, 61}, {13, 100}}) { // both splits
            double lat = 47 - (cell[0] + 0.5) / 120, lon = 8 + (cell[1] + 0.5) / 120;
            Viewpoint v = Viewpoint.onDem(m, lat, lon, 0, 2);
            assertEquals(1050, v.groundElevationMetres(), 1e-6, java.util.Arrays.toString(cell));
            assertEquals(1052, v.eyeAltitudeMetres(), 1e-6);
            // Off the diagonal, halfway to a 950 m corner (a quarter of the cell south, three quarters east of the
            // north-west corner where the diagonal runs NW–SE, a quarter east where it runs NE–SW): 1000 m.
            assertEquals(1000, m.heightAt(47 - (cell[0] + 0.25) / 120, lon + ((cell[0] + cell[1]) % 2 == 0 ? 0.25 : -0.25) / 120),
                    1e-6);
        }
        // On a sample and on an edge: the samples (and the edge's two), as every triangle holding the point has them.
        assertEquals(1050, m.heightAt(47 - 60.0 / 120, 8 + 60.0 / 120), 1e-6);
        assertEquals(1000, m.heightAt(47 - 60.0 / 120, 8 + 60.5 / 120), 1e-6);
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
