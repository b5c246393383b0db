package dempano.panorama;

import java.util.Arrays;

/**
 * How far one distance map is from a reference on the same grid: the accuracy report's metrics.
 *
 * <p>Relative error |d − ref| / ref is taken over pixels where both see terrain; pixels where only
 * one sees terrain are counted apart ({@code skyMismatchPixels}). The skyline of a column is its
 * topmost terrain row; its error is the difference of rows, in pixels.
 *
 * @param comparedPixels     pixels with terrain in both maps
 * @param medianRelative     median relative distance error (NaN when none compared)
 * @param p95Relative        95th percentile
 * @param p99Relative        99th percentile
 * @param maxRelative        maximum
 * @param shareOver5Percent  share of compared pixels with a relative error over 5 % (a different surface seen)
 * @param skyMismatchPixels  pixels that are sky in one map and terrain in the other
 * @param skylineMeanAbsPx   mean over columns of |skyline row − reference skyline row|, pixels
 * @param skylineMaxAbsPx    maximum of the same
 * @param skylineColumnsOff  share of columns whose skyline row differs
 * @param farMedianRelative  median relative error over pixels whose reference distance exceeds
 *                           {@link #FAR_METRES} (where depth-buffer precision shows; NaN if none)
 * @param farP99Relative     99th percentile of the same
 */
public record DistanceComparison(long comparedPixels, double medianRelative, double p95Relative, double p99Relative,
                                 double maxRelative, double shareOver5Percent, long skyMismatchPixels,
                                 double skylineMeanAbsPx, int skylineMaxAbsPx, double skylineColumnsOff,
                                 double farMedianRelative, double farP99Relative) {
    /** Distance beyond which pixels count as far, metres. */
    public static final double FAR_METRES = 20_000;

    /**
     * Compares two row-major maps of the same size.
     *
     * @param widthPx columns; the arrays hold widthPx × (length / widthPx) values
     */
    public static DistanceComparison of(float[] distance, float[] reference, int widthPx) {
        if (distance.length != reference.length || widthPx <= 0 || distance.length % widthPx != 0) {
            throw new IllegalArgumentException("maps differ in size: " + distance.length + " vs " + reference.length);
        }
        int h = distance.length / widthPx;
        float[] rel = new float[distance.length], far = new float[distance.length];
        int n = 0, nFar = 0;
        long mismatch = 0;
        for (int i = 0; i < distance.length; i++) {
            boolean a = Float.isFinite(distance[i]), b = Float.isFinite(reference[i]);
            if (a && b) {
                rel[n] = (float) (Math.abs((double) distance[i] - reference[i]) / Math.max(reference[i], 1e-9));
                if (reference[i] > FAR_METRES) {
                    far[nFar++] = rel[n];
                }
                n++;
            } else if (a != b) {
                mismatch++;
            }
        }
        float[] sorted = Arrays.copyOf(rel, n);
        Arrays.sort(sorted);
        float[] farSorted = Arrays.copyOf(far, nFar);
        Arrays.sort(farSorted);
        long over = 0;
        for (float v : sorted) {
            if (v > 0.05f) {
                over++;
            }
        }
        long sumAbs = 0;
        int maxAbs = 0, off = 0;
        for (int c = 0; c < widthPx; c++) {
            int d = Math.abs(skylineRow(distance, widthPx, h, c) - skylineRow(reference, widthPx, h, c));
            sumAbs += d;
            maxAbs = Math.max(maxAbs, d);
            if (d != 0) {
                off++;
            }
        }
        return new DistanceComparison(n, quantile(sorted, 0.5), quantile(sorted, 0.95), quantile(sorted, 0.99),
                n == 0 ? Double.NaN : sorted[n - 1], n == 0 ? Double.NaN : over / (double) n, mismatch,
                sumAbs / (double) widthPx, maxAbs, off / (double) widthPx, quantile(farSorted, 0.5), quantile(farSorted, 0.99));
    }

    /** The topmost terrain row of a column, or the height (one past the last row) for an all-sky column. */
    public static int skylineRow(float[] distance, int widthPx, int heightPx, int column) {
        for (int r = 0; r < heightPx; r++) {
            if (Float.isFinite(distance[r * widthPx + column])) {
                return r;
            }
        }
        return heightPx;
    }

    /** Quantile of sorted values by linear interpolation between order statistics; NaN if empty. */
    static double quantile(float[] sorted, double q) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        double pos = q * (sorted.length - 1);
        int i = (int) Math.floor(pos);
        int j = Math.min(sorted.length - 1, i + 1);
        return sorted[i] + (pos - i) * (sorted[j] - sorted[i]);
    }
}
