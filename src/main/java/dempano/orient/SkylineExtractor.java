package dempano.orient;

import boofcv.alg.filter.blur.BlurImageOps;
import boofcv.alg.filter.derivative.DerivativeType;
import boofcv.alg.filter.derivative.GImageDerivativeOps;
import boofcv.struct.border.BorderType;
import boofcv.struct.image.GrayF32;
import java.awt.image.BufferedImage;

/**
 * Finds a photo's skyline. The filters are BoofCV's (Gaussian blur, Sobel derivatives); the skyline is then the
 * best path across the image (dynamic programming, one row per column, steps of a few rows between columns)
 * through a "sky above, land below" edge score:
 *
 * <ul>
 *   <li>the image is turned into a sky-likeness channel S = luminance + (blue − red) (sky is bright and blue;
 *       land, trees and buildings darker and less blue; haze lowers the contrast but keeps the sign);</li>
 *   <li>the edge score of a pixel is the drop of S from above to below (the Sobel y derivative, negated and
 *       clipped at 0), scaled by the image's 99th percentile;</li>
 *   <li>a path pays for every row it jumps between neighbouring columns, and for the edges above it (the sky
 *       above a skyline is smooth), so that a cloud's rim loses against the ridge it touches unless much
 *       stronger.</li>
 * </ul>
 *
 * Sub-pixel rows come from a parabola through the score at the chosen row and its neighbours. Columns whose
 * score at the path is weak (below {@link #MIN_WEIGHT}) have no skyline. Stateless.
 */
public final class SkylineExtractor {
    /** Gaussian blur before the derivatives, pixels (σ). */
    static final double BLUR_SIGMA_PX = 1.2;
    /** Largest row step between neighbouring columns, as a share of the image height (at least 3 rows). */
    static final double MAX_STEP_SHARE = 0.04;
    /** Path cost per row jumped, in edge-score units. */
    static final double JUMP_COST = 0.02;
    /** Path cost per unit of edge score above the path (sky should be smooth). */
    static final double ABOVE_COST = 0.05;
    /** Columns whose score at the path is below this share of the strong edges have no skyline. */
    static final double MIN_WEIGHT = 0.08;
    /** Edges stronger than this many times the derivative's noise count as fully strong. */
    static final double NOISE_FACTOR = 8;
    /** ... and edges stronger than this share of the 99th percentile. */
    static final double STRONG_SHARE = 0.06;

    private SkylineExtractor() {
    }

    /** The skyline of an image (any type; colour is used when present). */
    public static Skyline extract(BufferedImage image) {
        int w = image.getWidth(), h = image.getHeight();
        if (w < 8 || h < 8) {
            throw new IllegalArgumentException("an image of at least 8 × 8 pixels is needed to find a skyline, got "
                    + w + " × " + h);
        }
        int[] argb = image.getRGB(0, 0, w, h, null, 0, w);
        GrayF32 s = new GrayF32(w, h);
        for (int i = 0; i < w * h; i++) {
            int c = argb[i];
            float r = (c >> 16) & 0xff, g = (c >> 8) & 0xff, b = c & 0xff;
            s.data[i] = (0.299f * r + 0.587f * g + 0.114f * b + (b - r)) / 255f;
        }
        GrayF32 blurred = BlurImageOps.gaussian(s, null, BLUR_SIGMA_PX, -1, null);
        GrayF32 dx = new GrayF32(w, h), dy = new GrayF32(w, h);
        GImageDerivativeOps.gradient(DerivativeType.SOBEL, blurred, dx, dy, BorderType.EXTENDED);
        float[] score = new float[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = dy.startIndex + y * dy.stride + x;
                // S falls going down across a skyline: dy < 0.
                score[y * w + x] = y == 0 || y == h - 1 ? 0 : Math.max(0, -dy.data[i]);
            }
        }
        float strong = percentile(score, 0.99);
        if (!(strong > 0)) {
            double[] none = new double[w];
            java.util.Arrays.fill(none, Double.NaN);
            return new Skyline(w, h, none, new double[w]);
        }
        float scale = saturation(dy, strong);
        float[] raw = new float[w * h];
        for (int i = 0; i < score.length; i++) {
            raw[i] = score[i] / strong;
            score[i] = Math.min(1f, score[i] / scale);
        }
        return path(score, raw, w, h);
    }

    /**
     * The edge strength at which the path's score saturates: {@link #NOISE_FACTOR} × the noise of the vertical
     * derivative (1.4826 × its median absolute value, a robust σ), but at least {@link #STRONG_SHARE} of the
     * strong edges ({@code strong}, the 99th percentile). Saturating puts a faint far ridge in haze on a par
     * with the contrasty near ridge below it, so the path takes the topmost edge with smooth sky above.
     */
    static float saturation(GrayF32 dy, float strong) {
        int w = dy.width, h = dy.height;
        float[] abs = new float[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                abs[y * w + x] = Math.abs(dy.data[dy.startIndex + y * dy.stride + x]);
            }
        }
        float noise = 1.4826f * percentile(abs, 0.5);
        return Math.max((float) NOISE_FACTOR * noise, (float) STRONG_SHARE * strong);
    }

    /** The dynamic-programming path through a score map (row-major, scores ≥ 0 scaled to about 1). */
    static Skyline path(float[] score, int w, int h) {
        return path(score, score, w, h);
    }

    /**
     * The path through {@code score} (saturated, about 0–1), sub-pixel rows from the parabola through {@code raw}
     * (the unsaturated edge strength, whose peak is not flattened).
     */
    static Skyline path(float[] score, float[] raw, int w, int h) {
        int step = Math.max(3, (int) Math.round(MAX_STEP_SHARE * h));
        // Gain of choosing row y in column x: score − ABOVE_COST·(sum of scores above).
        float[] gain = new float[w * h];
        for (int x = 0; x < w; x++) {
            double above = 0;
            for (int y = 0; y < h; y++) {
                gain[y * w + x] = (float) (score[y * w + x] - ABOVE_COST * above);
                above += score[y * w + x];
            }
        }
        float[] best = new float[h], next = new float[h];
        int[] from = new int[w * h];
        for (int y = 0; y < h; y++) {
            best[y] = gain[y * w];
        }
        for (int x = 1; x < w; x++) {
            for (int y = 0; y < h; y++) {
                float b = Float.NEGATIVE_INFINITY;
                int arg = y;
                for (int d = -step; d <= step; d++) {
                    int yy = y + d;
                    if (yy < 0 || yy >= h) {
                        continue;
                    }
                    float v = best[yy] - (float) (JUMP_COST * Math.abs(d));
                    if (v > b) {
                        b = v;
                        arg = yy;
                    }
                }
                next[y] = b + gain[y * w + x];
                from[y * w + x] = arg;
            }
            float[] t = best;
            best = next;
            next = t;
        }
        int y = 0;
        for (int yy = 1; yy < h; yy++) {
            if (best[yy] > best[y]) {
                y = yy;
            }
        }
        double[] rows = new double[w], weight = new double[w];
        for (int x = w - 1; x >= 0; x--) {
            double sc = score[y * w + x];
            // The saturated score is flat across the edge: climb to the peak of the raw strength.
            int yp = y;
            while (yp > 1 && raw[(yp - 1) * w + x] > raw[yp * w + x]) {
                yp--;
            }
            while (yp < h - 2 && raw[(yp + 1) * w + x] > raw[yp * w + x]) {
                yp++;
            }
            if (sc >= MIN_WEIGHT && yp > 0 && yp < h - 1) {
                double a = raw[(yp - 1) * w + x], b0 = raw[yp * w + x], c = raw[(yp + 1) * w + x];
                double denom = a - 2 * b0 + c;
                double off = denom < 0 ? 0.5 * (a - c) / denom : 0;
                rows[x] = yp + Math.max(-0.5, Math.min(0.5, off));
                weight[x] = Math.min(1, sc);
            } else {
                rows[x] = Double.NaN;
                weight[x] = 0;
            }
            if (x > 0) {
                y = from[y * w + x];
            }
        }
        return new Skyline(w, h, rows, weight);
    }

    private static float percentile(float[] v, double q) {
        // A histogram on [0, max]: the score maps are large and only one quantile is needed.
        float max = 0;
        for (float f : v) {
            max = Math.max(max, f);
        }
        if (max <= 0) {
            return 0;
        }
        int bins = 4096;
        int[] hist = new int[bins];
        for (float f : v) {
            hist[Math.min(bins - 1, (int) (f / max * bins))]++;
        }
        long target = (long) Math.ceil(q * v.length);
        long seen = 0;
        for (int b = 0; b < bins; b++) {
            seen += hist[b];
            if (seen >= target) {
                return Math.max(max * (b + 0.5f) / bins, 1e-6f);
            }
        }
        return max;
    }
}
