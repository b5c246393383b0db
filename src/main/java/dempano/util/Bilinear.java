package dempano.util;

/** Bilinear interpolation on a grid cell: the one formula the tile, mosaic, void fill and reports share. Pure. */
public final class Bilinear {
    private Bilinear() {
    }

    /**
     * The value at fraction {@code fr} of the way from the cell's north row to its south row and {@code fc} from its
     * west column to its east column (both usually in [0, 1]; outside, the same bilinear surface extended).
     * Rows first, then columns, in this order of operations everywhere (the same bits wherever it is used).
     *
     * @param h00 north-west corner
     * @param h01 north-east corner
     * @param h10 south-west corner
     * @param h11 south-east corner
     */
    public static double interpolate(double h00, double h01, double h10, double h11, double fr, double fc) {
        return (1 - fr) * ((1 - fc) * h00 + fc * h01) + fr * ((1 - fc) * h10 + fc * h11);
    }
}
