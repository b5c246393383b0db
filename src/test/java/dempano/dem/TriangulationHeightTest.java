package dempano.dem;

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

    /** A cell's corner as (south, east) fractions: its row and column offsets. */
    private static double[] at(int corner) {
        return new double[] {corner >> 1, corner & 1};
    }

    @Test
    void eachTriangleHoldsItsOwnCornersAndThePointsInsideThem() {
        // Corners of random heights: a point is held by the triangle whose corners' convex hull it lies in (checked
        // by the signed areas of its sub-triangles), and the height there is the plane through those three corners.
        java.util.Random random = new java.util.Random(7);
        for (boolean nwToSe : new boolean[] {true, false}) {
            double[] h = {random.nextDouble() * 100, random.nextDouble() * 100, random.nextDouble() * 100,
                    random.nextDouble() * 100};
            for (int triangle = 0; triangle < 2; triangle++) {
                java.util.Set<Integer> corners = new java.util.HashSet<>();
                for (int k = 0; k < 3; k++) {
                    corners.add(Triangulation.corner(nwToSe, triangle, k));
                }
                assertEquals(3, corners.size(), "three distinct corners");
                // The diagonal's two corners are in both triangles; NW–SE's diagonal joins NW and SE.
                int[] diagonal = nwToSe ? new int[] {Triangulation.NW, Triangulation.SE} : new int[] {Triangulation.NE, Triangulation.SW};
                assertTrue(corners.contains(diagonal[0]) && corners.contains(diagonal[1]), "the diagonal is an edge");
                int north = triangle == Triangulation.NORTH ? Triangulation.NW : Triangulation.SW;
                assertTrue(corners.contains(north) && corners.contains(north + 1), "the " + (triangle == 0 ? "north" : "south") + " edge");
            }
            for (int i = 0; i < 2000; i++) {
                double south = random.nextDouble(), east = random.nextDouble();
                int triangle = Triangulation.triangleHolding(nwToSe, south, east);
                double[] a = at(Triangulation.corner(nwToSe, triangle, 0)), b = at(Triangulation.corner(nwToSe, triangle, 1)),
                        c = at(Triangulation.corner(nwToSe, triangle, 2));
                double whole = area(a, b, c), wa = area(new double[] {south, east}, b, c) / whole,
                        wb = area(a, new double[] {south, east}, c) / whole, wc = 1 - wa - wb;
                assertTrue(wa >= -1e-12 && wb >= -1e-12 && wc >= -1e-12, "inside the triangle that holds it");
                double plane = wa * h[Triangulation.corner(nwToSe, triangle, 0)] + wb * h[Triangulation.corner(nwToSe, triangle, 1)]
                        + wc * h[Triangulation.corner(nwToSe, triangle, 2)];
                assertEquals(plane, Triangulation.height(nwToSe, h[0], h[1], h[2], h[3], south, east), 1e-9);
            }
        }
        // The cell's own split: row + col even is NW–SE.
        assertEquals(Triangulation.height(true, 0, 0, 0, 10, 0.5, 0.5), Triangulation.heightIn(2, 4, 0, 0, 0, 10, 0.5, 0.5));
        assertEquals(Triangulation.height(false, 0, 0, 0, 10, 0.5, 0.5), Triangulation.heightIn(2, 3, 0, 0, 0, 10, 0.5, 0.5));
    }

    /** Signed area of triangle (a, b, c), points as (south, east). */
    private static double area(double[] a, double[] b, double[] c) {
        return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    }
}
