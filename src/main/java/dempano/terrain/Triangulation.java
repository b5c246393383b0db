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
}
