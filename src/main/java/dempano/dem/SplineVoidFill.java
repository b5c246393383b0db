package dempano.dem;

/**
 * Void fills that minimise a smoothness energy over the void samples, the valid samples held fixed:
 * <pre>
 *   E = membrane · Σ_edges (h_i − h_j)²  +  plate · Σ_interior (h_N + h_S + h_E + h_W − 4 h_p)²
 * </pre>
 * The first sum runs over the 4-neighbour pairs of the grid that touch a void, the second over the
 * grid's interior samples whose 5-point stencil touches a void. {@code plate = 0} is the Laplace
 * (harmonic, diffusion) fill, {@code membrane ≪ plate} a thin-plate spline with slight tension.
 * Along the tile border the energy simply has fewer terms (natural boundary conditions): a void
 * touching the border is extrapolated, not clamped. Planes have zero bending and, in voids away
 * from the border, zero membrane force, so both fills restore a plane exactly there.
 *
 * <p>The minimum solves a sparse symmetric positive-definite system (the energy's gradient = 0),
 * here by conjugate gradients, matrix-free, started from a solution on a grid coarsened 2:1 (and so
 * on recursively until few voids remain, where the inverse-distance fill starts it): the smooth,
 * slowly converging part of the solution comes from the coarse grids. Deterministic: the sums run in
 * a fixed order on one thread; the operator, most of the work, is applied in parallel chunks on the
 * common fork-join pool where a grid level has many voids, each sample computed exactly as on one
 * thread, so the result does not depend on the number of threads.
 */
final class SplineVoidFill {
    /**
     * Tension of the thin-plate fill (membrane weight with bending weight 1): slopes carry on into
     * a void over about 1/√tension ≈ 30 samples before flattening (≈ 2.7 km at SRTM3); it also pins
     * a void in a tile corner, which bending alone leaves free.
     */
    static final double THIN_PLATE_TENSION = 1e-3;
    /** Voids below this count are solved directly on their grid, without a coarser start. */
    private static final int DIRECT_UNKNOWNS = 400;
    /** Stop when the residual falls below this share of the right-hand side (Euclidean norms). */
    private static final double RELATIVE_TOLERANCE = 1e-10;
    /**
     * Iterations per grid level: at most this many void-sample updates in all (so a level costs about
     * as much as a few hundred sweeps of a tile), at least {@link #MIN_ITERATIONS} and at most
     * {@link #MAX_ITERATIONS}. Small voids converge to round-off; on a tile's worth of voids the coarse
     * grids have already given the shape, and 5000 iterations instead of 60 changed the summit figures
     * of docs/void-fill.md by under 1 m while taking seconds more.
     */
    private static final long ITERATION_BUDGET = 1_000_000;
    private static final int MIN_ITERATIONS = 60, MAX_ITERATIONS = 3000;
    /**
     * Voids per parallel chunk of the operator: below two chunks' worth (a grid level with few voids) it runs on
     * the calling thread alone. The operator is evaluated sample by sample, so the split never changes a value;
     * the conjugate-gradient sums stay sequential, in a fixed order.
     */
    private static final int CHUNK_UNKNOWNS = 16_384, MAX_CHUNKS = 64;
    /** False: the operator on the calling thread only (for tests comparing both). */
    static volatile boolean parallel = true;

    private SplineVoidFill() {
    }

    /**
     * Fills the NaN samples of an {@code n × n} grid in place. The grid must hold at least one valid
     * sample.
     *
     * @param membrane weight of the squared differences between neighbours, ≥ 0
     * @param plate    weight of the squared discrete Laplacian, ≥ 0; not both 0
     */
    static void fill(float[] h, int n, double membrane, double plate) {
        double[] v = new double[h.length];
        for (int i = 0; i < h.length; i++) {
            v[i] = h[i];
        }
        double[] solved = solve(v, n, membrane, plate);
        for (int i = 0; i < h.length; i++) {
            if (Float.isNaN(h[i])) {
                h[i] = (float) solved[i];
            }
        }
    }

    /** The grid {@code v} (NaN = void) with its voids solved; a new array. */
    private static double[] solve(double[] v, int n, double membrane, double plate) {
        int unknowns = 0;
        for (double x : v) {
            if (Double.isNaN(x)) {
                unknowns++;
            }
        }
        int[] u = new int[unknowns];
        for (int i = 0, k = 0; i < v.length; i++) {
            if (Double.isNaN(v[i])) {
                u[k++] = i;
            }
        }
        double[] start = coarseStart(v, n, membrane, plate, unknowns);
        if (start == null) {
            float[] f = new float[v.length];
            for (int i = 0; i < v.length; i++) {
                f[i] = (float) v[i];
            }
            VoidFiller.idw(f, n);
            start = new double[v.length];
            for (int i = 0; i < v.length; i++) {
                start[i] = f[i];
            }
        }
        return conjugateGradients(v, n, u, start, membrane, plate);
    }

    /**
     * The solution on the grid coarsened 2:1 (coarse sample (R, C) = fine sample (2R, 2C), the last
     * row and column clamped), interpolated bilinearly back; null when the voids are few, the grid
     * small or the coarse grid holds no valid sample.
     */
    private static double[] coarseStart(double[] v, int n, double membrane, double plate, int unknowns) {
        if (unknowns < DIRECT_UNKNOWNS || n < 16) {
            return null;
        }
        int m = (n + 1) / 2;
        double[] cv = new double[m * m];
        boolean anyValid = false;
        for (int r = 0; r < m; r++) {
            for (int c = 0; c < m; c++) {
                double x = v[Math.min(2 * r, n - 1) * n + Math.min(2 * c, n - 1)];
                cv[r * m + c] = x;
                anyValid |= !Double.isNaN(x);
            }
        }
        if (!anyValid) {
            return null;
        }
        // Bending per sample scales as 1/spacing² against the membrane: keep the continuous energy.
        double[] cs = solve(cv, m, membrane * 4, plate);
        double[] start = v.clone();
        for (int i = 0; i < v.length; i++) {
            if (Double.isNaN(v[i])) {
                double rr = Math.min((i / n) / 2.0, m - 1), cc = Math.min((i % n) / 2.0, m - 1);
                int r0 = Math.min((int) rr, m - 2), c0 = Math.min((int) cc, m - 2);
                double fr = rr - r0, fc = cc - c0;
                start[i] = dempano.util.Bilinear.interpolate(cs[r0 * m + c0], cs[r0 * m + c0 + 1], cs[(r0 + 1) * m + c0],
                        cs[(r0 + 1) * m + c0 + 1], fr, fc);
            }
        }
        return start;
    }

    private static double[] conjugateGradients(double[] v, int n, int[] u, double[] start, double membrane,
                                               double plate) {
        int k = u.length;
        // The interior samples whose Laplacian stencil touches a void: where bending is evaluated.
        java.util.BitSet stencil = new java.util.BitSet(v.length);
        for (int i : u) {
            int r = i / n, c = i % n;
            mark(stencil, n, r, c);
            mark(stencil, n, r - 1, c);
            mark(stencil, n, r + 1, c);
            mark(stencil, n, r, c - 1);
            mark(stencil, n, r, c + 1);
        }
        Operator op = new Operator(n, u, stencil.stream().toArray(), edges(u, n), new double[v.length], membrane, plate);
        double[] full = new double[v.length];
        // Right-hand side: minus the operator applied to the valid samples (voids at 0).
        for (int i = 0; i < v.length; i++) {
            full[i] = Double.isNaN(v[i]) ? 0 : v[i];
        }
        double[] b = new double[k];
        op.apply(full, b);
        for (int j = 0; j < k; j++) {
            b[j] = -b[j];
        }
        java.util.Arrays.fill(full, 0);
        double[] x = new double[k];
        for (int j = 0; j < k; j++) {
            x[j] = start[u[j]];
            full[u[j]] = x[j];
        }
        double[] ap = new double[k];
        op.apply(full, ap);
        double[] r = new double[k], d = new double[k];
        double rr = 0, bb = 0;
        for (int j = 0; j < k; j++) {
            r[j] = b[j] - ap[j];
            d[j] = r[j];
            rr += r[j] * r[j];
            bb += b[j] * b[j];
        }
        double stop = RELATIVE_TOLERANCE * RELATIVE_TOLERANCE * Math.max(bb, 1e-30);
        long iterations = Math.max(MIN_ITERATIONS, Math.min(MAX_ITERATIONS, ITERATION_BUDGET / Math.max(1, k)));
        for (int it = 0; it < iterations && rr > stop; it++) {
            for (int j = 0; j < k; j++) {
                full[u[j]] = d[j];
            }
            op.apply(full, ap);
            double dAd = 0;
            for (int j = 0; j < k; j++) {
                dAd += d[j] * ap[j];
            }
            if (!(dAd > 0)) {
                break; // exactly converged, or a direction the energy does not see
            }
            double alpha = rr / dAd, next = 0;
            for (int j = 0; j < k; j++) {
                x[j] += alpha * d[j];
                r[j] -= alpha * ap[j];
                next += r[j] * r[j];
            }
            double beta = next / rr;
            rr = next;
            for (int j = 0; j < k; j++) {
                d[j] = r[j] + beta * d[j];
            }
        }
        double[] out = v.clone();
        for (int j = 0; j < k; j++) {
            out[u[j]] = x[j];
        }
        return out;
    }

    private static void mark(java.util.BitSet s, int n, int r, int c) {
        if (r > 0 && r < n - 1 && c > 0 && c < n - 1) {
            s.set(r * n + c);
        }
    }

    /** Neighbour flags per void: {@link #NORTH} (row above on the grid), {@link #SOUTH}, {@link #WEST}, {@link #EAST}. */
    private static final int NORTH = 1, SOUTH = 2, WEST = 4, EAST = 8, ALL = NORTH | SOUTH | WEST | EAST;

    /** For each void of {@code u}, which of its four neighbours lie on the grid (computed once per solve). */
    private static byte[] edges(int[] u, int n) {
        byte[] e = new byte[u.length];
        for (int j = 0; j < u.length; j++) {
            int r = u[j] / n, c = u[j] % n;
            e[j] = (byte) ((r > 0 ? NORTH : 0) | (r < n - 1 ? SOUTH : 0) | (c > 0 ? WEST : 0) | (c < n - 1 ? EAST : 0));
        }
        return e;
    }

    /**
     * The energy's Hessian (halved) on one grid: the voids {@code u} it is evaluated at, the interior
     * samples {@code p} whose Laplacian it needs, each void's neighbour flags ({@link #edges}), and
     * {@code lap}, scratch that must be zero outside {@code p}.
     */
    private record Operator(int n, int[] u, int[] p, byte[] edges, double[] lap, double membrane, double plate) {
        /**
         * The operator applied to {@code full} (valid samples zero or not, as the caller needs), at the voids
         * into {@code out}. The same operations in the same order for every void, so the same result to the
         * bit, whether a void is inside the grid (the branch-free path, nearly all of them) or on its border.
         */
        void apply(double[] full, double[] out) {
            int chunks = parallel ? Math.min(MAX_CHUNKS, u.length / CHUNK_UNKNOWNS) : 1;
            if (chunks < 2) {
                if (plate > 0) {
                    laplacians(full, 0, p.length);
                }
                applyRange(full, out, 0, u.length);
                return;
            }
            // Every output sample depends on its inputs alone: any split gives the same values, bit for bit.
            if (plate > 0) {
                java.util.stream.IntStream.range(0, chunks).parallel().forEach(c -> laplacians(full,
                        (int) ((long) p.length * c / chunks), (int) ((long) p.length * (c + 1) / chunks)));
            }
            java.util.stream.IntStream.range(0, chunks).parallel().forEach(c -> applyRange(full, out,
                    (int) ((long) u.length * c / chunks), (int) ((long) u.length * (c + 1) / chunks)));
        }

        /** The discrete Laplacian of {@code full} at {@code p[from..to)} into {@code lap}. */
        private void laplacians(double[] full, int from, int to) {
            for (int k = from; k < to; k++) {
                int i = p[k];
                lap[i] = full[i - n] + full[i + n] + full[i - 1] + full[i + 1] - 4 * full[i];
            }
        }

        /** {@link #apply} at the voids {@code u[from..to)}, the Laplacians already in {@code lap}. */
        private void applyRange(double[] full, double[] out, int from, int to) {
            boolean useMembrane = membrane > 0, usePlate = plate > 0;
            for (int j = from; j < to; j++) {
                int i = u[j], e = edges[j];
                double s = 0;
                if (e == ALL) {
                    if (useMembrane) {
                        double sum = 0;
                        sum += full[i - n];
                        sum += full[i + n];
                        sum += full[i - 1];
                        sum += full[i + 1];
                        s += membrane * (4 * full[i] - sum);
                    }
                    if (usePlate) {
                        double t = -4 * lap[i];
                        t += lap[i - n];
                        t += lap[i + n];
                        t += lap[i - 1];
                        t += lap[i + 1];
                        s += plate * t;
                    }
                    out[j] = s;
                    continue;
                }
                if (useMembrane) {
                    int degree = 0;
                    double sum = 0;
                    if ((e & NORTH) != 0) {
                        degree++;
                        sum += full[i - n];
                    }
                    if ((e & SOUTH) != 0) {
                        degree++;
                        sum += full[i + n];
                    }
                    if ((e & WEST) != 0) {
                        degree++;
                        sum += full[i - 1];
                    }
                    if ((e & EAST) != 0) {
                        degree++;
                        sum += full[i + 1];
                    }
                    s += membrane * (degree * full[i] - sum);
                }
                if (usePlate) {
                    double t = -4 * lap[i];
                    if ((e & NORTH) != 0) {
                        t += lap[i - n];
                    }
                    if ((e & SOUTH) != 0) {
                        t += lap[i + n];
                    }
                    if ((e & WEST) != 0) {
                        t += lap[i - 1];
                    }
                    if ((e & EAST) != 0) {
                        t += lap[i + 1];
                    }
                    s += plate * t;
                }
                out[j] = s;
            }
        }
    }
}
