package dempano.dem;

/**
 * What void filling found in one tile.
 *
 * @param voidCells                number of void samples (-32768 in the file), all of them filled
 * @param regions                  number of 4-connected void regions
 * @param largestRegionCells       samples in the largest region (0 if none)
 * @param largestRegionSpanSamples the largest region's bounding-box extent, samples (max of rows, cols)
 */
public record VoidReport(int voidCells, int regions, int largestRegionCells, int largestRegionSpanSamples) {
    /** No voids. */
    public static final VoidReport NONE = new VoidReport(0, 0, 0, 0);

    /** A region wider than this many samples (≈ 1 km at SRTM3) is worth a warning: its heights are invented. */
    public static final int LARGE_REGION_SPAN_SAMPLES = 11;

    public boolean hasLargeRegion() {
        return largestRegionSpanSamples > LARGE_REGION_SPAN_SAMPLES;
    }
}
