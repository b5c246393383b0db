package dempano.terrain;

/**
 * Level of detail chosen from the error it causes on screen. A square patch of the mosaic grid may be
 * drawn with every {@code step}-th sample only; the coarse surface then departs from the full one by
 * at most {@link #deviationsMetres deviation(step)} metres vertically, which a viewer at distance
 * {@code d} sees as at most {@code deviation / d} radians. The coarsest step whose angle stays within
 * a bound in pixels is chosen. Pure arithmetic, no GL.
 */
public final class LevelOfDetail {
    /** Default bound on the screen error of simplified terrain, panorama pixels. */
    public static final double DEFAULT_MAX_ERROR_PX = 0.5;

    private LevelOfDetail() {
    }

    /**
     * The largest vertical deviation, in metres, of the surface drawn with every {@code 2^level}-th
     * sample from the full-resolution surface, measured at the full-resolution samples, for levels
     * 0 (= 0 m) to log2(intervals).
     *
     * @param heights   heights (metres), row-major, {@code stride} samples per row
     * @param row0      first row of the patch in {@code heights}
     * @param col0      first column of the patch
     * @param intervals cells per patch side, a power of two
     */
    public static double[] deviationsMetres(float[] heights, int stride, int row0, int col0, int intervals) {
        if (Integer.bitCount(intervals) != 1) {
            throw new IllegalArgumentException("patch side must be a power of two, got " + intervals);
        }
        int levels = Integer.numberOfTrailingZeros(intervals);
        double[] dev = new double[levels + 1];
        for (int level = 1; level <= levels; level++) {
            int s = 1 << level;
            double worst = 0;
            for (int i = 0; i <= intervals; i++) {
                int ci = Math.min(i / s, intervals / s - 1);
                double v = (i - ci * s) / (double) s;
                for (int j = 0; j <= intervals; j++) {
                    int cj = Math.min(j / s, intervals / s - 1);
                    double u = (j - cj * s) / (double) s;
                    int rn = row0 + ci * s, rs = rn + s, cw = col0 + cj * s, ce = cw + s;
                    double coarse = interpolate(heights[rn * stride + cw], heights[rn * stride + ce],
                            heights[rs * stride + cw], heights[rs * stride + ce], u, v,
                            Triangulation.splitsNorthWestToSouthEast(ci, cj));
                    worst = Math.max(worst, Math.abs(heights[(row0 + i) * stride + col0 + j] - coarse));
                }
            }
            dev[level] = worst;
        }
        return dev;
    }

    /**
     * How far a flat coarse cell lies from the curved earth it spans: the sag of a chord across the
     * cell's diagonal (√2 · side), d²/8R, with refraction's apparent flattening (R/(1−k)) counted only
     * when it enlarges the sag (k < 0).
     *
     * @param cellSideMetres side of the coarse cell, metres (the longer of its two sides)
     */
    public static double chordSagMetres(double cellSideMetres, double refractionCoefficient) {
        double diagonal = Math.sqrt(2) * cellSideMetres;
        return diagonal * diagonal / (8 * 6_356_000.0) * Math.max(1, 1 - refractionCoefficient);
    }

    /**
     * Height on a cell's two triangles.
     *
     * @param u east fraction [0, 1]
     * @param v south fraction [0, 1]
     */
    static double interpolate(double nw, double ne, double sw, double se, double u, double v, boolean nwToSe) {
        if (nwToSe) {
            return u >= v ? nw + u * (ne - nw) + v * (se - ne) : nw + v * (sw - nw) + u * (se - sw);
        }
        return u + v <= 1 ? nw + u * (ne - nw) + v * (sw - nw) : se + (1 - u) * (sw - se) + (1 - v) * (ne - se);
    }

    /**
     * The level (step = 2^level) to draw a patch with.
     *
     * @param deviationsMetres from {@link #deviationsMetres}
     * @param nearestMetres    distance from the eye to the patch's nearest point
     * @param pixelsPerDegree  panorama resolution
     * @param maxErrorPx       bound on the screen error; 0 or less = always full resolution
     */
    public static int chooseLevel(double[] deviationsMetres, double nearestMetres, double pixelsPerDegree,
                                  double maxErrorPx) {
        if (!(maxErrorPx > 0)) {
            return 0;
        }
        double allowedMetres = maxErrorPx / pixelsPerDegree * Math.PI / 180 * Math.max(nearestMetres, 0);
        int level = 0;
        for (int l = 1; l < deviationsMetres.length; l++) {
            if (deviationsMetres[l] <= allowedMetres) {
                level = l;
            } else {
                break; // finer levels must hold the bound too, so stop at the first that does not
            }
        }
        return level;
    }
}
