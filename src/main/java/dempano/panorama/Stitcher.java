package dempano.panorama;

import dempano.camera.PanoramaTarget;
import dempano.camera.TargetImage;
import dempano.util.Floors;
import java.util.stream.IntStream;

/**
 * Resamples perspective views into the equirectangular panorama. Colour is interpolated
 * bilinearly.
 *
 * <p>Distance, where the views say which triangle each sample saw ({@link SeenTriangles}): every
 * pixel's own centre ray is intersected, in double precision, with the triangles seen at the 4×4
 * view samples around it, and the nearest hit is the pixel's distance. No neighbour's ray and no
 * blend: exact on the drawn surface at any incidence, and a silhouette (ridge, far terrain or sky)
 * is decided per pixel centre. A ray that meets none of them is sky where sky is seen among the
 * central 2×2 samples; elsewhere (a triangle too small to be sampled) the inverse-depth rule below
 * is the fallback, counted in {@link Result#fallbackPixels()}.
 *
 * <p>Without triangles: distance is interpolated only between samples of one surface (inverse eye
 * depth, which is affine across a planar triangle, so exact there) and otherwise taken from the
 * nearest sample, so no distance is ever a blend of a ridge and what lies behind it.
 */
public final class Stitcher {
    /** Neighbouring samples within this depth ratio are taken as one surface. */
    static final double SAME_SURFACE_RATIO = 1.05;

    private Stitcher() {
    }

    /**
     * Converts a capture's raw depth to inverse eye depth, 1/metres (0 for sky). Inverse depth is
     * what is affine across a planar triangle, so it is what the stitcher interpolates; as a float it
     * keeps 6e-8 of relative precision.
     */
    public static float[] inverseEyeDepths(ViewCapture c, ViewLayout layout, DepthMode mode, double nearMetres,
                                           double farMetres) {
        float[] depth = c.depth();
        float[] inv = new float[depth.length];
        int w = layout.widthPx();
        Secants secants = mode == DepthMode.SHADER_RANGE ? new Secants(layout) : null;
        IntStream.range(0, layout.heightPx()).parallel().forEach(row -> {
            for (int x = 0, i = row * w; x < w; x++, i++) {
                float d = depth[i];
                inv[i] = switch (mode) {
                    case STANDARD_24 -> d >= 1f ? 0f
                            : (float) (1 / DepthLinearizer.standardEyeDepth(DepthLinearizer.quantize24(d), nearMetres, farMetres));
                    case REVERSED_32F -> d > 0 ? (float) (d / nearMetres) : 0f; // z_e = n / z_b
                    case SHADER_RANGE -> secants.inverseEyeDepth(d, x, row);
                };
            }
        });
        return inv;
    }

    /**
     * Shader range to inverse eye depth for one view's samples: the range divided by the sample ray's secant,
     * √(1 + x² + y²), from per-column and per-row tables. The one arithmetic of {@link #inverseEyeDepths} and of the
     * stitcher's conversions where asked, so both give the same bits.
     */
    private static final class Secants {
        private final double[] xx, yy1;

        Secants(ViewLayout layout) {
            xx = new double[layout.widthPx()];
            yy1 = new double[layout.heightPx()];
            for (int x = 0; x < xx.length; x++) {
                double t = layout.xTanOfPixel(x);
                xx[x] = t * t;
            }
            for (int y = 0; y < yy1.length; y++) {
                double t = layout.yTanOfPixel(y);
                yy1[y] = 1 + t * t;
            }
        }

        /** 1/metres, 0 where nothing was drawn (range ≤ 0 or infinite). */
        float inverseEyeDepth(float rangeMetres, int x, int y) {
            return rangeMetres > 0 && rangeMetres < Float.POSITIVE_INFINITY
                    ? (float) (Math.sqrt(yy1[y] + xx[x]) / rangeMetres) : 0f;
        }
    }

    /**
     * How the distances were found.
     *
     * @param exactPixels    pixels whose distance (or sky) came from their own ray against the triangles seen
     * @param probedPixels   pixels whose ray met none of the triangles seen around it: the terrain was
     *                       searched along it ({@link RayProbe})
     * @param fallbackPixels pixels whose ray met none of the triangles seen around them, with no sky
     *                       beside them and no probe: the inverse-depth rule gave their distance
     */
    public record Result(long exactPixels, long probedPixels, long fallbackPixels) {
    }

    /**
     * Builds colour and distance for every panorama pixel.
     *
     * @param inverseEyeDepth per view, from {@link #inverseEyeDepths}; null with exact distances on
     *                 captures whose depth is the shader's range (SHADER_RANGE): the samples the
     *                 exact rule still needs it for are then converted where asked, to the same bits
     * @param exact    the triangles the views saw and the terrain to probe where they fail (exact
     *                 per-pixel rays), or null for the inverse-depth rule everywhere
     * @param argbOut  receives colour, row-major, row 0 at the top; null to skip colour
     * @param rangeOut receives straight-line distance in metres, +∞ for sky
     */
    public static Result stitch(PanoramaGeometry g, ViewLayout layout, ViewCapture[] captures, float[][] inverseEyeDepth,
                                Exact exact, int[] argbOut, float[] rangeOut) {
        return stitch(new PanoramaTarget(g), layout, captures, inverseEyeDepth, exact, argbOut, rangeOut);
    }

    /**
     * As {@link #stitch(PanoramaGeometry, ViewLayout, ViewCapture[], float[][], Exact, int[], float[])} for any
     * target image (a panorama or a camera): every pixel's ray is {@link TargetImage#rayOf} at its centre. A pixel
     * without a ray gets black and a NaN distance.
     *
     * <p>A null capture leaves the pixels that sample that view untouched: the views can be stitched in passes, a
     * pass as soon as its views are drawn (each pixel reads one view's samples and its triangles only, so the passes
     * give the same bits as one stitch). {@code inverseEyeDepth} and {@code exact}'s triangles then need to cover
     * only the pass's views.
     */
    public static Result stitch(TargetImage target, ViewLayout layout, ViewCapture[] captures, float[][] inverseEyeDepth,
                                Exact exact, int[] argbOut, float[] rangeOut) {
        if (inverseEyeDepth == null && exact == null) {
            throw new NullPointerException("inverse eye depths are needed without exact distances");
        }
        return resample(target, layout, captures, new InverseDepths(captures, layout, inverseEyeDepth), exact, argbOut,
                rangeOut);
    }

    /**
     * What exact per-pixel distances need.
     *
     * @param seen  the triangles the views saw
     * @param probe the terrain, searched along a pixel's ray where none of the triangles seen around
     *              it is met; null = sky where sky is seen beside it, else the inverse-depth rule
     */
    public record Exact(SeenTriangles seen, RayProbe probe) {
    }

    /**
     * Colour only: colour as {@link #stitch} makes it, and for each pixel the range of the nearest
     * view sample, metres (+∞ for sky), taken as read back, with no linearization or interpolation.
     * That range belongs to a ray up to half a view pixel away: enough to find skylines and
     * occlusion edges ({@link Silhouettes}) and to crop to the terrain, not a distance map.
     *
     * @param captures views whose depth is the shader's range target (metres, ≤ 0 or ∞ for sky)
     */
    public static void stitchColour(PanoramaGeometry g, ViewLayout layout, ViewCapture[] captures, int[] argbOut,
                                    float[] nearestRangeOut) {
        stitchColour(new PanoramaTarget(g), layout, captures, argbOut, nearestRangeOut);
    }

    /** As {@link #stitchColour(PanoramaGeometry, ViewLayout, ViewCapture[], int[], float[])} for any target image. */
    public static void stitchColour(TargetImage target, ViewLayout layout, ViewCapture[] captures, int[] argbOut,
                                    float[] nearestRangeOut) {
        resample(target, layout, captures, null, null, java.util.Objects.requireNonNull(argbOut), nearestRangeOut);
    }

    /**
     * Inverse eye depth of view samples, 1/metres (0 for sky): {@link #inverseEyeDepths}'s arrays where given;
     * else converted from the shader's range (SHADER_RANGE) only where asked, to the bit what
     * {@link #inverseEyeDepths} gives, since with exact distances few pixels ask (about 1 %: converting every
     * sample of every view cost 30–125 ms a panorama). Thread-safe.
     */
    private static final class InverseDepths {
        private final float[][] given;
        private final ViewCapture[] captures;
        private final ViewLayout layout;
        private final Secants secants; // null where given
        private final float[][] converted;

        InverseDepths(ViewCapture[] captures, ViewLayout layout, float[][] given) {
            this.given = given;
            this.captures = captures;
            this.layout = layout;
            secants = given == null ? new Secants(layout) : null;
            converted = new float[captures.length][];
        }

        /** Sample i (row-major, GL rows) of a view. */
        float at(int view, int i) {
            if (given != null) {
                return given[view][i];
            }
            int w = layout.widthPx();
            return secants.inverseEyeDepth(captures[view].depth()[i], i % w, i / w);
        }

        /** A whole view (for the inverse-depth rule), converted on first use where not given. */
        float[] of(int view) {
            if (given != null) {
                return given[view];
            }
            synchronized (converted) {
                if (converted[view] == null) {
                    converted[view] = inverseEyeDepths(captures[view], layout, DepthMode.SHADER_RANGE, 0, 0);
                }
                return converted[view];
            }
        }
    }

    /**
     * Below this sine of incidence (about 1.1°) a simplified patch's triangle's hit is searched again
     * on the full-resolution surface ({@link RayProbe}): there a sag of the simplified surface of
     * d·ε·sin θ would be a relative distance error ε. A full-resolution patch's triangle is kept:
     * it is that surface.
     */
    static final double GRAZING_SINE = 0.02;

    /**
     * Relative window around a simplified patch's grazing hit in which the full-resolution surface is met first
     * ({@link RayProbe#nearestHitBetweenMetres}): 2.5 × the level of detail's distance bound (0.2 %). At Mount
     * Washington and Provence every one of 17 341 such rays met it there, at the distance the search finds, to the bit.
     */
    static final double GRAZING_WINDOW = 0.005;

    /** The per-pixel walk of both; {@code inverseEyeDepth} null = nearest raw range (colour only). */
    private static Result resample(TargetImage target, ViewLayout layout, ViewCapture[] captures, InverseDepths inverseEyeDepth,
                                   Exact exact, int[] argbOut, float[] rangeOut) {
        SeenTriangles seen = exact == null ? null : exact.seen();
        ViewSampling sampling = ViewSampling.of(target, layout);
        int[][] topTerrainRow = seen == null ? null : topTerrainRows(seen.triangleOfSample(), layout);
        java.util.concurrent.atomic.LongAdder exactCount = new java.util.concurrent.atomic.LongAdder();
        java.util.concurrent.atomic.LongAdder probed = new java.util.concurrent.atomic.LongAdder();
        java.util.concurrent.atomic.LongAdder fallback = new java.util.concurrent.atomic.LongAdder();
        int height = target.heightPx();
        // Each worker takes the next chunk of CHUNK_COLUMNS columns not yet taken until none is left, and walks it a
        // row at a time from the bottom up: in a panorama a pixel's hit then bounds the search of the pixel above
        // (RowStitcher.belowBoundMetres). The probed pixels crowd into some azimuths (and into a few rows), so any
        // fixed split leaves one core with most of the work at some viewpoints (interleaved row stripes split four
        // ways by the stream: 1.57 cores busy at Mount Washington's summit); taken a chunk at a time, the cores finish
        // within a chunk of each other. A pixel reads only its own chunk's pixels below it, so the output does not
        // depend on which worker takes which chunk.
        Rows shared = new Rows(target.widthPx(), layout, captures, inverseEyeDepth, seen, exact == null ? null : exact.probe(),
                sampling, topTerrainRow, argbOut, rangeOut, passColumns(target.widthPx(), captures, sampling));
        boolean verticalColumns = target instanceof PanoramaTarget;
        int columnCount = shared.columns() == null ? target.widthPx() : shared.columns().length;
        int chunks = (columnCount + CHUNK_COLUMNS - 1) / CHUNK_COLUMNS;
        dempano.util.Parallel.forEachWorker(chunks, nextChunk -> {
            RowStitcher rows = new RowStitcher(shared, verticalColumns);
            for (int chunk = nextChunk.getAsInt(); chunk < chunks; chunk = nextChunk.getAsInt()) {
                int k0 = chunk * CHUNK_COLUMNS, k1 = Math.min(columnCount, k0 + CHUNK_COLUMNS);
                for (int row = height - 1; row >= 0; row--) {
                    rows.stitch(row, k0, k1);
                }
            }
            exactCount.add(rows.exactPixels);
            probed.add(rows.probedPixels);
            fallback.add(rows.fallbackPixels);
        });
        return new Result(exactCount.sum(), probed.sum(), fallback.sum());
    }

    /**
     * One worker's stitching, a row at a time, with its scratch and counts. The row loop and the rarer
     * searches are methods of their own (not one long loop in the worker's lambda): the JIT then compiles
     * small methods once instead of recompiling the whole walk on-stack at each loop (measured: six server
     * compilations of the lambda, 0.8–1.4 s of compiler time, in the first four renders of a JVM).
     */
    /**
     * What every worker of one stitch reads (and the outputs they fill, a row each): {@code seen} and {@code probe}
     * null without exact distances, {@code inverseEyeDepth} null for the nearest raw range (colour only), {@code
     * argbOut} null for no colour.
     */
    private record Rows(int width, ViewLayout layout, ViewCapture[] captures, InverseDepths inverseEyeDepth,
                        SeenTriangles seen, RayProbe probe, ViewSampling sampling, int[][] topTerrainRow, int[] argbOut,
                        float[] rangeOut, int[] columns) {
    }

    /** Where some views are left to other passes (null captures): the columns that may sample this pass's views; else null. */
    private static int[] passColumns(int width, ViewCapture[] captures, ViewSampling sampling) {
        return java.util.Arrays.asList(captures).contains(null)
                ? IntStream.range(0, width).filter(col -> {
                    int view = sampling.columnView(col);
                    return view < 0 || captures[view] != null;
                }).toArray() : null;
    }

    /** Columns a worker takes at a time, each from the bottom row up. */
    static final int CHUNK_COLUMNS = 32;

    private static final class RowStitcher {
        final int width;
        final ViewLayout layout;
        final ViewCapture[] captures;
        final InverseDepths inverseEyeDepth;
        final SeenTriangles seen;
        final RayProbe probe;
        final ViewSampling sampling;
        final int[][] topTerrainRow;
        final int[] argbOut;
        final float[] rangeOut;
        final double[][] scratch = new double[4][4]; // one neighbourhood buffer per worker, not per pixel
        final double[] p = new double[4], ray = new double[3], span = new double[2];
        final ExactHint hint = new ExactHint();
        /**
         * Where some views are left to other passes (null captures): the columns that may sample this pass's views
         * (a column wholly in another pass's view is skipped whole); null for every column.
         */
        final int[] columns;
        long exactPixels, probedPixels, fallbackPixels;

        // The shared inputs copied into final fields of the worker's own object: read per pixel, kept close.
        /** Whether each column's pixels share one azimuth (a panorama): a pixel's hit then bounds the one above's. */
        final boolean verticalColumns;
        /**
         * Per column of the chunk: horizontal metres to the pixel below's hit, where that is a distance on the surface
         * (exact or probed), else 0.
         */
        final double[] belowHorizontalMetres = new double[CHUNK_COLUMNS];

        RowStitcher(Rows r, boolean verticalColumns) {
            this.verticalColumns = verticalColumns;
            this.width = r.width();
            this.layout = r.layout();
            this.captures = r.captures();
            this.inverseEyeDepth = r.inverseEyeDepth();
            this.seen = r.seen();
            this.probe = r.probe();
            this.sampling = r.sampling();
            this.topTerrainRow = r.topTerrainRow();
            this.argbOut = r.argbOut();
            this.rangeOut = r.rangeOut();
            this.columns = r.columns();
        }

        /** Row {@code row}'s pixels in columns k0 ≤ k < k1 (indices into {@link #columns} where a pass has them). */
        void stitch(int row, int k0, int k1) {
            double[] p = this.p, ray = this.ray, below = this.belowHorizontalMetres;
            int[] columns = this.columns;
            for (int k = k0; k < k1; k++) {
                int col = columns == null ? k : columns[k];
                int view = sampling.locate(col, row, p, ray);
                int i = row * width + col;
                double belowHorizontal = below[k - k0];
                below[k - k0] = 0;
                if (view >= 0 && captures[view] == null) {
                    continue; // a view of another pass (see stitch)
                }
                if (view < 0) { // no ray: nothing to see
                    if (argbOut != null) {
                        argbOut[i] = 0xff000000;
                    }
                    rangeOut[i] = Float.NaN;
                    continue;
                }
                // With exact distances: all 4×4 samples around are sky (the top terrain rows say so cheaply).
                boolean sky = seen != null && skyAround(topTerrainRow[view], Floors.floorInt(p[0]), Floors.floorInt(p[1]));
                if (argbOut != null) {
                    // Sky all around: the four samples hold the one clear colour, which the blend gives back exactly.
                    argbOut[i] = sky ? texel(captures[view].rgba(), layout, p[0], p[1])
                            : bilinearColour(captures[view].rgba(), layout, p[0], p[1]);
                }
                if (inverseEyeDepth == null) {
                    rangeOut[i] = nearestRange(captures[view].depth(), layout, p[0], p[1]);
                    continue;
                }
                double r = Double.NaN;
                if (seen != null) {
                    if (sky) {
                        r = Double.POSITIVE_INFINITY; // all 4×4 samples around are sky, so no candidate
                        exactPixels++;
                    } else {
                        r = exactRange(seen, seen.triangleOfSample()[view], layout, p, ray, hint);
                        double nearestSeen;
                        if (r < Double.POSITIVE_INFINITY && probe != null
                                && hint.nearestCandidateMetres * (1 + NEARER_SEEN_MARGIN) < r
                                && (nearestSeen = nearestSeenMetres(inverseEyeDepth, view, layout, p)) * (1 + NEARER_SEEN_MARGIN) < r) {
                            // Met, but beyond terrain seen around it: the ray may have passed under a crest between
                            // the samples (none of whose triangles it meets) and come out beyond: the surface decides,
                            // searched from just nearer than that terrain along the pixel's own ray.
                            // (A crossing nearer than where the search starts means the ray was not above the surface
                            // there, a few per cent nearer than the terrain seen: the probe's surface and the drawn one
                            // part near a slope at the eye's feet; the triangles met decide then.)
                            double from = Math.max(NEAREST_SEEN_SHARE * nearestSeen, belowBoundMetres(belowHorizontal));
                            double nearer = from < r ? probe.firstHitMetres(ray[0], ray[1], ray[2], from, r) : Double.NaN;
                            if (nearer >= from && nearer < r) {
                                probedPixels++;
                                rangeOut[i] = (float) nearer;
                                below[k - k0] = horizontalMetres(nearer);
                                continue;
                            }
                        }
                        if (!Double.isNaN(r) && (r == Double.POSITIVE_INFINITY || !(hint.incidenceSine < GRAZING_SINE
                                && hint.simplified && probe != null))) {
                            exactPixels++;
                        } else {
                            r = searched(view, r, belowHorizontal);
                        }
                    }
                }
                rangeOut[i] = (float) (Double.isNaN(r) ? range(inverseEyeDepth.of(view), layout, p, scratch) : r);
                if (r < Double.POSITIVE_INFINITY) { // (not NaN: the views' interpolation bounds nothing)
                    below[k - k0] = horizontalMetres(r);
                }
            }
        }

        /** Horizontal metres to a hit {@code metres} along the current pixel's ray (0 where the column is not vertical). */
        private double horizontalMetres(double metres) {
            return verticalColumns ? metres * Math.hypot(ray[0], ray[2]) : 0;
        }

        /**
         * Nearer than this (metres along the current pixel's ray) its ray meets no terrain, from the hit of the pixel below
         * it ({@code belowHorizontal} metres away horizontally; 0: none known): its ray lies above the lower one in the
         * same vertical plane, and the lower one passed above every surface point up to that hit (the surface is a
         * height field), so this ray reaches none of them before the vertical there, at belowHorizontal / cos(elevation).
         * The margin ({@link #NEAREST_SEEN_SHARE}) covers what that flat reckoning leaves out (the vertical there is
         * tilted from the eye's by the Earth's curve, which moves the crossing by the rows' angle times that tilt:
         * under 1e-4) and a simplified patch's sag, should the hit below be on one (the level of detail's 0.2 %).
         */
        private double belowBoundMetres(double belowHorizontal) {
            double horizontalShare = Math.hypot(ray[0], ray[2]);
            return horizontalShare > 0.1 ? NEAREST_SEEN_SHARE * belowHorizontal / horizontalShare : 0;
        }

        /**
         * A pixel whose own ray met a simplified patch's triangle at grazing incidence ({@code r} its distance), or
         * none of the triangles seen around it ({@code r} NaN): its distance on the full-resolution surface where
         * the probe finds it, else as the hint says (sky, or NaN: left to the views' interpolation). Counts it.
         */
        private double searched(int view, double r, double belowHorizontal) {
            double dx = ray[0], dy = ray[1], dz = ray[2];
            if (!Double.isNaN(r)) {
                // Seen at grazing incidence, a simplified patch's sag of centimetres is metres of
                // distance (and the level of detail leaves the horizon rows unbounded): the full-
                // resolution surface decides, met within GRAZING_WINDOW of the triangle's hit (where
                // the level of detail's distance bound puts it), else searched from 20 % nearer. A
                // full-resolution patch's triangle is that surface already.
                double refined = probe.nearestHitBetweenMetres(dx, dy, dz, (1 - GRAZING_WINDOW) * r,
                        (1 + GRAZING_WINDOW) * r);
                if (Double.isNaN(refined)) {
                    refined = probe.firstHitMetres(dx, dy, dz, 0.8 * r, 1.25 * r + 100);
                }
                if (refined < Double.POSITIVE_INFINITY) {
                    probedPixels++;
                    return refined;
                }
                exactPixels++;
                return r;
            }
            if (probe != null && centralSpan(inverseEyeDepth, view, layout, p, span)
                    && !Double.isNaN(r = probe.nearestHitBetweenMetres(dx, dy, dz, span[0] * (1 - SPAN_MARGIN),
                            span[1] * (1 + SPAN_MARGIN)))) {
                probedPixels++; // met on the surface between the central samples' own hits: no search needed
                return r;
            }
            if (probe != null) {
                double to = 2 * hint.farthestCornerMetres + 500;
                // From just nearer than the nearest terrain the samples around saw, or than the pixel below's hit (the
                // ray met none of the triangles seen around it, so the candidates' corners bound nothing: a sliver of
                // terrain between the samples, 53 m off beside the triangles' corners at 69 m, was searched past).
                r = probe.firstHitMetres(dx, dy, dz,
                        Math.max(NEAREST_SEEN_SHARE * nearestSeenMetres(inverseEyeDepth, view, layout, p),
                                belowBoundMetres(belowHorizontal)),
                        to);
                if (Double.isNaN(r) && hint.skyInCentre) {
                    // Above the terrain out to there, with sky beside it: a horizon's ray, which may meet the surface
                    // far beyond the terrain the samples saw (a sea horizon 3 km off, seen beside samples of sea 800 m
                    // off and of sky, was taken for sky): searched on, out to the range.
                    r = probe.firstHitMetres(dx, dy, dz, to, Double.POSITIVE_INFINITY);
                }
                if (!Double.isNaN(r) && (r < Double.POSITIVE_INFINITY || hint.skyInCentre)) {
                    probedPixels++; // (nothing met out to the range, with no sky seen beside it, is a crack: below)
                    return r;
                }
            }
            if (hint.skyInCentre) {
                exactPixels++;
                return Double.POSITIVE_INFINITY; // sky beside it and no triangle met: sky
            }
            fallbackPixels++;
            return Double.NaN;
        }
    }

    /** Relative margin of the stretch {@link #centralSpan} gives, on either side. */
    static final double SPAN_MARGIN = 0.003;

    /**
     * Where a pixel's ray met none of the triangles seen around it but the central 2×2 samples all saw terrain (a
     * slope whose triangles, seen at grazing incidence or far away, are narrower than a sample), its ray meets that
     * surface between the samples' own hits: the stretch of its ray from the nearest to the farthest of them (plus
     * {@link #SPAN_MARGIN}) is intersected with the full-resolution triangles there
     * ({@link RayProbe#nearestHitBetweenMetres}), a cell at a time instead of a search from 3 % nearer than all 16
     * samples. Agreed with that search to the bit at every one of 88 323 such pixels at Mount Washington.
     *
     * @param out receives the distances, metres, along the pixel's ray, at which it reaches the nearest and the
     *            farthest of the central samples' eye depths
     * @return false where one of the central samples is sky or beyond the view's edge
     */
    static boolean centralSpan(InverseDepths inv, int view, ViewLayout l, double[] p, double[] out) {
        int x0 = Floors.floorInt(p[0]), y0 = Floors.floorInt(p[1]);
        if (x0 < 0 || y0 < 0 || x0 + 1 >= l.widthPx() || y0 + 1 >= l.heightPx()) {
            return false;
        }
        float lo = Float.POSITIVE_INFINITY, hi = 0;
        for (int k = 0; k < 4; k++) {
            float v = inv.at(view, (y0 + (k >> 1)) * l.widthPx() + x0 + (k & 1));
            if (!(v > 0)) {
                return false;
            }
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        out[0] = DepthLinearizer.rangeFromEyeDepth(1 / hi, p[2], p[3]);
        out[1] = DepthLinearizer.rangeFromEyeDepth(1 / lo, p[2], p[3]);
        return true;
    }

    /**
     * Where a pixel's ray met none of the triangles seen around it, its search starts this share of
     * the nearest terrain seen at those samples (along its own ray) from the eye: terrain nearer
     * still, that none of the 16 samples around saw, would be a feature narrower than a view sample
     * and 3 % nearer than everything around it.
     */
    static final double NEAREST_SEEN_SHARE = 0.97;

    /**
     * A pixel whose ray met a triangle farther than this share beyond the nearest corner of the triangles seen around
     * it is searched on the surface from there ({@link #NEAREST_SEEN_SHARE} of it) to the triangle met: its ray
     * may pass under a crest between the view samples and meet the triangle behind.
     */
    static final double NEARER_SEEN_MARGIN = 0.03;

    /**
     * Distance along the ray of view point p = {px, py, xTan, yTan} at which it reaches the eye depth
     * of the nearest of the 4×4 view samples around it, metres (0 when none saw terrain).
     */
    static double nearestSeenMetres(InverseDepths inv, int view, ViewLayout l, double[] p) {
        int x0 = Floors.floorInt(p[0]), y0 = Floors.floorInt(p[1]);
        float nearest = 0; // the largest inverse eye depth
        for (int y = Math.max(0, y0 - 1), ye = Math.min(l.heightPx() - 1, y0 + 2); y <= ye; y++) {
            for (int x = Math.max(0, x0 - 1), xe = Math.min(l.widthPx() - 1, x0 + 2); x <= xe; x++) {
                nearest = Math.max(nearest, inv.at(view, y * l.widthPx() + x));
            }
        }
        return nearest > 0 ? DepthLinearizer.rangeFromEyeDepth(1 / nearest, p[2], p[3]) : 0;
    }

    /**
     * Per view and sample column, the highest sample row (GL rows, 0 at the bottom) where terrain
     * was seen, −1 where none was: above it a column is all sky. Scans each view from the top down,
     * so it reads only the sky and the first terrain row of each column.
     */
    static int[][] topTerrainRows(int[][] triangleOfSample, ViewLayout layout) {
        int w = layout.widthPx(), h = layout.heightPx();
        int[][] out = new int[triangleOfSample.length][];
        for (int v = 0; v < out.length; v++) {
            if (triangleOfSample[v] == null) {
                continue; // a view of another pass
            }
            int[] tri = triangleOfSample[v], top = new int[w];
            java.util.Arrays.fill(top, -1);
            int open = w;
            for (int y = h - 1; y >= 0 && open > 0; y--) {
                for (int x = 0, i = y * w; x < w; x++, i++) {
                    if (top[x] < 0 && tri[i] >= 0) {
                        top[x] = y;
                        open--;
                    }
                }
            }
            out[v] = top;
        }
        return out;
    }

    /** Whether every sample of the 4×4 block around (x0 + ½, y0 + ½) is sky (or outside the view). */
    static boolean skyAround(int[] topTerrainRow, int x0, int y0) {
        int lowest = y0 - 1;
        for (int x = Math.max(0, x0 - 1), end = Math.min(topTerrainRow.length - 1, x0 + 2); x <= end; x++) {
            if (topTerrainRow[x] >= lowest) {
                return false;
            }
        }
        return true;
    }

    /**
     * What {@link #exactRange} says of a pixel besides its distance, and its scratch: one per worker,
     * overwritten pixel by pixel.
     */
    static final class ExactHint {
        /** Scratch: the distinct triangles seen around the pixel. */
        final int[] candidates = new int[16];
        /** When NaN is returned: whether sky is seen among the central 2×2 samples. */
        boolean skyInCentre;
        /** When NaN is returned: distance to the farthest candidate's first corner, metres. */
        double farthestCornerMetres;
        /** When a distance is returned: whether the triangle met is a simplified patch's ({@link SeenTriangles#simplified()}). */
        boolean simplified;
        /** When a distance is returned: the sine of the incidence on the triangle met if simplified (only then asked), else 1. */
        double incidenceSine;
        /**
         * When a distance is returned: the nearest distance from the eye of a corner of the triangles seen around the
         * pixel, metres (+∞ where the central samples saw the triangle met alone).
         */
        double nearestCandidateMetres;
    }

    /**
     * The distance along a pixel's own ray to the nearest of the triangles seen at the 4×4 view
     * samples around it; +∞ (sky) when nothing is seen there; NaN when it meets none of them.
     *
     * @param tri  triangle per view sample, −1 for sky
     * @param p    the pixel in the view: {px, py, …}, fractional view pixel (centres at integers), GL rows
     * @param ray  the pixel's own ray, unit, in the eye's frame (jME axes: east, up, south)
     * @param hint receives what else is known of the pixel
     */
    static double exactRange(SeenTriangles seen, int[] tri, ViewLayout l, double[] p, double[] ray, ExactHint hint) {
        double px = p[0], py = p[1], dx = ray[0], dy = ray[1], dz = ray[2];
        int[] candidates = hint.candidates;
        int x0 = Floors.floorInt(px), y0 = Floors.floorInt(py);
        int w = l.widthPx(), h = l.heightPx();
        // Fast path, most pixels: the central 2×2 samples saw one triangle. The pixel's ray lies
        // between their rays, so it meets that (convex, planar) triangle too.
        if (x0 >= 0 && y0 >= 0 && x0 + 1 < w && y0 + 1 < h) {
            int t = tri[y0 * w + x0];
            if (t >= 0 && tri[y0 * w + x0 + 1] == t && tri[(y0 + 1) * w + x0] == t && tri[(y0 + 1) * w + x0 + 1] == t) {
                double d = seen.skirt()[t] ? Double.POSITIVE_INFINITY : seen.distanceAlong(t, dx, dy, dz);
                if (d < Double.POSITIVE_INFINITY) {
                    boolean simplified = seen.simplified()[t];
                    hint.incidenceSine = simplified ? seen.incidenceSine(t, dx, dy, dz) : 1; // only a simplified patch's is asked
                    hint.simplified = simplified;
                    hint.nearestCandidateMetres = Double.POSITIVE_INFINITY;
                    return d;
                }
            }
        }
        int n = 0;
        boolean skyInCentre = false;
        for (int oy = -1; oy <= 2; oy++) {
            int y = y0 + oy;
            if (y < 0 || y >= h) {
                continue; // beyond the view's edge: not seen, not sky
            }
            for (int ox = -1; ox <= 2; ox++) {
                int x = x0 + ox;
                boolean central = (oy == 0 || oy == 1) && (ox == 0 || ox == 1);
                if (x < 0 || x >= w) {
                    continue;
                }
                int t = tri[y * w + x];
                if (t < 0) {
                    skyInCentre |= central;
                    continue;
                }
                boolean known = false;
                for (int k = 0; k < n; k++) {
                    if (candidates[k] == t) {
                        known = true;
                        break;
                    }
                }
                if (!known) {
                    candidates[n++] = t;
                }
            }
        }
        double best = Double.POSITIVE_INFINITY;
        int met = -1;
        for (int k = 0; k < n; k++) {
            double d = seen.distanceAlong(candidates[k], dx, dy, dz);
            if (d < best) {
                best = d;
                met = candidates[k];
            }
        }
        if (met >= 0 && seen.skirt()[met]) {
            best = Double.POSITIVE_INFINITY; // a skirt hangs below the surface: the ray went under a simplified patch
        } else if (best < Double.POSITIVE_INFINITY || n == 0) {
            boolean simplified = met >= 0 && seen.simplified()[met];
            hint.incidenceSine = simplified ? seen.incidenceSine(met, dx, dy, dz) : 1;
            hint.simplified = simplified;
            double nearestSq = Double.POSITIVE_INFINITY;
            for (int k = 0; k < n; k++) {
                double dSq = seen.cornerDistanceSquared(candidates[k]);
                if (dSq < nearestSq) {
                    nearestSq = dSq;
                }
            }
            hint.nearestCandidateMetres = Math.sqrt(nearestSq);
            return best;
        }
        double farthestCorner = 0;
        for (int k = 0; k < n; k++) {
            double d = seen.cornerDistanceMetres(candidates[k]);
            // (A comparison, not Math.max, which the client compiler calls: a corner's distance is a square root of a
            // sum of squares, never NaN or −0, where the two agree.)
            if (d > farthestCorner) {
                farthestCorner = d;
            }
        }
        hint.skyInCentre = skyInCentre;
        hint.farthestCornerMetres = farthestCorner;
        return Double.NaN;
    }

    private static int clampX(ViewLayout l, int x) {
        return Math.max(0, Math.min(l.widthPx() - 1, x));
    }

    private static int clampY(ViewLayout l, int y) {
        return Math.max(0, Math.min(l.heightPx() - 1, y));
    }

    /** The colour of the sample at the floor of (px, py), clamped into the view, as {@link #bilinearColour} packs it. */
    static int texel(byte[] rgba, ViewLayout l, double px, double py) {
        int o = (clampY(l, Floors.floorInt(py)) * l.widthPx() + clampX(l, Floors.floorInt(px))) * 4;
        return 0xff000000 | (rgba[o] & 0xff) << 16 | (rgba[o + 1] & 0xff) << 8 | rgba[o + 2] & 0xff;
    }

    static int bilinearColour(byte[] rgba, ViewLayout l, double px, double py) {
        int x0 = Floors.floorInt(px), y0 = Floors.floorInt(py);
        double fx = px - x0, fy = py - y0;
        int viewWidth = l.widthPx();
        if (x0 >= 0 && y0 >= 0 && x0 + 1 < viewWidth && y0 + 1 < l.heightPx()) {
            // Inside the view (most pixels): no clamping, the same weights summed in the same order as below.
            int o0 = (y0 * viewWidth + x0) * 4, o1 = o0 + 4, o2 = o0 + 4 * viewWidth, o3 = o2 + 4;
            double w0 = (1 - fx) * (1 - fy), w1 = fx * (1 - fy), w2 = (1 - fx) * fy, w3 = fx * fy;
            double r = w0 * (rgba[o0] & 0xff) + w1 * (rgba[o1] & 0xff) + w2 * (rgba[o2] & 0xff) + w3 * (rgba[o3] & 0xff);
            double gr = w0 * (rgba[o0 + 1] & 0xff) + w1 * (rgba[o1 + 1] & 0xff) + w2 * (rgba[o2 + 1] & 0xff)
                    + w3 * (rgba[o3 + 1] & 0xff);
            double b = w0 * (rgba[o0 + 2] & 0xff) + w1 * (rgba[o1 + 2] & 0xff) + w2 * (rgba[o2 + 2] & 0xff)
                    + w3 * (rgba[o3 + 2] & 0xff);
            // The channels are ≥ 0, so adding ½ and truncating rounds half up as Math.round does (faster: no floor).
            return 0xff000000 | ((int) (r + 0.5) << 16) | ((int) (gr + 0.5) << 8) | (int) (b + 0.5);
        }
        double r = 0, gr = 0, b = 0;
        for (int k = 0; k < 4; k++) {
            int x = clampX(l, x0 + (k & 1)), y = clampY(l, y0 + (k >> 1));
            double w = ((k & 1) == 1 ? fx : 1 - fx) * ((k >> 1) == 1 ? fy : 1 - fy);
            int o = (y * l.widthPx() + x) * 4;
            r += w * (rgba[o] & 0xff);
            gr += w * (rgba[o + 1] & 0xff);
            b += w * (rgba[o + 2] & 0xff);
        }
        return 0xff000000 | ((int) (r + 0.5) << 16) | ((int) (gr + 0.5) << 8) | (int) (b + 0.5);
    }

    private static float nearestRange(float[] range, ViewLayout l, double px, double py) {
        float d = range[clampY(l, (int) Math.round(py)) * l.widthPx() + clampX(l, (int) Math.round(px))];
        return d > 0 ? d : Float.POSITIVE_INFINITY; // nothing drawn there: sky
    }

    /** Largest second difference of 1/z, relative to the adjacent first differences, that still counts as one plane. */
    static final double PLANE_TOLERANCE = 0.3;

    /**
     * Range along the panorama pixel's ray; p = {px, py, xTan, yTan}.
     *
     * <p>On a plane 1/z is linear in view coordinates, so where the 4×4 view samples around the
     * point are linear in 1/z (every second difference through the central 2×2, along rows and
     * columns, is tiny beside the first differences) bilinear interpolation of 1/z is exact, even at
     * grazing incidence where neighbours differ by tens of per cent. Otherwise samples within
     * {@link #SAME_SURFACE_RATIO} of each other are interpolated the same way (a smooth surface), and
     * anything else (a silhouette) takes the nearest sample: a distance really seen, never a blend.
     *
     * @param w a 4×4 scratch buffer, overwritten
     */
    static double range(float[] inv, ViewLayout l, double[] p, double[][] w) {
        int x0 = Floors.floorInt(p[0]), y0 = Floors.floorInt(p[1]);
        double fx = p[0] - x0, fy = p[1] - y0;
        // Fast path, most pixels: the central 2×2 are one smooth surface, or all sky.
        {
            int xa = clampX(l, x0), xb = clampX(l, x0 + 1), ya = clampY(l, y0) * l.widthPx(), yb = clampY(l, y0 + 1) * l.widthPx();
            float i00 = inv[ya + xa], i01 = inv[ya + xb], i10 = inv[yb + xa], i11 = inv[yb + xb];
            float lo = Math.min(Math.min(i00, i01), Math.min(i10, i11)), hi = Math.max(Math.max(i00, i01), Math.max(i10, i11));
            if (hi == 0) {
                return Double.POSITIVE_INFINITY;
            }
            // Depths within the ratio: the smallest inverse depth at least the largest / ratio (sky fails).
            if (lo * SAME_SURFACE_RATIO >= hi) {
                double mean = (1 - fy) * ((1 - fx) * i00 + fx * i01) + fy * ((1 - fx) * i10 + fx * i11);
                return DepthLinearizer.rangeFromEyeDepth(1 / mean, p[2], p[3]);
            }
        }
        // w: [dy + 1][dx + 1] of 1/z for dy, dx in -1..2 (a 4×4 buffer the caller reuses)
        for (int dy = -1; dy <= 2; dy++) {
            for (int dx = -1; dx <= 2; dx++) {
                int x = x0 + dx, y = y0 + dy;
                boolean outer = dx == -1 || dx == 2 || dy == -1 || dy == 2;
                if (outer && (x < 0 || y < 0 || x >= l.widthPx() || y >= l.heightPx())) {
                    w[dy + 1][dx + 1] = Double.NaN; // beyond the view's edge: that triple is not tested
                } else {
                    w[dy + 1][dx + 1] = inv[clampY(l, y) * l.widthPx() + clampX(l, x)];
                }
            }
        }
        double lo = Double.POSITIVE_INFINITY, hi = 0, invSum = 0, nearestW = -1, nearestZ = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 4; k++) {
            double weight = ((k & 1) == 1 ? fx : 1 - fx) * ((k >> 1) == 1 ? fy : 1 - fy);
            double zk = 1 / w[1 + (k >> 1)][1 + (k & 1)];
            lo = Math.min(lo, zk);
            hi = Math.max(hi, zk);
            invSum += weight / zk;
            if (weight > nearestW) {
                nearestW = weight;
                nearestZ = zk;
            }
        }
        double eyeDepth;
        if (Double.isFinite(hi) && (hi <= lo * SAME_SURFACE_RATIO || linear(w))) {
            eyeDepth = 1 / invSum;
        } else {
            eyeDepth = nearestZ;
        }
        return DepthLinearizer.rangeFromEyeDepth(eyeDepth, p[2], p[3]);
    }

    /** True when 1/z is linear (to {@link #PLANE_TOLERANCE}) along the rows and columns through the central 2×2. */
    static boolean linear(double[][] w) {
        for (int i = 1; i <= 2; i++) {
            for (int j = 1; j <= 2; j++) {
                if (!linear3(w[i][j - 1], w[i][j], w[i][j + 1]) || !linear3(w[i - 1][j], w[i][j], w[i + 1][j])) {
                    return false;
                }
            }
        }
        return true;
    }

    private static boolean linear3(double a, double b, double c) {
        if (Double.isNaN(a) || Double.isNaN(c)) {
            // At a view's edge: the other triple through the same central pair still sees any jump.
            return true;
        }
        if (a == 0 || b == 0 || c == 0) {
            return false; // sky (1/∞) in the neighbourhood
        }
        double second = Math.abs(a - 2 * b + c);
        return second <= PLANE_TOLERANCE * (Math.abs(b - a) + Math.abs(c - b)) + 1e-6 * Math.abs(b);
    }
}
