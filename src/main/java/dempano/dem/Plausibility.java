package dempano.dem;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Cheap checks for silently wrong terrain that reading cannot refuse: each returns warnings naming
 * the file and the figures, never fails. They cost a few milliseconds per tile (see the tests).
 */
final class Plausibility {
    /** A row above an all-zero block counts as land when more than half its samples are non-zero with this mean, m. */
    static final double LAND_MEAN_METRES = 20;
    /** A needle stands more than this above every sample on the ring {@link #NEEDLE_RING} samples away, m. */
    static final double NEEDLE_METRES = 1000;
    /** Ring distance of the needle check, samples: a spike up to 5×5 samples wide fits inside. */
    static final int NEEDLE_RING = 3;
    /** Mean |difference| along a shared tile edge above which the tiles are said to disagree, m. */
    static final double EDGE_MEAN_METRES = 10;

    private Plausibility() {
    }

    /**
     * Rows exactly 0 from some row to the southern edge right below land: a straight cut no coast
     * makes (an SRTM3 tile padded with zeros into an SRTM1-sized file, a truncated download
     * zero-filled). Voids are NaN and count as non-zero.
     *
     * @return the warning, or null
     */
    static String zeroRowsBelowLand(float[] raw, int n, String source) {
        int k = n; // first row of the all-zero block at the bottom
        while (k > 0 && rowAllZero(raw, n, k - 1)) {
            k--;
        }
        if (k == n || k == 0) {
            return null;
        }
        int nonZero = 0, valid = 0;
        double sum = 0;
        for (int c = 0, i = (k - 1) * n; c < n; c++, i++) {
            float h = raw[i];
            if (Float.isNaN(h)) {
                continue;
            }
            valid++;
            sum += h;
            if (h != 0) {
                nonZero++;
            }
        }
        double mean = valid == 0 ? 0 : sum / valid;
        if (nonZero * 2 <= n || mean <= LAND_MEAN_METRES) {
            return null;
        }
        return String.format(Locale.ROOT, "%s: rows %d to %d (the southern %.0f %% of the tile) are exactly 0 m right "
                        + "below row %d, which is land (%d of %d samples non-zero, mean %.0f m): a straight cut, not a coast; "
                        + "truncated or zero-padded data (an SRTM3 tile in an SRTM1-sized file?)",
                source, k, n - 1, 100.0 * (n - k) / n, k - 1, nonZero, n, mean);
    }

    private static boolean rowAllZero(float[] h, int n, int row) {
        for (int c = 0, i = row * n; c < n; c++, i++) {
            if (h[i] != 0) { // NaN (void) is not zero
                return false;
            }
        }
        return true;
    }

    /**
     * Samples standing more than {@link #NEEDLE_METRES} above every sample on the square ring
     * {@link #NEEDLE_RING} samples away: no real slope does that (at SRTM3 spacing, 1000 m over 270 m
     * in every direction), a spike in the data does, and is drawn as a needle. Samples within
     * {@link #NEEDLE_RING} of the tile edge are not checked.
     *
     * @return the warning, or null
     */
    static String needles(float[] h, int n, TileId id, String source) {
        final int d = NEEDLE_RING, dn = d * n;
        int count = 0, worstRow = -1, worstCol = -1;
        float worst = 0, worstRise = 0;
        for (int r = d; r < n - d; r++) {
            int base = r * n;
            for (int c = d; c < n - d; c++) {
                int i = base + c;
                float limit = h[i] - (float) NEEDLE_METRES;
                // Cheap pre-check: the four axis samples of the ring.
                if (h[i - d] >= limit || h[i + d] >= limit || h[i - dn] >= limit || h[i + dn] >= limit) {
                    continue;
                }
                float ringMax = ringMax(h, n, r, c, d);
                if (ringMax >= limit) {
                    continue;
                }
                count++;
                if (h[i] > worst || worstRow < 0) {
                    worst = h[i];
                    worstRise = h[i] - ringMax;
                    worstRow = r;
                    worstCol = c;
                }
            }
        }
        if (count == 0) {
            return null;
        }
        double ipd = n - 1;
        return String.format(Locale.ROOT, "%s: %d sample%s stand%s more than %.0f m above every sample %d samples around "
                        + "(highest %.0f m at row %d, column %d, %.5f, %.5f, %.0f m above the highest around it): "
                        + "a spike in the data, drawn as a needle",
                source, count, count == 1 ? "" : "s", count == 1 ? "s" : "", NEEDLE_METRES, d, worst, worstRow, worstCol,
                id.latSouthDeg() + 1 - worstRow / ipd, id.lonWestDeg() + worstCol / ipd, worstRise);
    }

    private static float ringMax(float[] h, int n, int r, int c, int d) {
        float m = -Float.MAX_VALUE;
        for (int k = -d; k <= d; k++) {
            m = Math.max(m, Math.max(h[(r - d) * n + c + k], h[(r + d) * n + c + k]));
            m = Math.max(m, Math.max(h[(r + k) * n + c - d], h[(r + k) * n + c + d]));
        }
        return m;
    }

    /**
     * Adjacent tiles of a block (row 0 north; null where absent) whose shared edge disagrees: SRTM
     * tiles repeat their edge samples, so the two copies should match (filled voids aside). A mean
     * |difference| over {@link #EDGE_MEAN_METRES} means a shifted, mislabelled or foreign tile.
     */
    static List<String> edgeMismatches(HgtTile[][] tiles) {
        List<String> out = new ArrayList<>();
        for (int r = 0; r < tiles.length; r++) {
            for (int c = 0; c < tiles[r].length; c++) {
                HgtTile t = tiles[r][c];
                if (t == null) {
                    continue;
                }
                if (c + 1 < tiles[r].length && tiles[r][c + 1] != null) {
                    addIfMismatch(out, t, tiles[r][c + 1], true);
                }
                if (r + 1 < tiles.length && tiles[r + 1][c] != null) {
                    addIfMismatch(out, t, tiles[r + 1][c], false);
                }
            }
        }
        return out;
    }

    /** Compares a's eastern (southern) edge with b's western (northern) edge on the coarser tile's samples. */
    private static void addIfMismatch(List<String> out, HgtTile a, HgtTile b, boolean eastWest) {
        int na = a.intervalsPerDegree(), nb = b.intervalsPerDegree(), m = Math.min(na, nb);
        if (na % m != 0 || nb % m != 0) {
            return;
        }
        int sa = na / m, sb = nb / m, count = 0;
        double sum = 0, max = 0;
        for (int k = 0; k <= m; k++) {
            int ra = eastWest ? k * sa : na, ca = eastWest ? na : k * sa;
            int rb = eastWest ? k * sb : 0, cb = eastWest ? 0 : k * sb;
            if (a.isFilledVoid(ra, ca) || b.isFilledVoid(rb, cb)) {
                continue;
            }
            double diff = Math.abs(a.heightMetres(ra, ca) - b.heightMetres(rb, cb));
            sum += diff;
            max = Math.max(max, diff);
            count++;
        }
        if (count > 0 && sum / count > EDGE_MEAN_METRES) {
            out.add(String.format(Locale.ROOT, "%s (%s) and %s (%s) disagree along the edge they share "
                            + "(%s's %s edge, repeated in both files): mean |difference| %.1f m, max %.0f m over %d samples; one of them is shifted or holds "
                            + "another tile's data",
                    a.id(), a.source(), b.id(), b.source(), a.id(), eastWest ? "eastern" : "southern", sum / count, max, count));
        }
    }
}
