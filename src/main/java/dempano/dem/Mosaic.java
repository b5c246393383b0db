package dempano.dem;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * Heights of a block of one-degree tiles stitched into one grid. Neighbouring tiles share their
 * edge row/column, which appears once in the grid. Row 0 is the northern edge, column 0 the
 * western edge; the spacing is 1/{@link #intervalsPerDegree()} degree in both directions.
 * Samples of tiles the range circle does not touch are {@code NaN} (not loaded); missing tiles are
 * sea level (0 m) under {@link MissingTilePolicy#SEA_LEVEL} and {@link MissingTilePolicy#AUTO}. Immutable.
 *
 * <p>The grid is a view on the tiles, not a copy: each sample is read from the tile that holds it,
 * so a block of 7×9 SRTM1 tiles of which most are sea costs the memory of its present tiles only,
 * and building a mosaic from cached tiles costs nothing. On an edge shared by two present tiles the
 * southern (eastern) tile's sample is used; a present tile's sample wins over a missing
 * neighbour's sea level. A tile coarser than the grid (SRTM3 beside SRTM1) is interpolated
 * bilinearly onto it.
 *
 * <p>Longitudes are unwrapped: a block crossing the antimeridian has {@link #lonWestDeg()} + width
 * beyond 180, and {@link #heightAt} accepts longitudes either way.
 */
public final class Mosaic {
    private final int latSouthDeg;
    private final int lonWestDeg;
    private final int tilesNorthSouth;
    private final int tilesEastWest;
    private final int intervalsPerDegree;
    private final int rows;
    private final int cols;
    /** Block tiles, row 0 north; null where missing or not touched. */
    private final HgtTile[][] tiles;
    /** Per block tile: held as sea level (missing). Null and not sea level = not loaded (NaN). */
    private final boolean[][] seaLevel;
    private final List<TileId> tilesUsed;
    private final List<TileId> tilesMissing;
    private final List<String> warnings;
    private final String sourceDescription;
    private final java.util.Map<TileId, List<DemContribution>> tileSources;

    /** A sample whose height was interpolated over a void. */
    public static final int FLAG_FILLED_VOID = 1;
    /** A sample of a missing tile (sea level stands in). */
    public static final int FLAG_MISSING_TILE = 2;

    // locate() results that are no tile sample.
    private static final long NOT_LOADED = -1, SEA_LEVEL = -2;
    /**
     * Per sample row and column: its tile row (column) of the grid, min(row / n, tiles − 1), looked up
     * instead of divided (two integer divisions per sample were most of {@link #sample}'s time).
     */
    private final int[] tileOfRow, tileOfCol;

    private Mosaic(TileSelection sel, int intervalsPerDegree, HgtTile[][] tiles, boolean[][] seaLevel, List<TileId> used,
                   List<TileId> missing, List<String> warnings, String sourceDescription) {
        this.latSouthDeg = sel.latSouthDeg();
        this.lonWestDeg = sel.lonWestDeg();
        this.tilesNorthSouth = sel.tilesNorthSouth();
        this.tilesEastWest = sel.tilesEastWest();
        this.intervalsPerDegree = intervalsPerDegree;
        this.rows = tilesNorthSouth * intervalsPerDegree + 1;
        this.cols = tilesEastWest * intervalsPerDegree + 1;
        this.tileOfRow = new int[rows];
        for (int r = 0; r < rows; r++) {
            tileOfRow[r] = Math.min(r / intervalsPerDegree, tilesNorthSouth - 1);
        }
        this.tileOfCol = new int[cols];
        for (int c = 0; c < cols; c++) {
            tileOfCol[c] = Math.min(c / intervalsPerDegree, tilesEastWest - 1);
        }
        this.tiles = tiles;
        this.seaLevel = seaLevel;
        this.tilesUsed = Collections.unmodifiableList(used);
        this.tilesMissing = Collections.unmodifiableList(missing);
        this.warnings = Collections.unmodifiableList(warnings);
        this.sourceDescription = sourceDescription;
        java.util.Map<TileId, List<DemContribution>> bySource = new java.util.LinkedHashMap<>();
        for (HgtTile[] row : tiles) {
            for (HgtTile t : row) {
                if (t != null) {
                    bySource.put(t.id(), t.contributions());
                }
            }
        }
        this.tileSources = Collections.unmodifiableMap(bySource);
    }

    /**
     * Loads and stitches the tiles that the range circle around a viewpoint touches.
     *
     * @param rangeMetres range of sight, metres
     * @throws DemException if a needed tile is unreadable or ambiguous, or tiles are missing under
     *                      {@link MissingTilePolicy#ERROR} (all of them listed). The checks of
     *                      {@link MissingTilePolicy#AUTO} that need the viewpoint's altitude are
     *                      {@link MissingTilePolicy#checkData}'s.
     * @throws IllegalArgumentException for coordinates off the globe or a bad range
     */
    public static Mosaic around(DemSource source, double latDeg, double lonDeg, double rangeMetres,
                                MissingTilePolicy policy) {
        return of(source, TileSelection.around(latDeg, lonDeg, rangeMetres), policy);
    }

    /** Loads and stitches the touched tiles of a selection. */
    public static Mosaic of(DemSource source, TileSelection sel, MissingTilePolicy policy) {
        List<TileId> used = new ArrayList<>();
        List<TileId> missing = new ArrayList<>();
        List<String> warnings = new ArrayList<>();
        HgtTile[][] tiles = new HgtTile[sel.tilesNorthSouth()][sel.tilesEastWest()];
        boolean[][] seaLevel = new boolean[sel.tilesNorthSouth()][sel.tilesEastWest()];
        int ipd = 0;
        for (int r = 0; r < sel.tilesNorthSouth(); r++) {
            for (int c = 0; c < sel.tilesEastWest(); c++) {
                if (!sel.touched()[r][c]) {
                    continue;
                }
                TileId id = sel.tile(r, c);
                HgtTile t = source.tile(id).orElse(null);
                if (t != null && t.entirelyVoid()) {
                    warnings.add(id + " (" + t.source() + ") " + MissingTilePolicy.ENTIRELY_VOID + ": treated as missing");
                    t = null;
                }
                if (t == null) {
                    missing.add(id);
                    seaLevel[r][c] = true;
                    continue;
                }
                VoidReport v = t.voids();
                if (v.voidCells() > 0 && v.hasLargeRegion()) {
                    warnings.add(String.format(Locale.ROOT,
                            "%s: %d void samples (%.2f %%) filled by interpolation; largest void region %d samples, "
                                    + "%d samples across (heights there are invented)",
                            id, v.voidCells(), 100.0 * v.voidCells() / (t.samplesPerSide() * (double) t.samplesPerSide()),
                            v.largestRegionCells(), v.largestRegionSpanSamples()));
                }
                warnings.addAll(t.warnings());
                tiles[r][c] = t;
                used.add(id);
                ipd = Math.max(ipd, t.intervalsPerDegree());
            }
        }
        List<String> unread = new ArrayList<>(); // files there for a missing tile under a name not read: a hint
        for (TileId id : missing) {
            unread.addAll(source.unreadFilesNamedFor(id));
        }
        if (!missing.isEmpty() && policy == MissingTilePolicy.ERROR) {
            throw new DemException((missing.size() == 1 ? "tile " + missing.get(0) + " is" : missing.size() + " tiles "
                    + missing + " are") + " needed for the range of sight but " + source.describe()
                    + " has no usable file for " + (missing.size() == 1 ? "it" : "them") + " (--missing-tiles error)"
                    + (unread.isEmpty() ? "" : "; " + unreadHint(unread)));
        }
        warnings.addAll(Plausibility.edgeMismatches(tiles));
        String datums = mixedDatums(tiles);
        if (datums != null) {
            warnings.add(datums);
        }
        if (!missing.isEmpty()) {
            warnings.add("no data for " + missing + " in " + source.describe() + ": treated as sea level (0 m)");
        }
        if (!unread.isEmpty()) {
            warnings.add(unreadHint(unread));
        }
        if (ipd == 0) {
            ipd = HgtTile.SRTM3_SAMPLES - 1; // only sea: keep SRTM3 spacing
        }
        long rows = (long) sel.tilesNorthSouth() * ipd + 1, cols = (long) sel.tilesEastWest() * ipd + 1;
        if (rows * cols > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a mosaic of " + sel.tilesNorthSouth() + "×" + sel.tilesEastWest()
                    + " tiles at " + ipd + " samples per degree is too large; reduce the range");
        }
        return new Mosaic(sel, ipd, tiles, seaLevel, used, missing, warnings, source.describe());
    }

    /**
     * A warning when the tiles' heights refer to different vertical datums (Copernicus' EGM2008 beside
     * SRTM's EGM96), or null. Known datums only: "unknown" is compatible with anything.
     */
    static String mixedDatums(HgtTile[][] tiles) {
        java.util.Set<String> datums = new java.util.TreeSet<>();
        for (HgtTile[] row : tiles) {
            for (HgtTile t : row) {
                if (t != null) {
                    for (DemContribution c : t.contributions()) {
                        if (c.samples() > 0 && !c.verticalDatum().equals(DemContribution.UNKNOWN)) {
                            datums.add(c.verticalDatum());
                        }
                    }
                }
            }
        }
        return datums.size() < 2 ? null : "the DEM heights refer to different vertical datums " + datums
                + ", used as they are: they differ by the difference of the geoid models (mostly under 1 m, a few metres "
                + "in places)";
    }

    /**
     * Which tile holds grid sample (row, col): packed block tile row/column and the sample's row and
     * column in grid units inside that tile, or {@link #SEA_LEVEL} / {@link #NOT_LOADED}.
     */
    private long locate(int row, int col) {
        int n = intervalsPerDegree;
        if (row < 0 || col < 0 || row >= rows || col >= cols) {
            throw new IndexOutOfBoundsException("sample (" + row + ", " + col + ") outside the " + rows + "×" + cols + " mosaic");
        }
        int tr = tileOfRow[row], tc = tileOfCol[col];
        int lr = row - tr * n, lc = col - tc * n;
        if (tiles[tr][tc] != null) {
            return pack(tr, tc, lr, lc);
        }
        boolean north = lr == 0 && tr > 0, west = lc == 0 && tc > 0;
        if (north && tiles[tr - 1][tc] != null) {
            return pack(tr - 1, tc, n, lc);
        }
        if (west && tiles[tr][tc - 1] != null) {
            return pack(tr, tc - 1, lr, n);
        }
        if (north && west && tiles[tr - 1][tc - 1] != null) {
            return pack(tr - 1, tc - 1, n, n);
        }
        if (seaLevel[tr][tc] || north && seaLevel[tr - 1][tc] || west && seaLevel[tr][tc - 1]
                || north && west && seaLevel[tr - 1][tc - 1]) {
            return SEA_LEVEL;
        }
        return NOT_LOADED;
    }

    private static long pack(int tileRow, int tileCol, int localRow, int localCol) {
        return ((long) tileRow << 52) | ((long) tileCol << 40) | ((long) localRow << 20) | localCol;
    }

    /**
     * Heights of {@code count} samples of one row from column {@code col} on, into {@code out} from
     * {@code offset}: each exactly {@link #sample(int, int)}, read a tile's run at a time.
     *
     * @throws IndexOutOfBoundsException for samples outside the mosaic
     */
    public void sampleRow(int row, int col, int count, float[] out, int offset) {
        if (row < 0 || col < 0 || row >= rows || col + count > cols || count < 0) {
            throw new IndexOutOfBoundsException("samples (" + row + ", " + col + "…+" + count + ") outside the " + rows
                    + "×" + cols + " mosaic");
        }
        int n = intervalsPerDegree, tr = Math.min(row / n, tilesNorthSouth - 1), lr = row - tr * n;
        int c = col, end = col + count;
        while (c < end) {
            int tc = Math.min(c / n, tilesEastWest - 1);
            HgtTile t = tiles[tr][tc];
            if (t != null && t.intervalsPerDegree() == n) {
                // The columns this tile serves (as locate() assigns them): up to its east edge, the last tile's included.
                int stop = Math.min(end, tc == tilesEastWest - 1 ? cols : (tc + 1) * n);
                int first = tc * n;
                for (; c < stop; c++) {
                    out[offset + c - col] = t.heightMetres(lr, c - first);
                }
            } else if (t == null && lr > 0 && c > tc * n) {
                // Inside a missing tile, off its north row and west column (which a neighbour may serve):
                // every sample is the tile's one value, as locate() decides it.
                int stop = Math.min(end, tc == tilesEastWest - 1 ? cols : (tc + 1) * n);
                java.util.Arrays.fill(out, offset + c - col, offset + stop - col, seaLevel[tr][tc] ? 0f : Float.NaN);
                c = stop;
            } else {
                out[offset + c - col] = sample(row, c);
                c++;
            }
        }
    }

    /**
     * What this mosaic's samples are made of, held weakly: its tile grid (south-west corner, tiles
     * each way, samples per degree), the tile object in every slot and which slots are sea level.
     * Tiles are immutable, so another mosaic that {@link SampleIdentity#matches} it has the very same
     * sample at every (row, column): what a cache of values derived from the samples (the ray
     * probe's maximum pyramid) may be keyed on. A slot whose tile was since collected never matches.
     */
    public SampleIdentity sampleIdentity() {
        return new SampleIdentity(this);
    }

    /** See {@link #sampleIdentity()}. */
    public static final class SampleIdentity {
        private final int latSouthDeg, lonWestDeg, tilesNorthSouth, tilesEastWest, intervalsPerDegree;
        private final java.lang.ref.WeakReference<?>[][] tiles;
        private final boolean[][] seaLevel;

        private SampleIdentity(Mosaic m) {
            latSouthDeg = m.latSouthDeg;
            lonWestDeg = m.lonWestDeg;
            tilesNorthSouth = m.tilesNorthSouth;
            tilesEastWest = m.tilesEastWest;
            intervalsPerDegree = m.intervalsPerDegree;
            tiles = new java.lang.ref.WeakReference<?>[tilesNorthSouth][tilesEastWest];
            seaLevel = new boolean[tilesNorthSouth][];
            for (int r = 0; r < tilesNorthSouth; r++) {
                for (int c = 0; c < tilesEastWest; c++) {
                    tiles[r][c] = m.tiles[r][c] == null ? null : new java.lang.ref.WeakReference<>(m.tiles[r][c]);
                }
                seaLevel[r] = m.seaLevel[r].clone();
            }
        }

        /** Whether {@code m} has the same tile grid, the same tile object in every slot and the same sea-level slots. */
        public boolean matches(Mosaic m) {
            if (m.latSouthDeg != latSouthDeg || m.lonWestDeg != lonWestDeg || m.tilesNorthSouth != tilesNorthSouth
                    || m.tilesEastWest != tilesEastWest || m.intervalsPerDegree != intervalsPerDegree) {
                return false;
            }
            for (int r = 0; r < tilesNorthSouth; r++) {
                if (!java.util.Arrays.equals(seaLevel[r], m.seaLevel[r])) {
                    return false;
                }
                for (int c = 0; c < tilesEastWest; c++) {
                    HgtTile t = m.tiles[r][c];
                    if (t == null ? tiles[r][c] != null : tiles[r][c] == null || tiles[r][c].get() != t) {
                        return false;
                    }
                }
            }
            return true;
        }
    }

    /** Height of a sample, metres; NaN where the range circle did not need the tile. */
    public float sample(int row, int col) {
        if (row >= 0 && col >= 0 && row < rows && col < cols) {
            // Most samples: the tile is there at the mosaic's resolution; what locate() and the general path below
            // would give, without packing and unpacking its result (the ray probe asks millions a panorama).
            int tr = tileOfRow[row], tc = tileOfCol[col];
            HgtTile t = tiles[tr][tc];
            if (t != null && t.intervalsPerDegree() == intervalsPerDegree) {
                return t.heightMetres(row - tr * intervalsPerDegree, col - tc * intervalsPerDegree);
            }
        }
        long at = locate(row, col);
        if (at < 0) {
            return at == SEA_LEVEL ? 0f : Float.NaN;
        }
        HgtTile t = tiles[(int) (at >>> 52)][(int) (at >>> 40) & 0xfff];
        int lr = (int) (at >>> 20) & 0xfffff, lc = (int) at & 0xfffff;
        int tn = t.intervalsPerDegree(), n = intervalsPerDegree;
        if (tn == n) {
            return t.heightMetres(lr, lc);
        }
        // A coarser tile beside finer ones: bilinear on its own grid.
        double r = (double) lr * tn / n, c = (double) lc * tn / n;
        int r0 = Math.min(tn - 1, (int) r), c0 = Math.min(tn - 1, (int) c);
        double fr = r - r0, fc = c - c0;
        return (float) dempano.util.Bilinear.interpolate(t.heightMetres(r0, c0), t.heightMetres(r0, c0 + 1),
                t.heightMetres(r0 + 1, c0), t.heightMetres(r0 + 1, c0 + 1), fr, fc);
    }

    /**
     * Debug flags of a sample ({@link #FLAG_FILLED_VOID}, {@link #FLAG_MISSING_TILE}); 0 for a plain
     * sample and for one not loaded.
     */
    public int flags(int row, int col) {
        long at = locate(row, col);
        if (at < 0) {
            return at == SEA_LEVEL ? FLAG_MISSING_TILE : 0;
        }
        HgtTile t = tiles[(int) (at >>> 52)][(int) (at >>> 40) & 0xfff];
        long lr = (at >>> 20) & 0xfffff, lc = at & 0xfffff;
        int tn = t.intervalsPerDegree(), n = intervalsPerDegree;
        boolean onTileGrid = lr * tn % n == 0 && lc * tn % n == 0;
        return onTileGrid && t.isFilledVoid((int) (lr * tn / n), (int) (lc * tn / n)) ? FLAG_FILLED_VOID : 0;
    }

    /** Southern edge of the block, degrees. */
    public int latSouthDeg() {
        return latSouthDeg;
    }

    /** Northern edge of the block, degrees. */
    public int latNorthDeg() {
        return latSouthDeg + tilesNorthSouth;
    }

    /** Western edge, degrees, unwrapped (see class comment). */
    public int lonWestDeg() {
        return lonWestDeg;
    }

    public int tilesNorthSouth() {
        return tilesNorthSouth;
    }

    public int tilesEastWest() {
        return tilesEastWest;
    }

    /** Sample intervals per degree (1200 for SRTM3, 3600 for SRTM1). */
    public int intervalsPerDegree() {
        return intervalsPerDegree;
    }

    public int rows() {
        return rows;
    }

    public int cols() {
        return cols;
    }

    /**
     * Latitude of a grid row, degrees. For a whole row the same bits whatever block the mosaic covers: one rounding
     * of an exact quotient (whole sample intervals from the equator over intervals per degree), so that a sample
     * placed from two mosaics (two viewpoints of a batch, a cached mesh and this render's probe) is placed alike.
     * ({@code north − row / n}, two roundings, gave another last bit for another north edge.)
     */
    public double latOfRow(double row) {
        return ((double) latNorthDeg() * intervalsPerDegree - row) / intervalsPerDegree;
    }

    /** Unwrapped longitude of a grid column, degrees; for a whole column one rounding, as {@link #latOfRow}. */
    public double lonOfCol(double col) {
        return ((double) lonWestDeg * intervalsPerDegree + col) / intervalsPerDegree;
    }

    /**
     * Longitude of a grid column wrapped into [−180°, 180°), degrees: the same bits for the same meridian whatever
     * the mosaic, also across the antimeridian (where {@link #lonOfCol} is 181° in one block and −179° in another).
     * For trigonometry.
     */
    public double wrappedLonOfCol(int col) {
        long n = intervalsPerDegree;
        long east = Math.floorMod(lonWestDeg * n + col + 180 * n, 360 * n);
        return (double) (east - 180 * n) / n;
    }

    /** Fractional grid row of a latitude. */
    public double rowOf(double latDeg) {
        return (latNorthDeg() - latDeg) * intervalsPerDegree;
    }

    /** Fractional grid column of a longitude (either wrapping). */
    public double colOf(double lonDeg) {
        double east = lonDeg - lonWestDeg, shifted = east + 360;
        // Within a turn east (every call of the ray probe) the remainders are one subtraction, to the bit:
        // (east % 360 + 360) % 360 is then fl(east + 360) − 360, exact. Two remainders were a third of its time.
        double unwrapped = lonWestDeg + (east >= 0 && shifted < 720 ? shifted - 360 : ((east % 360) + 360) % 360);
        return (unwrapped - lonWestDeg) * intervalsPerDegree;
    }

    /**
     * Height of the drawn surface at a coordinate, metres: linear on the {@link Triangulation} triangle of its cell
     * that holds it, as both renderers draw it (the bilinear height differs from it by up to a quarter of the cell's
     * corner heights' twist: 18 m at the centre of a cell with corners 593, 546 / 443, 469 m, where an eye 2 m above
     * the bilinear height was inside the drawn terrain). NaN outside the block or where a tile was not loaded.
     */
    public double heightAt(double latDeg, double lonDeg) {
        double row = rowOf(latDeg), col = colOf(lonDeg);
        if (!(row >= 0 && row <= rows - 1 && col >= 0 && col <= cols - 1)) {
            return Double.NaN;
        }
        int r = Math.min(rows - 2, (int) row), c = Math.min(cols - 2, (int) col);
        double fr = row - r, fc = col - c;
        double h00 = sample(r, c), h01 = sample(r, c + 1), h10 = sample(r + 1, c), h11 = sample(r + 1, c + 1);
        // Exactly on a sample or edge, weights of zero must not let a NaN neighbour through (a tile not loaded
        // beside the block's edge): there the edge's own samples decide, as they do in every triangle holding it.
        if (fr == 0 || fr == 1 || fc == 0 || fc == 1) {
            return lerp(lerp(h00, h01, fc), lerp(h10, h11, fc), fr);
        }
        return Triangulation.heightIn(r, c, h00, h01, h10, h11, fr, fc);
    }

    private static double lerp(double a, double b, double t) {
        if (t == 0) {
            return a;
        }
        if (t == 1) {
            return b;
        }
        return a + (b - a) * t;
    }

    /**
     * A slot of the mosaic's tile grid that it samples: the tile's id and the tile itself, or null where the slot
     * is held at sea level (no tile, or an entirely void one).
     */
    public record TileSlot(TileId id, HgtTile tile) {
    }

    /**
     * The slots this mosaic samples, north to south, west to east; slots the range did not need are left out.
     * Tiles are immutable: a cache of values derived from the samples can tell by the tile objects (and their
     * {@link HgtTile#contentHash()}) whether the heights it was made from are still those of the source.
     */
    public List<TileSlot> tileSlots() {
        List<TileSlot> out = new ArrayList<>();
        for (int r = 0; r < tilesNorthSouth; r++) {
            for (int c = 0; c < tilesEastWest; c++) {
                if (tiles[r][c] != null || seaLevel[r][c]) {
                    out.add(new TileSlot(TileId.of(latSouthDeg + tilesNorthSouth - 1 - r, lonWestDeg + c), tiles[r][c]));
                }
            }
        }
        return out;
    }

    /** Tiles read from the source, north to south, west to east. */
    public List<TileId> tilesUsed() {
        return tilesUsed;
    }

    /** Tiles needed but absent (held as sea level). */
    public List<TileId> tilesMissing() {
        return tilesMissing;
    }

    /** Bytes the heights of the tiles used take (float tiles, e.g. Copernicus, 4 per sample, SRTM 2). */
    public long tileBytes() {
        long sum = 0;
        for (HgtTile[] row : tiles) {
            for (HgtTile t : row) {
                sum += t == null ? 0 : t.heightBytes();
            }
        }
        return sum;
    }

    /**
     * For each tile used (in {@link #tilesUsed()} order), which sources served how many of its samples
     * and their vertical datums (see {@link HgtTile#contributions()}).
     */
    public java.util.Map<TileId, List<DemContribution>> tileSources() {
        return tileSources;
    }

    /** The DEM source's description (e.g. its folder), for messages. */
    public String sourceDescription() {
        return sourceDescription;
    }

    /** Warnings for the user: missing tiles, large void regions, implausible tiles, disagreeing edges. */
    public List<String> warnings() {
        return warnings;
    }

    /** How a missing tile's file that is there under a name not read is hinted at (in a warning, and in the errors). */
    static final String NOT_READ = "named for a missing tile but not read as one";

    static String unreadHint(List<String> files) {
        return (files.size() == 1 ? files.get(0) + " is " : files + " are ") + NOT_READ + " (" + TileId.expectedNames()
                + "); rename " + (files.size() == 1 ? "it" : "them") + " if " + (files.size() == 1 ? "it is" : "they are")
                + " the tile";
    }
}
