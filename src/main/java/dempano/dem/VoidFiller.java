package dempano.dem;

import java.util.ArrayDeque;

/**
 * Fills voids (NaN) with one of the {@link VoidFill} methods and reports them. The inverse-distance
 * fill ({@link VoidFill#IDW}) weights the nearest valid sample in each of eight directions (as GDAL's
 * FillNodata searches), so that every void, however large, gets a height interpolated from the valid
 * samples around it, in O(8·n²) with directional sweeps; it also starts the spline fills
 * ({@link SplineVoidFill}) on their coarsest grid. A tile without any valid sample is set to 0 m (sea
 * level) and reported as entirely void.
 */
final class VoidFiller {
    private static final int[][] DIRECTIONS = {
            {0, 1}, {0, -1}, {1, 0}, {-1, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

    private VoidFiller() {
    }

    /** The NaN samples of a grid (before filling). */
    static java.util.BitSet voidMask(float[] h) {
        java.util.BitSet mask = new java.util.BitSet();
        for (int i = 0; i < h.length; i++) {
            if (Float.isNaN(h[i])) {
                mask.set(i);
            }
        }
        return mask;
    }

    /** Fills NaN samples of a square grid in place with the default fill and reports them. */
    static VoidReport fill(float[] h, int n) {
        return fill(h, n, VoidFill.DEFAULT);
    }

    /** Fills NaN samples of a square grid in place and reports them. */
    static VoidReport fill(float[] h, int n, VoidFill method) {
        int voids = 0;
        for (float v : h) {
            if (Float.isNaN(v)) {
                voids++;
            }
        }
        if (voids == 0) {
            return VoidReport.NONE;
        }
        VoidReport report = regions(h, n, voids);
        if (voids == h.length) {
            java.util.Arrays.fill(h, 0f);
            return report;
        }
        switch (method) {
            case IDW -> idw(h, n);
            case LAPLACE -> SplineVoidFill.fill(h, n, 1, 0);
            case THIN_PLATE -> thinPlate(h, n);
        }
        return report;
    }

    /**
     * The thin-plate fill, except for voids touching the tile border: those have valid samples on one
     * side only, and bending extrapolates their slopes out of the tile without bound (on N46E008 a void
     * on the western edge rose to 5414 m, 1200 m above anything around it), so they get the Laplace fill,
     * which never leaves the range of their rim, with the thin-plate fill's heights held fixed elsewhere.
     */
    private static void thinPlate(float[] h, int n) {
        java.util.BitSet border = borderVoids(h, n);
        SplineVoidFill.fill(h, n, SplineVoidFill.THIN_PLATE_TENSION, 1);
        if (!border.isEmpty()) {
            for (int i = border.nextSetBit(0); i >= 0; i = border.nextSetBit(i + 1)) {
                h[i] = Float.NaN;
            }
            SplineVoidFill.fill(h, n, 1, 0);
        }
    }

    /** The void samples 4-connected to a void on the grid's border. */
    static java.util.BitSet borderVoids(float[] h, int n) {
        java.util.BitSet seen = new java.util.BitSet(h.length);
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        for (int k = 0; k < n; k++) {
            for (int i : new int[] {k, (n - 1) * n + k, k * n, k * n + n - 1}) {
                if (Float.isNaN(h[i]) && !seen.get(i)) {
                    seen.set(i);
                    queue.add(i);
                }
            }
        }
        while (!queue.isEmpty()) {
            int i = queue.poll(), r = i / n, c = i % n;
            for (int j : new int[] {r > 0 ? i - n : -1, r < n - 1 ? i + n : -1, c > 0 ? i - 1 : -1, c < n - 1 ? i + 1 : -1}) {
                if (j >= 0 && Float.isNaN(h[j]) && !seen.get(j)) {
                    seen.set(j);
                    queue.add(j);
                }
            }
        }
        return seen;
    }

    /** The inverse-distance fill, in place; the grid must hold at least one valid sample. */
    static void idw(float[] h, int n) {
        // A void that sees no valid sample along any of the eight lines (possible when the valid
        // samples are few and off-axis) is filled by a later pass from the samples filled before it.
        while (fillPass(h, n) > 0) {
            // repeat
        }
    }

    /** One directional IDW pass; returns how many voids remain. */
    private static int fillPass(float[] h, int n) {
        double[] weightSum = new double[h.length];
        double[] weightedHeight = new double[h.length];
        float[] nearestHeight = new float[h.length];
        float[] nearestDistance = new float[h.length];
        for (int[] d : DIRECTIONS) {
            int dr = d[0], dc = d[1];
            float step = (dr != 0 && dc != 0) ? (float) Math.sqrt(2) : 1f;
            // Visit cells so that the predecessor (r - dr, c - dc) comes first.
            int r0 = dr >= 0 ? 0 : n - 1, r1 = dr >= 0 ? n : -1, rs = dr >= 0 ? 1 : -1;
            int c0 = dc >= 0 ? 0 : n - 1, c1 = dc >= 0 ? n : -1, cs = dc >= 0 ? 1 : -1;
            for (int r = r0; r != r1; r += rs) {
                for (int c = c0; c != c1; c += cs) {
                    int i = r * n + c;
                    int pr = r - dr, pc = c - dc;
                    float dist = Float.POSITIVE_INFINITY, val = Float.NaN;
                    if (pr >= 0 && pr < n && pc >= 0 && pc < n) {
                        int p = pr * n + pc;
                        if (!Float.isNaN(h[p])) {
                            dist = step;
                            val = h[p];
                        } else if (nearestDistance[p] < Float.POSITIVE_INFINITY) {
                            dist = nearestDistance[p] + step;
                            val = nearestHeight[p];
                        }
                    }
                    nearestDistance[i] = dist;
                    nearestHeight[i] = val;
                    if (Float.isNaN(h[i]) && dist < Float.POSITIVE_INFINITY) {
                        double w = 1.0 / ((double) dist * dist);
                        weightSum[i] += w;
                        weightedHeight[i] += w * val;
                    }
                }
            }
        }
        int remaining = 0;
        for (int i = 0; i < h.length; i++) {
            if (Float.isNaN(h[i])) {
                if (weightSum[i] > 0) {
                    h[i] = (float) (weightedHeight[i] / weightSum[i]);
                } else {
                    remaining++;
                }
            }
        }
        return remaining;
    }

    private static VoidReport regions(float[] h, int n, int voids) {
        boolean[] seen = new boolean[h.length];
        int regions = 0, largest = 0, largestSpan = 0;
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        for (int start = 0; start < h.length; start++) {
            if (seen[start] || !Float.isNaN(h[start])) {
                continue;
            }
            regions++;
            int size = 0, minR = n, maxR = -1, minC = n, maxC = -1;
            seen[start] = true;
            queue.add(start);
            while (!queue.isEmpty()) {
                int i = queue.poll();
                size++;
                int r = i / n, c = i % n;
                minR = Math.min(minR, r);
                maxR = Math.max(maxR, r);
                minC = Math.min(minC, c);
                maxC = Math.max(maxC, c);
                if (r > 0) visit(h, seen, queue, i - n);
                if (r < n - 1) visit(h, seen, queue, i + n);
                if (c > 0) visit(h, seen, queue, i - 1);
                if (c < n - 1) visit(h, seen, queue, i + 1);
            }
            if (size > largest) {
                largest = size;
            }
            largestSpan = Math.max(largestSpan, Math.max(maxR - minR + 1, maxC - minC + 1));
        }
        return new VoidReport(voids, regions, largest, largestSpan);
    }

    private static void visit(float[] h, boolean[] seen, ArrayDeque<Integer> queue, int j) {
        if (!seen[j] && Float.isNaN(h[j])) {
            seen[j] = true;
            queue.add(j);
        }
    }
}
