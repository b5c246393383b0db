package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link OrientationEstimator#blockJackknifeSigma} against the spread of the estimates themselves: a straight line
 * fitted to many independently drawn samples (Monte Carlo truth), with errors that are independent and with errors
 * that run alike over neighbouring samples, as a skyline's do where the DEM draws a ridge a little off.
 */
class BlockJackknifeTest {
    static final int N = 300, TRIALS = 1500;

    /** Per trial: {slope estimate, jackknife σ of the slope, formal σ of the slope}. */
    static double[][] trials(double rho, long seed) {
        Random random = new Random(seed);
        double[] x = new double[N];
        for (int i = 0; i < N; i++) {
            x[i] = (i - N / 2.0) / N; // the parameter's column: a tilt along the skyline
        }
        double[][] out = new double[TRIALS][];
        for (int t = 0; t < TRIALS; t++) {
            double[] y = new double[N];
            double e = random.nextGaussian();
            for (int i = 0; i < N; i++) {
                e = rho * e + Math.sqrt(1 - rho * rho) * random.nextGaussian(); // AR(1), unit variance
                y[i] = 2 + 3 * x[i] + e;
            }
            double mx = Arrays.stream(x).average().orElseThrow(), my = Arrays.stream(y).average().orElseThrow();
            double sxx = 0, sxy = 0;
            for (int i = 0; i < N; i++) {
                sxx += (x[i] - mx) * (x[i] - mx);
                sxy += (x[i] - mx) * (y[i] - my);
            }
            double slope = sxy / sxx, intercept = my - slope * mx;
            double[] r = new double[N];
            double ss = 0;
            for (int i = 0; i < N; i++) {
                r[i] = y[i] - intercept - slope * x[i];
                ss += r[i] * r[i];
            }
            double[] ones = new double[N], w = new double[N];
            Arrays.fill(ones, 1);
            Arrays.fill(w, 1);
            int[] rows = new int[N];
            Arrays.setAll(rows, i -> i);
            // Residuals are "model − data" in the estimator; the sign does not change a spread.
            double jack = OrientationEstimator.blockJackknifeSigma(new double[][] {ones, x}, r, w, rows, 1, 10);
            out[t] = new double[] {slope, jack, Math.sqrt(ss / (N - 2) / sxx)};
        }
        return out;
    }

    static double sd(double[][] t, int col) {
        double mean = Arrays.stream(t).mapToDouble(v -> v[col]).average().orElseThrow();
        return Math.sqrt(Arrays.stream(t).mapToDouble(v -> (v[col] - mean) * (v[col] - mean)).sum() / (t.length - 1));
    }

    static double median(double[][] t, int col) {
        double[] v = Arrays.stream(t).mapToDouble(a -> a[col]).sorted().toArray();
        return v[v.length / 2];
    }

    @Test
    void independentErrorsGiveTheSpreadTheFormalErrorGivesToo() {
        double[][] t = trials(0, 1);
        double truth = sd(t, 0);
        assertEquals(1, median(t, 2) / truth, 0.1, "formal");
        assertEquals(1, median(t, 1) / truth, 0.2, "jackknife");
    }

    @Test
    void errorsAlikeOverNeighboursAreCountedWhereTheFormalErrorIsFarTooSmall() {
        double[][] t = trials(0.9, 2);
        double truth = sd(t, 0);
        assertTrue(median(t, 2) / truth < 0.4, "the formal error is this small: " + median(t, 2) / truth);
        assertEquals(1, median(t, 1) / truth, 0.3, "jackknife");
    }

    @Test
    void aParameterOneBlockAloneDeterminesHasNoFiniteError() {
        double[] ones = new double[N], bump = new double[N], r = new double[N], w = new double[N];
        Arrays.fill(ones, 1);
        Arrays.fill(w, 1);
        for (int i = 0; i < 20; i++) {
            bump[i] = 1; // only the first block's samples see this parameter (a near slope's)
        }
        Random random = new Random(3);
        for (int i = 0; i < N; i++) {
            r[i] = random.nextGaussian();
        }
        int[] rows = new int[N];
        Arrays.setAll(rows, i -> i);
        assertEquals(Double.POSITIVE_INFINITY,
                OrientationEstimator.blockJackknifeSigma(new double[][] {ones, bump}, r, w, rows, 1, 10));
    }

    @Test
    void tooFewSamplesGiveNoJackknife() {
        double[] ones = new double[14], x = new double[14], r = new double[14], w = new double[14];
        Arrays.fill(ones, 1);
        Arrays.fill(w, 1);
        Arrays.setAll(x, i -> i);
        Arrays.setAll(r, i -> i % 2 == 0 ? 1 : -1);
        int[] rows = new int[14];
        Arrays.setAll(rows, i -> i);
        assertEquals(0, OrientationEstimator.blockJackknifeSigma(new double[][] {ones, x}, r, w, rows, 1, 10));
    }
}
