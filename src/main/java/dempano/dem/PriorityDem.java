package dempano.dem;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Several DEM sources in priority order, e.g. {@code --dem-dir copernicus --dem-dir srtm}: for each
 * tile, the first source that has it (and not only voids) is the primary; its voids are filled from
 * the later sources, in order, before any void interpolation; a tile no source has is missing. A
 * tile without voids is the primary's own tile, unchanged.
 *
 * <p>The merged tile has the primary's grid. A later source's sample is used where it lies exactly on
 * that grid (same or finer resolution aligned to it); otherwise it is interpolated bilinearly from
 * that source's own samples, and only if none of those with a non-zero weight was a void there.
 * Voids no source fills are interpolated as for a single source. {@link HgtTile#contributions()}
 * tells which source served how many samples of each tile, with each source's vertical datum
 * (sources with different datums are merged as they are: heights differ by the geoid models'
 * difference, typically under 1 m).
 *
 * <p>With {@link Blend#DELTA_SURFACE} (the default) a later source's heights are not pasted in as they are: where it is
 * coarser or offset, that would leave a step at the void's rim. Instead the difference primary − source is
 * taken on every sample where both have data, interpolated into the voids by the void fill (thin-plate by
 * default; Grohman, Kroenung and Strebeck's "delta surface fill" (2006), with which NGA filled SRTM's voids,
 * used a smooth interpolation of the same kind), and added to the source's heights there. At the rim the fill then meets the primary exactly; inside,
 * it has the source's shape. Where the source agrees with the primary on the rim, it is used unchanged.
 *
 * <p>Merged tiles are cached, keyed by the identity of the sources' tiles: as long as every source
 * returns the same (cached) tile object, the merged tile is reused; a source that read its file
 * again (because it changed) yields a new merge. Thread-safe when the sources are.
 */
public final class PriorityDem implements DemSource {
    private static final int CACHED_TILES = DemDirectory.DEFAULT_CACHED_TILES;

    private final List<DemSource> sources;
    private final Map<TileId, Merge> cache;
    private final VoidFill voidFill;
    private final Blend blend;

    /** How a lower-priority source's heights fill the primary's voids. */
    public enum Blend {
        /** The source's heights as they are (bilinear where its grid differs). */
        AS_IS,
        /** The source's heights plus the primary − source difference on the rim, interpolated over the void by the void fill. */
        DELTA_SURFACE;

        /**
         * The blend used unless another is asked for: the delta surface, which measured best on held-out
         * voids with a coarser second source (RMS 37.5 m against 80.1 m as-is, docs/coarse-fill.md). Where the
         * later source holds the primary's true heights it agrees with the primary at every rim, the
         * difference is 0 everywhere and its heights go in unchanged, exactly as {@link #AS_IS}.
         */
        public static final Blend DEFAULT = DELTA_SURFACE;

        /** The name on the command line: {@code as-is}, {@code delta-surface}. */
        public String cliName() {
            return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
        }

        /**
         * The blend named on the command line (case-insensitive, '-' or '_').
         *
         * @throws IllegalArgumentException naming the accepted names
         */
        public static Blend parse(String name) {
            for (Blend b : values()) {
                if (b.cliName().equalsIgnoreCase(name.trim().replace('_', '-'))) {
                    return b;
                }
            }
            throw new IllegalArgumentException("unknown DEM blend '" + name + "' (expected as-is or delta-surface)");
        }
    }

    private record Merge(List<HgtTile> inputs, HgtTile merged) {
    }

    /**
     * @param sources in priority order, at least one
     * @throws IllegalArgumentException if there is none
     */
    public PriorityDem(List<? extends DemSource> sources) {
        this(sources, VoidFill.DEFAULT);
    }

    /**
     * @param sources  in priority order, at least one
     * @param voidFill how the voids no source fills are interpolated
     * @throws IllegalArgumentException if there is no source
     */
    public PriorityDem(List<? extends DemSource> sources, VoidFill voidFill) {
        this(sources, voidFill, Blend.DEFAULT);
    }

    /**
     * @param sources  in priority order, at least one
     * @param voidFill how the voids no source fills are interpolated
     * @param blend    how a later source's heights go into the primary's voids
     * @throws IllegalArgumentException if there is no source
     */
    public PriorityDem(List<? extends DemSource> sources, VoidFill voidFill, Blend blend) {
        this.voidFill = java.util.Objects.requireNonNull(voidFill);
        this.blend = java.util.Objects.requireNonNull(blend);
        if (sources.isEmpty()) {
            throw new IllegalArgumentException("no DEM source given");
        }
        this.sources = List.copyOf(sources);
        this.cache = new LinkedHashMap<>(CACHED_TILES * 2, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<TileId, Merge> eldest) {
                return size() > CACHED_TILES;
            }
        };
    }

    /** One source if there is only one, else a {@link PriorityDem} of them. */
    public static DemSource of(List<? extends DemSource> sources) {
        return of(sources, VoidFill.DEFAULT);
    }

    /** One source if there is only one, else a {@link PriorityDem} of them filling with {@code voidFill}. */
    public static DemSource of(List<? extends DemSource> sources, VoidFill voidFill) {
        return of(sources, voidFill, Blend.DEFAULT);
    }

    /** One source if there is only one, else a {@link PriorityDem} of them filling with {@code voidFill} and {@code blend}. */
    public static DemSource of(List<? extends DemSource> sources, VoidFill voidFill, Blend blend) {
        return sources.size() == 1 ? sources.get(0) : new PriorityDem(sources, voidFill, blend);
    }

    /**
     * The tile folders in priority order as one DEM, their voids filled as {@code fill} says: each folder a
     * {@link DemDirectory} interpolating its own voids with {@code fill.voidFill()} (used where it is the only
     * source of a tile), several merged by a {@link PriorityDem} with {@code fill.blend()}. What the folders'
     * indexing found worth saying (unreadable or unrecognised files) goes to {@code warnings}, one line each.
     * The way a Java caller opens DEM folders as the command line does:
     * {@code PanoramaRenderer.open(PriorityDem.open(List.of(a, b), DemFill.DEFAULT, System.err::println))}.
     *
     * @param directories tile folders, highest priority first, at least one
     * @throws DemException if a folder is missing or unreadable (naming it)
     * @throws IllegalArgumentException if there is no folder
     */
    public static DemSource open(List<java.nio.file.Path> directories, DemFill fill, java.util.function.Consumer<String> warnings) {
        if (directories.isEmpty()) {
            throw new IllegalArgumentException("no DEM folder given");
        }
        List<DemDirectory> dirs = new ArrayList<>();
        for (java.nio.file.Path d : directories) {
            DemDirectory one = new DemDirectory(d, DemDirectory.DEFAULT_CACHED_TILES, fill.voidFill());
            one.warnings().forEach(warnings);
            dirs.add(one);
        }
        return of(dirs, fill.voidFill(), fill.blend());
    }

    /** The fill this DEM uses: its void interpolation and its blend. */
    public DemFill fill() {
        return new DemFill(voidFill, blend);
    }

    public List<DemSource> sources() {
        return sources;
    }

    @Override
    public Optional<HgtTile> tile(TileId id) {
        List<HgtTile> found = new ArrayList<>(sources.size());
        for (DemSource s : sources) {
            found.add(s.tile(id).orElse(null));
        }
        int primary = -1;
        for (int i = 0; i < found.size() && primary < 0; i++) {
            if (found.get(i) != null && !found.get(i).entirelyVoid()) {
                primary = i;
            }
        }
        if (primary < 0) {
            // Nothing, or only tiles without a valid sample: Mosaic reports an all-void tile as missing.
            return found.stream().filter(t -> t != null).findFirst();
        }
        HgtTile first = found.get(primary);
        if (first.voids().voidCells() == 0 || primary == found.size() - 1) {
            return Optional.of(first);
        }
        synchronized (cache) {
            Merge m = cache.get(id);
            if (m != null && sameTiles(m.inputs(), found)) {
                return Optional.of(m.merged());
            }
        }
        HgtTile merged = merge(first, found.subList(primary + 1, found.size()), voidFill, blend);
        synchronized (cache) {
            cache.put(id, new Merge(found, merged));
        }
        return Optional.of(merged);
    }

    private static boolean sameTiles(List<HgtTile> a, List<HgtTile> b) {
        for (int i = 0; i < a.size(); i++) {
            if (a.get(i) != b.get(i)) {
                return false;
            }
        }
        return true;
    }

    /** The primary's valid samples, its voids filled from the fillers in order, the rest interpolated. */
    static HgtTile merge(HgtTile primary, List<HgtTile> fillers) {
        return merge(primary, fillers, VoidFill.DEFAULT);
    }

    /** {@link #merge(HgtTile, List)} interpolating the remaining voids with {@code voidFill}. */
    static HgtTile merge(HgtTile primary, List<HgtTile> fillers, VoidFill voidFill) {
        return merge(primary, fillers, voidFill, Blend.DEFAULT);
    }

    /** {@link #merge(HgtTile, List, VoidFill)} putting the fillers' heights in as {@code blend} says. */
    static HgtTile merge(HgtTile primary, List<HgtTile> fillers, VoidFill voidFill, Blend blend) {
        int n = primary.samplesPerSide();
        float[] h = new float[n * n];
        BitSet open = new BitSet(n * n);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                int i = r * n + c;
                if (primary.isFilledVoid(r, c)) {
                    h[i] = Float.NaN;
                    open.set(i);
                } else {
                    h[i] = primary.heightMetres(r, c);
                }
            }
        }
        List<DemContribution> contributions = new ArrayList<>();
        contributions.add(new DemContribution(primary.source(), primary.verticalDatum(), (long) n * n - open.cardinality()));
        List<String> warnings = new ArrayList<>(primary.warnings());
        StringBuilder source = new StringBuilder(primary.source());
        for (HgtTile f : fillers) {
            if (f == null || f.entirelyVoid() || open.isEmpty()) {
                continue;
            }
            long filled = 0;
            BitSet now = new BitSet(n * n);
            for (int i = open.nextSetBit(0); i >= 0; i = open.nextSetBit(i + 1)) {
                float v = validSample(f, (double) (i / n) / (n - 1), (double) (i % n) / (n - 1));
                if (!Float.isNaN(v)) {
                    h[i] = v;
                    now.set(i);
                    filled++;
                }
            }
            if (filled > 0 && blend == Blend.DELTA_SURFACE) {
                addDeltaSurface(h, n, open, now, f, voidFill);
            }
            open.andNot(now);
            if (filled > 0) {
                contributions.add(new DemContribution(f.source(), f.verticalDatum(), filled));
                source.append(" + ").append(filled).append(" samples from ").append(f.source());
                warnings.addAll(f.warnings());
            }
        }
        BitSet mask = VoidFiller.voidMask(h);
        VoidReport voids = VoidFiller.fill(h, n, voidFill);
        return new HgtTile(primary.id(), source.toString(), n, h, voids, mask, warnings)
                .withVerticalDatum(primary.verticalDatum()).withContributions(contributions);
    }

    /**
     * Adds to the samples {@code now} just filled from {@code f} the difference (heights − f) known on the
     * other samples with data (not {@code open}) where f has data, interpolated over the rest of the tile
     * by {@code voidFill} (the fill of the remaining voids; thin-plate by default).
     */
    private static void addDeltaSurface(float[] h, int n, BitSet open, BitSet now, HgtTile f, VoidFill voidFill) {
        float[] delta = new float[n * n];
        for (int i = 0; i < n * n; i++) {
            if (open.get(i)) {
                delta[i] = Float.NaN;
            } else {
                float v = validSample(f, (double) (i / n) / (n - 1), (double) (i % n) / (n - 1));
                delta[i] = Float.isNaN(v) ? Float.NaN : h[i] - v;
            }
        }
        VoidFiller.fill(delta, n, voidFill);
        for (int i = now.nextSetBit(0); i >= 0; i = now.nextSetBit(i + 1)) {
            h[i] += delta[i];
        }
    }

    /**
     * A tile's height at a fraction of the tile (0 = north/west edge, 1 = south/east edge) from its
     * own, non-void samples: exact on a sample, else bilinear; NaN if a sample it needs was a void.
     */
    static float validSample(HgtTile t, double rowFraction, double colFraction) {
        int m = t.intervalsPerDegree();
        double row = rowFraction * m, col = colFraction * m;
        double rr = Math.rint(row), rc = Math.rint(col);
        if (Math.abs(row - rr) < 1e-9) {
            row = rr;
        }
        if (Math.abs(col - rc) < 1e-9) {
            col = rc;
        }
        int r0 = Math.min(m - 1, (int) Math.floor(row)), c0 = Math.min(m - 1, (int) Math.floor(col));
        double fr = row - r0, fc = col - c0;
        double sum = 0;
        for (int dr = 0; dr < 2; dr++) {
            double wr = dr == 0 ? 1 - fr : fr;
            for (int dc = 0; dc < 2 && wr != 0; dc++) {
                double wc = dc == 0 ? 1 - fc : fc;
                if (wc == 0) {
                    continue;
                }
                if (t.isFilledVoid(r0 + dr, c0 + dc)) {
                    return Float.NaN;
                }
                sum += wr * wc * t.heightMetres(r0 + dr, c0 + dc);
            }
        }
        return (float) sum;
    }

    @Override
    public List<String> unreadFilesNamedFor(TileId id) {
        List<String> all = new ArrayList<>();
        for (DemSource s : sources) {
            all.addAll(s.unreadFilesNamedFor(id));
        }
        return all;
    }

    @Override
    public String describe() {
        StringBuilder b = new StringBuilder();
        for (DemSource s : sources) {
            b.append(b.length() == 0 ? "" : ", then ").append(s.describe());
        }
        return b.toString();
    }
}
