package dempano.dem;

/**
 * How each mosaic cell is split into two triangles: the surface both renderers draw. The cell whose
 * north-west corner is (row, col) is split along its north-west–south-east diagonal when row + col is
 * even, along its north-east–south-west diagonal when odd (a diamond pattern, as jME's own terrain
 * at full detail, but fixed to the mosaic's grid instead of each patch's).
 *
 * <p>Rows grow southward, columns eastward (mosaic indices).
 */
public final class Triangulation {
    private Triangulation() {
    }

    /** True when the cell with north-west corner (row, col) is split along NW–SE. */
    public static boolean splitsNorthWestToSouthEast(int row, int col) {
        return ((row + col) & 1) == 0;
    }

    /** A cell's corners, as the triangles' corner indices: north-west, north-east, south-west, south-east. */
    public static final int NW = 0, NE = 1, SW = 2, SE = 3;
    /** A cell's triangles: the one along its north edge, the one along its south edge. */
    public static final int NORTH = 0, SOUTH = 1;

    /** Corners of each triangle, [split NW–SE ? 0 : 1][NORTH or SOUTH], in the order the CPU reference walks them. */
    private static final int[][][] CORNERS = {
            {{NW, NE, SE}, {NW, SW, SE}}, // NW–SE: the north-east triangle, the south-west one
            {{NW, NE, SW}, {NE, SE, SW}}}; // NE–SW: the north-west triangle, the south-east one

    /**
     * Corner {@code k} (0…2) of a cell's triangle, as {@link #NW}…{@link #SE}: its row offset from the cell's
     * north-west corner is {@code corner >> 1}, its column offset {@code corner & 1}.
     *
     * @param triangle {@link #NORTH} or {@link #SOUTH}
     */
    public static int corner(boolean nwToSe, int triangle, int k) {
        return CORNERS[nwToSe ? 0 : 1][triangle][k];
    }

    /**
     * The triangle of a cell split so that holds a point: {@link #NORTH} or {@link #SOUTH}; a point on the diagonal
     * belongs to the north one.
     *
     * @param south fraction of the cell southward from its north-west corner, 0…1
     * @param east  fraction of the cell eastward, 0…1
     */
    public static int triangleHolding(boolean nwToSe, double south, double east) {
        return (nwToSe ? east >= south : east + south <= 1) ? NORTH : SOUTH;
    }

    /**
     * The height of the drawn surface inside a cell: linear on the triangle that holds the point (the bilinear
     * height differs from it by up to a quarter of the cell's corner heights' twist, metres on steep cells).
     *
     * @param row   the cell's north-west corner's row
     * @param col   the cell's north-west corner's column
     * @param south fraction of the cell southward from its north-west corner, 0…1
     * @param east  fraction of the cell eastward, 0…1
     * @return metres, in the corners' unit; NaN if a corner of the triangle is NaN
     */
    public static double heightIn(int row, int col, double nw, double ne, double sw, double se, double south,
                                  double east) {
        return height(splitsNorthWestToSouthEast(row, col), nw, ne, sw, se, south, east);
    }

    /**
     * The same for a cell split as given (a coarse cell of a level of detail has its own split): the one formula
     * of the drawn surface's height.
     */
    public static double height(boolean nwToSe, double nw, double ne, double sw, double se, double south, double east) {
        if (nwToSe) {
            return east >= south ? nw + east * (ne - nw) + south * (se - ne) // north-east triangle (nw, ne, se)
                    : nw + south * (sw - nw) + east * (se - sw); // south-west triangle (nw, sw, se)
        }
        return east + south <= 1 ? nw + east * (ne - nw) + south * (sw - nw) // north-west triangle (nw, ne, sw)
                : se + (1 - east) * (sw - se) + (1 - south) * (ne - se); // south-east triangle (se, ne, sw)
    }
}
