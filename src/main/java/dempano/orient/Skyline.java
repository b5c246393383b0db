package dempano.orient;

/**
 * A photo's skyline: per image column, the row (sub-pixel, OpenCV convention: pixel centres at integers) of the
 * boundary between the sky above and the land below, and how strong the edge there is.
 *
 * @param widthPx  image width, pixels
 * @param heightPx image height, pixels
 * @param rowPx    boundary row per column, pixels from the top; NaN where no skyline was found
 * @param weight   edge strength per column in [0, 1] (1 = the image's strongest skyline edges); 0 where NaN
 */
public record Skyline(int widthPx, int heightPx, double[] rowPx, double[] weight) {
    public Skyline {
        if (rowPx.length != widthPx || weight.length != widthPx) {
            throw new IllegalArgumentException("a skyline needs one row and one weight per column");
        }
        rowPx = rowPx.clone();
        weight = weight.clone();
    }

    @Override
    public double[] rowPx() {
        return rowPx.clone();
    }

    @Override
    public double[] weight() {
        return weight.clone();
    }

    /** Boundary row of a column (NaN = none). */
    public double row(int column) {
        return rowPx[column];
    }

    /** Edge weight of a column. */
    public double weightOf(int column) {
        return weight[column];
    }

    /** Number of columns with a skyline. */
    public int foundColumns() {
        int n = 0;
        for (double r : rowPx) {
            if (!Double.isNaN(r)) {
                n++;
            }
        }
        return n;
    }
}
