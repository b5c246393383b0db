package dempano.summits;

import java.util.List;

/**
 * The thesis's error metrics (chapter 4) for distances estimated from a panorama against true
 * distances: RMSE, MAPE, RSE, R² and the share of relative errors under 5, 10, …, 40 %.
 *
 * @param count            pairs compared
 * @param rmseMetres       √(mean (est − true)²), metres
 * @param mape             mean |est − true| / true (a fraction, not per cent)
 * @param rse              relative squared error Σ(est − true)² / Σ(true − mean true)²
 * @param r2               1 − RSE
 * @param shareUnder       share of relative errors under {@link #THRESHOLDS}[i]
 */
public record DistanceMetrics(int count, double rmseMetres, double mape, double rse, double r2, double[] shareUnder) {
    /** 5 %, 10 %, …, 40 %. */
    public static final double[] THRESHOLDS = {0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35, 0.40};

    /** @param estimatedMetres and trueMetres: same length, finite, true values positive */
    public static DistanceMetrics of(List<Double> estimatedMetres, List<Double> trueMetres) {
        int n = estimatedMetres.size();
        if (n != trueMetres.size()) {
            throw new IllegalArgumentException("lists differ in length");
        }
        if (n == 0) {
            return new DistanceMetrics(0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, new double[THRESHOLDS.length]);
        }
        double mean = 0;
        for (double t : trueMetres) {
            mean += t / n;
        }
        double se = 0, ape = 0, var = 0;
        int[] under = new int[THRESHOLDS.length];
        for (int i = 0; i < n; i++) {
            double e = estimatedMetres.get(i), t = trueMetres.get(i);
            if (!Double.isFinite(e) || !(t > 0)) {
                throw new IllegalArgumentException("pair " + i + " not finite/positive: " + e + ", " + t);
            }
            se += (e - t) * (e - t);
            double rel = Math.abs(e - t) / t;
            ape += rel;
            var += (t - mean) * (t - mean);
            for (int k = 0; k < THRESHOLDS.length; k++) {
                if (rel < THRESHOLDS[k]) {
                    under[k]++;
                }
            }
        }
        double[] share = new double[THRESHOLDS.length];
        for (int k = 0; k < share.length; k++) {
            share[k] = under[k] / (double) n;
        }
        double rse = var == 0 ? Double.NaN : se / var;
        return new DistanceMetrics(n, Math.sqrt(se / n), ape / n, rse, 1 - rse, share);
    }
}
