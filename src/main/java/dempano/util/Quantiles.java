package dempano.util;

import java.util.Arrays;

/** Medians and quantiles: the one definition the reports and the accuracy comparisons share. Pure. */
public final class Quantiles {
    private Quantiles() {
    }

    /**
     * The median of the values (any order; the array is not changed): the middle one, or the mean of the two middle
     * ones for an even count; NaN for none. NaN values sort last, as {@link Arrays#sort(double[])} puts them.
     */
    public static double median(double[] values) {
        double[] s = values.clone();
        Arrays.sort(s);
        int n = s.length;
        return n == 0 ? Double.NaN : n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
    }

    /**
     * Quantile {@code q} (0…1) of values sorted ascending, by linear interpolation between the order statistics at
     * positions q·(n − 1) (type 7 of Hyndman and Fan, R's and NumPy's default); NaN for none.
     */
    public static double ofSorted(double[] sorted, double q) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        double pos = q * (sorted.length - 1);
        int i = (int) Math.floor(pos), j = Math.min(sorted.length - 1, i + 1);
        return sorted[i] + (pos - i) * (sorted[j] - sorted[i]);
    }

    /** The same for floats (the distance maps' values), computed in double. */
    public static double ofSorted(float[] sorted, double q) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        double pos = q * (sorted.length - 1);
        int i = (int) Math.floor(pos), j = Math.min(sorted.length - 1, i + 1);
        return sorted[i] + (pos - i) * (sorted[j] - sorted[i]);
    }
}
