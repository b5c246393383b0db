package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link Triangulation#heightIn}: the drawn surface inside a cell, against closed forms. */
class TriangulationHeightTest {
    @Test
    void aPlaneIsItselfOnEitherSplit() {
        // h = 100 + 7·east − 3·south: both triangles of either split lie in that plane.
        for (int col = 0; col < 2; col++) {
            double nw = 100, ne = 107, sw = 97, se = 104;
            for (double south = 0; south <= 1; south += 0.125) {
                for (double east = 0; east <= 1; east += 0.125) {
                    assertEquals(100 + 7 * east - 3 * south, Triangulation.heightIn(0, col, nw, ne, sw, se, south, east), 1e-12,
                            "split " + (col == 0 ? "NW-SE" : "NE-SW") + " at " + south + ", " + east);
                }
            }
        }
    }

    @Test
    void aTwistedCellFollowsItsDiagonal() {
        // Corners 0, 0, 0 and 10 m at the south-east: split NW–SE (row + col even) the diagonal runs to the high
        // corner, so the centre is at 5 m; split NE–SW the diagonal joins two low corners: 0 m at the centre.
        double nw = 0, ne = 0, sw = 0, se = 10;
        assertEquals(5, Triangulation.heightIn(0, 0, nw, ne, sw, se, 0.5, 0.5), 1e-12);
        assertEquals(0, Triangulation.heightIn(0, 1, nw, ne, sw, se, 0.5, 0.5), 1e-12);
        // The bilinear height there is 2.5 m: the drawn surface differs from it by a quarter of the twist.
        for (int col = 0; col < 2; col++) {
            assertEquals(se, Triangulation.heightIn(0, col, nw, ne, sw, se, 1, 1), 1e-12, "corner");
            assertEquals(nw, Triangulation.heightIn(0, col, nw, ne, sw, se, 0, 0), 1e-12, "corner");
            assertTrue(Double.isNaN(Triangulation.heightIn(0, col, Double.NaN, ne, sw, se, 0.1, 0.1)), "a void corner");
        }
    }
}
