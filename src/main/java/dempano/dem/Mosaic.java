package dempano.dem;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * Heights of a block of one-degree tiles stitched into one grid. Neighbouring tiles share their
 * edge row/column, which appears once in the grid. Row 0 is the northern edge, column 0 the
 * western edge; the spacing is 1/{@link #intervalsPerDegree()} degree in both directions.
 * Samples of tiles the range circle does not touch are {@code NaN} (not loaded); missing tiles are
 * sea level (0 m) under {@link MissingTilePolicy#SEA_LEVEL}. Immutable.
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
    private final float[] heights;
    private final List<TileId> tilesUsed;
    private final List<TileId> tilesMissing;
    private final List<String> warnings;

    /** Per sample: {@link #FLAG_FILLED_VOID}, {@link #FLAG_MISSING_TILE} (null when none is set). */
    private final byte[] flags;
    /** A sample whose height was interpolated over a void. */
    public static final int FLAG_FILLED_VOID = 1;
    /** A sample of a missing tile (sea level stands in). */
    public static final int FLAG_MISSING_TILE = 2;

    private Mosaic(TileSelection sel, int intervalsPerDegree, float[] heights, List<TileId> used,
                   List<TileId> missing, List<String> warnings, byte[] flags) {
        this.flags = flags;
        this.latSouthDeg = sel.latSouthDeg();
        this.lonWestDeg = sel.lonWestDeg();
        this.tilesNorthSouth = sel.tilesNorthSouth();
        this.tilesEastWest = sel.tilesEastWest();
        this.intervalsPerDegree = intervalsPerDegree;
        this.rows = tilesNorthSouth * intervalsPerDegree + 1;
        this.cols = tilesEastWest * intervalsPerDegree + 1;
        this.heights = heights;
        this.tilesUsed = Collections.unmodifiableList(used);
        this.tilesMissing = Collections.unmodifiableList(missing);
        this.warnings = Collections.unmodifiableList(warnings);
    }

    /**
     * Loads and stitches the tiles that the range circle around a viewpoint touches.
     *
     * @param rangeMetres range of sight, metres
     * @throws DemException if a tile is unreadable, or missing under {@link MissingTilePolicy#ERROR}
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
        int ipd = 0;
        for (int r = 0; r < sel.tilesNorthSouth(); r++) {
            for (int c = 0; c < sel.tilesEastWest(); c++) {
                if (!sel.touched()[r][c]) {
                    continue;
                }
                TileId id = sel.tile(r, c);
                HgtTile t = source.tile(id).orElse(null);
                if (t != null && t.entirelyVoid()) {
                    warnings.add(id + " (" + t.source() + ") has no valid sample at all: treated as missing");
                    t = null;
                }
                if (t == null) {
                    if (policy == MissingTilePolicy.ERROR) {
                        throw new DemException("tile " + id + " is needed for the range of sight but "
                                + source.describe() + " has no usable file for it");
                    }
                    missing.add(id);
                    continue;
                }
                VoidReport v = t.voids();
                if (v.voidCells() > 0) {
                    String msg = String.format(Locale.ROOT,
                            "%s: %d void samples (%.2f %%) filled by interpolation; largest void region %d samples, %d samples across",
                            id, v.voidCells(), 100.0 * v.voidCells() / (t.samplesPerSide() * (double) t.samplesPerSide()),
                            v.largestRegionCells(), v.largestRegionSpanSamples());
                    if (v.hasLargeRegion()) {
                        warnings.add(msg + " (heights there are invented)");
                    }
                }
                tiles[r][c] = t;
                used.add(id);
                ipd = Math.max(ipd, t.intervalsPerDegree());
            }
        }
        if (!missing.isEmpty()) {
            warnings.add("no data for " + missing + " in " + source.describe() + ": treated as sea level (0 m)");
        }
        if (ipd == 0) {
            ipd = HgtTile.SRTM3_SAMPLES - 1; // only sea: keep SRTM3 spacing
        }
        int rows = sel.tilesNorthSouth() * ipd + 1, cols = sel.tilesEastWest() * ipd + 1;
        if ((long) rows * cols > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a mosaic of " + sel.tilesNorthSouth() + "×" + sel.tilesEastWest()
                    + " tiles at " + ipd + " samples per degree is too large; reduce the range");
        }
        float[] h = new float[rows * cols];
        Arrays.fill(h, Float.NaN);
        boolean anyFlag = !missing.isEmpty();
        for (HgtTile[] row : tiles) {
            for (HgtTile t : row) {
                anyFlag |= t != null && t.voids().voidCells() > 0;
            }
        }
        byte[] flags = anyFlag ? new byte[rows * cols] : null;
        // Missing tiles first, so that a present neighbour's values win on the shared edge.
        for (int r = 0; r < sel.tilesNorthSouth(); r++) {
            for (int c = 0; c < sel.tilesEastWest(); c++) {
                if (sel.touched()[r][c] && tiles[r][c] == null) {
                    fillBlock(h, cols, r * ipd, c * ipd, ipd, 0f);
                    for (int i = 0; i <= ipd; i++) {
                        Arrays.fill(flags, (r * ipd + i) * cols + c * ipd, (r * ipd + i) * cols + c * ipd + ipd + 1,
                                (byte) FLAG_MISSING_TILE);
                    }
                }
            }
        }
        for (int r = 0; r < sel.tilesNorthSouth(); r++) {
            for (int c = 0; c < sel.tilesEastWest(); c++) {
                HgtTile t = tiles[r][c];
                if (t != null) {
                    copyTile(h, cols, r * ipd, c * ipd, ipd, t);
                    if (flags != null) {
                        markVoids(flags, cols, r * ipd, c * ipd, ipd, t);
                    }
                }
            }
        }
        return new Mosaic(sel, ipd, h, used, missing, warnings, flags);
    }

    private static void markVoids(byte[] flags, int cols, int row0, int col0, int ipd, HgtTile t) {
        int step = ipd / t.intervalsPerDegree(); // a coarser tile beside finer ones: its samples on the finer grid
        for (int r = 0; r <= ipd; r++) {
            for (int c = 0; c <= ipd; c++) {
                int i = (row0 + r) * cols + col0 + c;
                // A present tile's samples win on an edge shared with a missing tile.
                flags[i] = (byte) (r % step == 0 && c % step == 0 && t.isFilledVoid(r / step, c / step) ? FLAG_FILLED_VOID : 0);
            }
        }
    }

    /** Debug flags of a sample ({@link #FLAG_FILLED_VOID}, {@link #FLAG_MISSING_TILE}); 0 for a plain sample. */
    public int flags(int row, int col) {
        return flags == null ? 0 : flags[row * cols + col];
    }

    private static void fillBlock(float[] h, int cols, int row0, int col0, int ipd, float value) {
        for (int r = 0; r <= ipd; r++) {
            Arrays.fill(h, (row0 + r) * cols + col0, (row0 + r) * cols + col0 + ipd + 1, value);
        }
    }

    private static void copyTile(float[] h, int cols, int row0, int col0, int ipd, HgtTile t) {
        if (t.intervalsPerDegree() == ipd) {
            for (int r = 0; r <= ipd; r++) {
                for (int c = 0; c <= ipd; c++) {
                    h[(row0 + r) * cols + col0 + c] = t.heightMetres(r, c);
                }
            }
            return;
        }
        // A coarser tile beside finer ones: resample bilinearly onto the finer grid.
        int latS = t.id().latSouthDeg(), lonW = t.id().lonWestDeg();
        for (int r = 0; r <= ipd; r++) {
            double lat = latS + 1 - (double) r / ipd;
            for (int c = 0; c <= ipd; c++) {
                h[(row0 + r) * cols + col0 + c] = (float) t.heightAt(lat, lonW + (double) c / ipd);
            }
        }
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

    /** Latitude of a grid row, degrees. */
    public double latOfRow(double row) {
        return latNorthDeg() - row / intervalsPerDegree;
    }

    /** Unwrapped longitude of a grid column, degrees. */
    public double lonOfCol(double col) {
        return lonWestDeg + col / intervalsPerDegree;
    }

    /** Fractional grid row of a latitude. */
    public double rowOf(double latDeg) {
        return (latNorthDeg() - latDeg) * intervalsPerDegree;
    }

    /** Fractional grid column of a longitude (either wrapping). */
    public double colOf(double lonDeg) {
        double unwrapped = lonWestDeg + (((lonDeg - lonWestDeg) % 360) + 360) % 360;
        return (unwrapped - lonWestDeg) * intervalsPerDegree;
    }

    /** Height of a sample, metres; NaN where the range circle did not need the tile. */
    public float sample(int row, int col) {
        return heights[row * cols + col];
    }

    /**
     * Bilinear height at a coordinate, metres; NaN outside the block or where a tile was not loaded.
     */
    public double heightAt(double latDeg, double lonDeg) {
        double row = rowOf(latDeg), col = colOf(lonDeg);
        if (!(row >= 0 && row <= rows - 1 && col >= 0 && col <= cols - 1)) {
            return Double.NaN;
        }
        int r = Math.min(rows - 2, (int) row), c = Math.min(cols - 2, (int) col);
        double fr = row - r, fc = col - c;
        double h00 = sample(r, c), h01 = sample(r, c + 1), h10 = sample(r + 1, c), h11 = sample(r + 1, c + 1);
        // Exactly on a sample or edge, weights of zero must not let a NaN neighbour through.
        return lerp(lerp(h00, h01, fc), lerp(h10, h11, fc), fr);
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

    /** Tiles read from the source, north to south, west to east. */
    public List<TileId> tilesUsed() {
        return tilesUsed;
    }

    /** Tiles needed but absent (held as sea level). */
    public List<TileId> tilesMissing() {
        return tilesMissing;
    }

    /** Warnings for the user: missing tiles, large void regions. */
    public List<String> warnings() {
        return warnings;
    }
}
