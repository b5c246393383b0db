package dempano.dem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.geo.Geodesy;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class TileSelectionTest {
    // viewpoint, range, expected number of touched tiles. Truth: tiles whose nearest point lies within
    // the range, checked independently below by dense sampling of each tile's area.
    @ParameterizedTest
    @CsvSource({
            "46.5, 8.5, 10000, 1",
            "46.5, 8.5, 50000, 3",      // 55.6 km to N/S edges, 38.3 km to E/W edges at 46.5N
            "46.5, 8.5, 100000, 9",     // the thesis's 3x3 block
            "46.5, 8.5, 150000, 15",    // wider east-west: 3 rows x 5 columns
            "46.0, 8.0, 1000, 4",       // on a tile corner: all four
            "59.9, 10.5, 100000, 10",   // high latitude: a degree of longitude is 55.8 km: 2 rows x 5 columns
            "0.0, 179.9, 50000, 4",     // equator and antimeridian
    })
    void touchesTheTilesTheCircleReaches(double lat, double lon, double range, int expected) {
        TileSelection sel = TileSelection.around(lat, lon, range);
        List<TileId> got = sel.touchedTiles();
        assertEquals(expected, got.size(), got.toString());
        // Independent check: sample each candidate tile densely (every 1/200°) with geodesics.
        Set<TileId> truth = new TreeSet<>();
        for (int la = (int) Math.floor(lat) - 4; la <= (int) Math.floor(lat) + 4; la++) {
            for (int lo = (int) Math.floor(lon) - 6; lo <= (int) Math.floor(lon) + 6; lo++) {
                if (nearestSampledMetres(lat, lon, la, lo) <= range) {
                    truth.add(TileId.of(la, lo));
                }
            }
        }
        assertTrue(got.containsAll(truth), "missing " + truth + " vs " + got);
        for (TileId t : got) {
            assertTrue(truth.contains(t) || nearestSampledMetres(lat, lon, t.latSouthDeg(), t.lonWestDeg()) <= range + 1500,
                    t + " selected but far away");
        }
    }

    private static double nearestSampledMetres(double lat, double lon, int latS, int lonW) {
        double best = Double.POSITIVE_INFINITY;
        int n = 200;
        for (int i = 0; i <= n; i++) {
            double t = (double) i / n;
            for (double[] p : new double[][] {{latS, lonW + t}, {latS + 1, lonW + t}, {latS + t, lonW}, {latS + t, lonW + 1}}) {
                best = Math.min(best, Geodesy.distanceMetres(lat, lon, p[0], p[1]));
            }
        }
        if (lat >= latS && lat <= latS + 1 && dempano.geo.Angles.wrap180(lon - lonW) >= 0 && dempano.geo.Angles.wrap180(lon - lonW) <= 1) {
            return 0;
        }
        return best;
    }
}
