package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MosaicTest {
    private static final int N = 121; // small synthetic tiles: 120 intervals per degree

    /** A tile sampling f(lat, unwrapped lon) on its grid. */
    static HgtTile tile(int latS, int lonW, DoubleBinaryOperator f) {
        float[] h = new float[N * N];
        for (int r = 0; r < N; r++) {
            for (int c = 0; c < N; c++) {
                h[r * N + c] = (float) f.applyAsDouble(latS + 1 - r / 120.0, lonW + c / 120.0);
            }
        }
        return HgtTile.of(TileId.of(latS, lonW), N, h, "synthetic");
    }

    static DemSource blockAround(int latS, int lonW, int rows, int cols, DoubleBinaryOperator f) {
        List<HgtTile> tiles = new ArrayList<>();
        for (int i = 0; i < rows; i++) {
            for (int j = 0; j < cols; j++) {
                tiles.add(tile(latS + i, lonW + j, f));
            }
        }
        return new InMemoryDem("synthetic", tiles);
    }

    // Viewpoints across special meridians/parallels; the tile block around each: truth is f itself.
    @ParameterizedTest
    @CsvSource({
            "46.5, 8.5, 46, 8",      // mid-tile, Alps
            "0.2, 10.5, -1, 10",    // equator
            "51.5, 0.3, 51, -1",    // prime meridian
            "-15.5, 166.5, -16, 166", // southern hemisphere
            "10.5, 179.7, 10, 179",  // antimeridian, east side
            "10.5, -179.7, 10, 179", // antimeridian, west side (block starts at 179E, unwrapped)
    })
    void stitchesWithoutDuplicatingEdges(double lat, double lon, int blockLatS, int blockLonW) {
        // Linear inside every tile and continuous across 0° and ±180° (kinks only on tile edges).
        DoubleBinaryOperator f = (la, lo) -> 500 + 40 * la + 17 * Math.abs(dempano.geo.Angles.wrap180(lo));
        DemSource dem = blockAround(blockLatS - 1, blockLonW - 1, 4, 4, f);
        Mosaic m = Mosaic.around(dem, lat, lon, 60_000, MissingTilePolicy.ERROR);
        assertEquals(m.tilesNorthSouth() * 120 + 1, m.rows());
        assertEquals(m.tilesEastWest() * 120 + 1, m.cols());
        assertTrue(m.tilesMissing().isEmpty());
        Random rnd = new Random(7);
        for (int i = 0; i < 500; i++) {
            double la = lat + (rnd.nextDouble() - 0.5) * 0.9;
            double lo = lon + (rnd.nextDouble() - 0.5) * 0.9;
            double truth = f.applyAsDouble(la, lo);
            double got = m.heightAt(la, lo);
            if (!Double.isNaN(got)) {
                assertEquals(truth, got, 1e-3, "at " + la + ", " + lo);
            }
        }
        // The viewpoint itself is always defined, and samples line up exactly on the shared edges.
        assertEquals(f.applyAsDouble(lat, lon), m.heightAt(lat, lon), 1e-3);
    }

    @Test
    void sharedEdgeTakenOnceAndNotShifted() {
        // Each tile carries its own offset so a duplicated or shifted edge would show.
        DemSource dem = new InMemoryDem("two", List.of(
                tile(46, 8, (la, lo) -> 100 + 10 * lo), tile(46, 9, (la, lo) -> 100 + 10 * lo)));
        TileSelection sel = new TileSelection(46, 8, 1, 2, new boolean[][] {{true, true}});
        Mosaic m = Mosaic.of(dem, sel, MissingTilePolicy.ERROR);
        assertEquals(241, m.cols());
        for (int c = 0; c < m.cols(); c++) {
            assertEquals(100 + 10 * (8 + c / 120.0), m.sample(60, c), 1e-3, "col " + c);
        }
    }

    @Test
    void missingTileIsSeaLevelWithWarningOrAnError() {
        DemSource dem = new InMemoryDem("one", List.of(tile(46, 8, (la, lo) -> 700)));
        Mosaic m = Mosaic.around(dem, 46.5, 8.97, 20_000, MissingTilePolicy.SEA_LEVEL);
        assertEquals(List.of(new TileId(46, 9)), m.tilesMissing());
        assertEquals(List.of(new TileId(46, 8)), m.tilesUsed());
        assertTrue(m.warnings().stream().anyMatch(w -> w.contains("N46E009") && w.contains("sea level")));
        assertEquals(0, m.heightAt(46.5, 9.1), 0);
        assertEquals(700, m.heightAt(46.5, 9.0), 0, "the present tile wins on the shared edge");
        DemException e = assertThrows(DemException.class,
                () -> Mosaic.around(dem, 46.5, 8.97, 20_000, MissingTilePolicy.ERROR));
        assertTrue(e.getMessage().contains("N46E009"), e.getMessage());
    }

    @Test
    void entirelyVoidTileCountsAsMissing() {
        float[] voids = new float[N * N];
        java.util.Arrays.fill(voids, Float.NaN);
        DemSource dem = new InMemoryDem("void", List.of(HgtTile.of(new TileId(46, 8), N, voids, "void")));
        Mosaic m = Mosaic.around(dem, 46.5, 8.5, 10_000, MissingTilePolicy.SEA_LEVEL);
        assertEquals(List.of(new TileId(46, 8)), m.tilesMissing());
        assertTrue(m.warnings().stream().anyMatch(w -> w.contains("no valid sample")));
    }

    @Test
    void mixedResolutionsResampleToTheFinest() {
        int fine = 241;
        float[] h = new float[fine * fine];
        for (int r = 0; r < fine; r++) {
            for (int c = 0; c < fine; c++) {
                h[r * fine + c] = (float) (100 + 10 * (9 + c / 240.0));
            }
        }
        DemSource dem = new InMemoryDem("mixed", List.of(tile(46, 8, (la, lo) -> 100 + 10 * lo),
                HgtTile.of(new TileId(46, 9), fine, h, "fine")));
        Mosaic m = Mosaic.of(dem, new TileSelection(46, 8, 1, 2, new boolean[][] {{true, true}}), MissingTilePolicy.ERROR);
        assertEquals(240, m.intervalsPerDegree());
        assertEquals(100 + 10 * 8.5, m.heightAt(46.5, 8.5), 1e-3);
        assertEquals(100 + 10 * 9.5, m.heightAt(46.5, 9.5), 1e-3);
    }

    @Test
    void aRowOfSamplesIsSampleBySample() {
        // Present, missing (sea level) and unloaded tiles, a void, and a coarser tile beside a finer one.
        float[] nw = new float[N * N];
        for (int k = 0; k < nw.length; k++) {
            nw[k] = 300 + k % 97;
        }
        nw[60 * N + 60] = Float.NaN;
        int fine = 241;
        float[] h = new float[fine * fine];
        for (int k = 0; k < h.length; k++) {
            h[k] = (float) (100 + (k * 31 % 1000) / 7.0);
        }
        DemSource dem = new InMemoryDem("rows", List.of(HgtTile.of(new TileId(47, 8), N, nw, "nw"),
                HgtTile.of(new TileId(47, 9), fine, h, "fine"), tile(46, 10, (la, lo) -> 500 + la)));
        Mosaic m = Mosaic.of(dem, new TileSelection(46, 8, 2, 3,
                new boolean[][] {{true, true, false}, {true, false, true}}), MissingTilePolicy.SEA_LEVEL);
        java.util.Random random = new java.util.Random(7);
        for (int r = 0; r < m.rows(); r++) {
            int col = r % 3 == 0 ? 0 : random.nextInt(m.cols()), count = r % 3 == 0 ? m.cols() : random.nextInt(m.cols() - col + 1);
            float[] out = new float[count + 3];
            m.sampleRow(r, col, count, out, 3);
            for (int c = 0; c < count; c++) {
                assertEquals(Float.floatToRawIntBits(m.sample(r, col + c)), Float.floatToRawIntBits(out[3 + c]),
                        "sample " + r + ", " + (col + c));
            }
        }
        assertThrows(IndexOutOfBoundsException.class, () -> m.sampleRow(0, m.cols() - 2, 3, new float[3], 0));
    }

    @Test
    void samplesAndFlagsOfPresentMissingAndUnloadedTilesAndTheirSharedEdges() {
        // Block 2×2 (row 0 north): NW present with one void, NE present, SW missing, SE not touched.
        float[] nw = new float[N * N];
        java.util.Arrays.fill(nw, 300);
        nw[60 * N + 60] = Float.NaN; // a void, filled from its neighbours
        DemSource dem = new InMemoryDem("four", List.of(HgtTile.of(new TileId(47, 8), N, nw, "nw"),
                tile(47, 9, (la, lo) -> 500)));
        Mosaic m = Mosaic.of(dem, new TileSelection(46, 8, 2, 2, new boolean[][] {{true, true}, {true, false}}),
                MissingTilePolicy.SEA_LEVEL);
        assertEquals(List.of(new TileId(46, 8)), m.tilesMissing());
        // {row, col, height (NaN = not loaded), flags}
        double[][] cases = {
                {60, 60, 300, Mosaic.FLAG_FILLED_VOID}, {60, 61, 300, 0},
                {0, 120, 500, 0},     // NW|NE edge: the eastern tile's sample
                {120, 60, 300, 0},    // NW over missing SW: the present tile wins
                {121, 60, 0, Mosaic.FLAG_MISSING_TILE}, {240, 120, 0, Mosaic.FLAG_MISSING_TILE},
                {120, 120, 500, 0},   // corner of all four: NE is present
                {121, 120, 0, Mosaic.FLAG_MISSING_TILE}, // SW|SE edge: missing beats not loaded
                {121, 121, Double.NaN, 0}, {240, 240, Double.NaN, 0},
                {120, 121, 500, 0},   // NE over the unloaded SE
        };
        for (double[] c : cases) {
            int r = (int) c[0], col = (int) c[1];
            assertEquals((float) c[2], m.sample(r, col), 1e-4, "height at " + r + ", " + col);
            assertEquals((int) c[3], m.flags(r, col), "flags at " + r + ", " + col);
        }
        assertThrows(IndexOutOfBoundsException.class, () -> m.sample(241, 0));
    }

    @Test
    void badCoordinatesAreClearErrors() {
        DemSource dem = new InMemoryDem("none", List.of());
        for (double[] ll : new double[][] {{Double.NaN, 8}, {46, Double.NaN}, {91, 8}, {46, 181}, {-90.5, 0}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> Mosaic.around(dem, ll[0], ll[1], 10_000, MissingTilePolicy.SEA_LEVEL));
            assertTrue(e.getMessage().contains("must be in"), e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> Mosaic.around(dem, 46, 8, Double.NaN, MissingTilePolicy.SEA_LEVEL));
        assertThrows(IllegalArgumentException.class, () -> Mosaic.around(dem, 46, 8, -5, MissingTilePolicy.SEA_LEVEL));
        assertThrows(IllegalArgumentException.class, () -> Mosaic.around(dem, 89.5, 8, 100_000, MissingTilePolicy.SEA_LEVEL));
    }

    /**
     * The same sample has the same coordinates, to the bit, in mosaics of different blocks: a mesh cached from one
     * viewpoint's mosaic and drawn for another's, and the probe placing this render's triangles, must agree (they
     * did not: a batch's distances depended on the rows rendered before, one float step in a pixel).
     */
    @ParameterizedTest
    @CsvSource({
            "44, -72, 1, 1, 43, -73, 3, 2", // New England: north edges 45° and 46°, west edges 72°W and 73°W
            "-17, 166, 1, 1, -18, 165, 3, 2",
            "10, 178, 1, 2, 9, 179, 3, 2",  // across the antimeridian: 180°-181° unwrapped in one block, in both
    })
    void aSampleHasTheSameCoordinatesInEveryMosaicThatHoldsIt(int latS, int lonW, int ns, int ew, int latS2, int lonW2,
                                                             int ns2, int ew2) {
        // SRTM3's 1200 intervals a degree: at 120 the old rounding happened to agree.
        Mosaic a = Mosaic.of(flatBlock(latS, lonW, ns, ew), new TileSelection(latS, lonW, ns, ew, all(ns, ew)),
                MissingTilePolicy.ERROR);
        Mosaic b = Mosaic.of(flatBlock(latS2, lonW2, ns2, ew2), new TileSelection(latS2, lonW2, ns2, ew2, all(ns2, ew2)),
                MissingTilePolicy.ERROR);
        int compared = 0;
        for (int r = 0; r < a.rows(); r++) {
            int rb = r + (b.latNorthDeg() - a.latNorthDeg()) * 1200;
            if (rb < 0 || rb >= b.rows()) {
                continue;
            }
            assertEquals(Double.doubleToLongBits(a.latOfRow(r)), Double.doubleToLongBits(b.latOfRow(rb)), "row " + r);
            compared++;
        }
        for (int c = 0; c < a.cols(); c++) {
            int shift = Math.floorMod(a.lonWestDeg() - b.lonWestDeg() + 180, 360) - 180;
            int cb = c + shift * 1200;
            if (cb < 0 || cb >= b.cols()) {
                continue;
            }
            assertEquals(Double.doubleToLongBits(a.wrappedLonOfCol(c)), Double.doubleToLongBits(b.wrappedLonOfCol(cb)),
                    "col " + c);
            if (a.lonWestDeg() * 1200L + c == b.lonWestDeg() * 1200L + cb) { // unwrapped alike: the same bits too
                assertEquals(Double.doubleToLongBits(a.lonOfCol(c)), Double.doubleToLongBits(b.lonOfCol(cb)), "col " + c);
            }
            double wrapped = a.wrappedLonOfCol(c);
            assertTrue(wrapped >= -180 && wrapped < 180, "col " + c + ": " + wrapped);
            assertEquals(dempano.geo.Angles.wrap180(a.lonOfCol(c)), wrapped, 1e-12, "col " + c);
            compared++;
        }
        assertTrue(compared > 200, "compared " + compared);
    }

    private static DemSource flatBlock(int latS, int lonW, int ns, int ew) {
        List<HgtTile> tiles = new ArrayList<>();
        for (int i = 0; i < ns; i++) {
            for (int j = 0; j < ew; j++) {
                float[] h = new float[1201 * 1201];
                java.util.Arrays.fill(h, 100);
                tiles.add(HgtTile.of(TileId.of(latS + i, lonW + j), 1201, h, "flat"));
            }
        }
        return new InMemoryDem("flat", tiles);
    }

    private static boolean[][] all(int ns, int ew) {
        boolean[][] present = new boolean[ns][ew];
        for (boolean[] row : present) {
            java.util.Arrays.fill(row, true);
        }
        return present;
    }
}
