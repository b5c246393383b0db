package dempano.panorama;

import dempano.util.Quantiles;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

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
 * @param farShareOver1Percent share of the compared pixels whose reference distance exceeds {@link #FAR_METRES}
 *                           with a relative error over {@link #FAR_ERROR_LIMIT} (NaN if none)
 */
public record DistanceComparison(long comparedPixels, double medianRelative, double p95Relative, double p99Relative,
                                 double maxRelative, double shareOver5Percent, long skyMismatchPixels,
                                 double skylineMeanAbsPx, int skylineMaxAbsPx, double skylineColumnsOff,
                                 double farMedianRelative, double farP99Relative, double farShareOver1Percent) {
    /** Distance beyond which pixels count as far, metres. */
    public static final double FAR_METRES = 20_000;
    /** Relative error above which a far pixel counts in {@code farShareOver1Percent}: 1 %. */
    public static final double FAR_ERROR_LIMIT = 0.01;

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
                rel[n] = (float) relative(distance[i], reference[i]);
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
        long farOver = 0;
        for (float v : farSorted) {
            if (v > FAR_ERROR_LIMIT) {
                farOver++;
            }
        }
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
        return new DistanceComparison(n, Quantiles.ofSorted(sorted, 0.5), Quantiles.ofSorted(sorted, 0.95), Quantiles.ofSorted(sorted, 0.99),
                n == 0 ? Double.NaN : sorted[n - 1], n == 0 ? Double.NaN : over / (double) n, mismatch,
                sumAbs / (double) widthPx, maxAbs, off / (double) widthPx, Quantiles.ofSorted(farSorted, 0.5), Quantiles.ofSorted(farSorted, 0.99),
                nFar == 0 ? Double.NaN : farOver / (double) nFar);
    }

    /**
     * Relative errors of the pixels whose incidence lies in one bin.
     *
     * @param fromDeg        lower bound of the incidence, degrees (inclusive)
     * @param toDeg          upper bound, degrees (exclusive; +∞ for the last bin)
     * @param pixels         compared pixels in the bin (terrain in both maps, finite incidence)
     * @param medianRelative median relative error (NaN when the bin is empty)
     * @param p99Relative    99th percentile (NaN when empty)
     */
    public record IncidenceBin(double fromDeg, double toDeg, long pixels, double medianRelative, double p99Relative) {
    }

    /** The accuracy report's incidence bins, lower bounds in degrees: &lt;0.5°, 0.5–2°, 2–10°, ≥10°. */
    public static final double[] INCIDENCE_BIN_LOWER_DEG = {0, 0.5, 2, 10};

    /**
     * Relative error |d − ref| / ref binned by the incidence angle at each pixel (the angle between
     * the ray and the surface seen, from the reference: {@link Layer#INCIDENCE}), over pixels where
     * both maps see terrain and the incidence is finite.
     *
     * @param incidenceDeg per pixel, degrees; NaN where unknown (such pixels are left out)
     * @param lowerDeg     ascending lower bounds of the bins, degrees; bin k holds [lowerDeg[k], lowerDeg[k+1]),
     *                     the last one is unbounded above; incidences below lowerDeg[0] are left out
     */
    public static List<IncidenceBin> byIncidence(float[] distance, float[] reference, float[] incidenceDeg, double[] lowerDeg) {
        if (distance.length != reference.length || incidenceDeg.length != reference.length) {
            throw new IllegalArgumentException("maps differ in size: " + distance.length + ", " + reference.length
                    + ", " + incidenceDeg.length);
        }
        for (int k = 1; k < lowerDeg.length; k++) {
            if (!(lowerDeg[k] > lowerDeg[k - 1])) {
                throw new IllegalArgumentException("bin bounds must ascend: " + Arrays.toString(lowerDeg));
            }
        }
        int bins = lowerDeg.length;
        float[][] rel = new float[bins][];
        int[] n = new int[bins];
        for (int k = 0; k < bins; k++) {
            rel[k] = new float[16];
        }
        for (int i = 0; i < distance.length; i++) {
            float inc = incidenceDeg[i];
            if (!Float.isFinite(distance[i]) || !Float.isFinite(reference[i]) || Float.isNaN(inc) || inc < lowerDeg[0]) {
                continue;
            }
            int k = bins - 1;
            while (inc < lowerDeg[k]) {
                k--;
            }
            if (n[k] == rel[k].length) {
                rel[k] = Arrays.copyOf(rel[k], 2 * n[k]);
            }
            rel[k][n[k]++] = (float) relative(distance[i], reference[i]);
        }
        List<IncidenceBin> out = new ArrayList<>();
        for (int k = 0; k < bins; k++) {
            float[] sorted = Arrays.copyOf(rel[k], n[k]);
            Arrays.sort(sorted);
            out.add(new IncidenceBin(lowerDeg[k], k + 1 < bins ? lowerDeg[k + 1] : Double.POSITIVE_INFINITY, n[k],
                    Quantiles.ofSorted(sorted, 0.5), Quantiles.ofSorted(sorted, 0.99)));
        }
        return out;
    }

    /**
     * The error on one row counted down from each column's horizon (the truth's topmost terrain row).
     *
     * @param rowsBelowSkyline       0 = the horizon row itself, 1 = the row under it, …
     * @param columns                columns where the truth has terrain on that row
     * @param skyMismatchColumns     of those, columns where the tested map reads sky there
     * @param medianTruthMetres      median over those columns of the true distance, metres
     * @param medianMetres           median of the tested distance where it reads terrain, metres (NaN if none)
     * @param medianSignedRelative   median of (d − truth) / truth where it reads terrain (negative = too near)
     * @param maxAbsRelative         maximum of |d − truth| / truth where it reads terrain
     */
    public record HorizonRow(int rowsBelowSkyline, long columns, long skyMismatchColumns, double medianTruthMetres,
                             double medianMetres, double medianSignedRelative, double maxAbsRelative) {
    }

    /**
     * Per row under the horizon: the error of the first {@code rows} rows counted down from each
     * column's skyline in the truth (a sea horizon: the "first row under the horizon").
     *
     * @param rows rows to report, counting the horizon row as the first
     */
    public static List<HorizonRow> belowHorizon(float[] distance, float[] truth, int widthPx, int rows) {
        if (distance.length != truth.length || widthPx <= 0 || truth.length % widthPx != 0) {
            throw new IllegalArgumentException("maps differ in size: " + distance.length + " vs " + truth.length);
        }
        int h = truth.length / widthPx;
        List<HorizonRow> out = new ArrayList<>();
        for (int k = 0; k < rows; k++) {
            float[] t = new float[widthPx], d = new float[widthPx], signed = new float[widthPx];
            int nt = 0, nd = 0;
            long sky = 0;
            double maxAbs = Double.NaN;
            for (int c = 0; c < widthPx; c++) {
                int r = skylineRow(truth, widthPx, h, c) + k;
                if (r >= h || !Float.isFinite(truth[r * widthPx + c])) {
                    continue;
                }
                float tv = truth[r * widthPx + c], dv = distance[r * widthPx + c];
                t[nt++] = tv;
                if (!Float.isFinite(dv)) {
                    sky++;
                    continue;
                }
                double s = ((double) dv - tv) / tv;
                d[nd] = dv;
                signed[nd++] = (float) s;
                maxAbs = Double.isNaN(maxAbs) ? Math.abs(s) : Math.max(maxAbs, Math.abs(s));
            }
            float[] ts = Arrays.copyOf(t, nt), ds = Arrays.copyOf(d, nd), ss = Arrays.copyOf(signed, nd);
            Arrays.sort(ts);
            Arrays.sort(ds);
            Arrays.sort(ss);
            out.add(new HorizonRow(k, nt, sky, Quantiles.ofSorted(ts, 0.5), Quantiles.ofSorted(ds, 0.5), Quantiles.ofSorted(ss, 0.5), maxAbs));
        }
        return out;
    }

    /**
     * Share of the truth's terrain pixels, the first {@code skipRows} rows under each column's horizon
     * left out, that the tested map reads within {@code tolerance} relative error (a pixel read as sky
     * counts as outside). NaN when no pixel is left.
     *
     * @param tolerance relative error, e.g. 0.001 for 0.1 %
     * @param skipRows  rows from each column's skyline down to leave out (1 = the horizon row)
     */
    public static double shareWithin(float[] distance, float[] truth, int widthPx, double tolerance, int skipRows) {
        if (distance.length != truth.length || widthPx <= 0 || truth.length % widthPx != 0) {
            throw new IllegalArgumentException("maps differ in size: " + distance.length + " vs " + truth.length);
        }
        int h = truth.length / widthPx;
        long n = 0, within = 0;
        for (int c = 0; c < widthPx; c++) {
            for (int r = skylineRow(truth, widthPx, h, c) + skipRows; r < h; r++) {
                int i = r * widthPx + c;
                if (!Float.isFinite(truth[i])) {
                    continue;
                }
                n++;
                if (Float.isFinite(distance[i]) && relative(distance[i], truth[i]) <= tolerance) {
                    within++;
                }
            }
        }
        return n == 0 ? Double.NaN : within / (double) n;
    }

    /** |d − ref| / ref in double precision (ref floored at 1e-9 m). */
    private static double relative(float d, float ref) {
        return Math.abs((double) d - ref) / Math.max(ref, 1e-9);
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
}
