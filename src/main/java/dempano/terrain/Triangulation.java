package dempano.terrain;

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
        if (splitsNorthWestToSouthEast(row, col)) {
            return east >= south ? nw + east * (ne - nw) + south * (se - ne) // north-east triangle (nw, ne, se)
                    : nw + south * (sw - nw) + east * (se - sw); // south-west triangle (nw, sw, se)
        }
        return east + south <= 1 ? nw + east * (ne - nw) + south * (sw - nw) // north-west triangle (nw, ne, sw)
                : se + (1 - east) * (sw - se) + (1 - south) * (ne - se); // south-east triangle (se, ne, sw)
    }
}
