package dempano.dem;

import java.util.Objects;

/**
 * One SRTM tile's heights after void filling. Immutable: the height array is never exposed.
 * Row 0 is the northern edge, column 0 the western edge; samples lie on the tile's edges, so the
 * last row/column repeats the first row/column of the neighbour.
 */
public final class HgtTile {
    /** SRTM3: 3 arc-seconds. */
    public static final int SRTM3_SAMPLES = 1201;
    /** SRTM1: 1 arc-second. */
    public static final int SRTM1_SAMPLES = 3601;

    private final TileId id;
    private final String source;
    private final int samplesPerSide;
    /** Heights when all are whole metres in int16 range (SRTM without voids): half the memory. */
    private final short[] wholeMetres;
    /** Heights otherwise (filled voids, synthetic terrain). Exactly one of the two is non-null. */
    private final float[] heightsMetres;
    private final VoidReport voids;
    private final java.util.BitSet filledVoids;
    private final java.util.List<String> warnings;
    private final String verticalDatum;
    /** Null: one contribution, this tile's own source (computed on demand). */
    private final java.util.List<DemContribution> contributions;

    HgtTile(TileId id, String source, int samplesPerSide, float[] heightsMetres, VoidReport voids) {
        this(id, source, samplesPerSide, heightsMetres, voids, new java.util.BitSet());
    }

    HgtTile(TileId id, String source, int samplesPerSide, float[] heightsMetres, VoidReport voids,
            java.util.BitSet filledVoids) {
        this(id, source, samplesPerSide, heightsMetres, voids, filledVoids, java.util.List.of());
    }

    HgtTile(TileId id, String source, int samplesPerSide, float[] heightsMetres, VoidReport voids,
            java.util.BitSet filledVoids, java.util.List<String> warnings) {
        this.warnings = java.util.List.copyOf(warnings);
        this.filledVoids = (java.util.BitSet) filledVoids.clone();
        this.id = Objects.requireNonNull(id);
        this.source = Objects.requireNonNull(source);
        if (heightsMetres.length != samplesPerSide * samplesPerSide) {
            throw new IllegalArgumentException("heights do not match " + samplesPerSide + "²");
        }
        this.samplesPerSide = samplesPerSide;
        // One pass: the heights as whole metres where they all are, and their fingerprint (contentHash).
        short[] whole = new short[heightsMetres.length];
        boolean allWhole = true;
        long hash = 0xCBF29CE484222325L ^ samplesPerSide;
        for (int i = 0; i < heightsMetres.length; i++) {
            float h = heightsMetres[i];
            hash = (hash ^ (Float.floatToRawIntBits(h) & 0xFFFFFFFFL)) * FNV_PRIME;
            short w = (short) h;
            whole[i] = w;
            allWhole &= w == h; // not a whole number of metres in range (or NaN): keep floats
        }
        this.wholeMetres = allWhole ? whole : null;
        this.heightsMetres = allWhole ? null : heightsMetres;
        this.voids = Objects.requireNonNull(voids);
        this.verticalDatum = DemContribution.UNKNOWN;
        this.contributions = null;
        for (long word : this.filledVoids.toLongArray()) {
            hash = (hash ^ word) * FNV_PRIME;
        }
        hash ^= hash >>> 33; // a final mix (MurmurHash3's), so that every bit depends on every sample
        hash *= 0xFF51AFD7ED558CCDL;
        this.contentHash = hash ^ (hash >>> 33);
    }

    /** A copy sharing the (immutable) heights, with another datum and contributions. */
    private HgtTile(HgtTile t, String verticalDatum, java.util.List<DemContribution> contributions) {
        this.id = t.id;
        this.source = t.source;
        this.samplesPerSide = t.samplesPerSide;
        this.wholeMetres = t.wholeMetres;
        this.heightsMetres = t.heightsMetres;
        this.voids = t.voids;
        this.filledVoids = t.filledVoids;
        this.warnings = t.warnings;
        this.verticalDatum = Objects.requireNonNull(verticalDatum);
        this.contributions = contributions == null ? null : java.util.List.copyOf(contributions);
        this.contentHash = t.contentHash;
    }

    /** This tile with its heights' vertical datum set (see {@link DemContribution#verticalDatum()}). */
    HgtTile withVerticalDatum(String datum) {
        return new HgtTile(this, datum, contributions);
    }

    /** This tile with the sources its samples came from (for tiles merged from several sources). */
    HgtTile withContributions(java.util.List<DemContribution> sources) {
        return new HgtTile(this, verticalDatum, sources);
    }

    /**
     * A tile from heights in metres (row 0 north). Voids ({@code NaN}) are filled as when reading.
     * For synthetic terrain and tests.
     */
    public static HgtTile of(TileId id, int samplesPerSide, float[] heightsMetres, String source) {
        if (samplesPerSide < 2 || heightsMetres.length != samplesPerSide * samplesPerSide) {
            throw new IllegalArgumentException("need " + samplesPerSide + "² heights, got " + heightsMetres.length);
        }
        float[] copy = heightsMetres.clone();
        java.util.BitSet mask = VoidFiller.voidMask(copy);
        VoidReport report = VoidFiller.fill(copy, samplesPerSide);
        return new HgtTile(id, source, samplesPerSide, copy, report, mask);
    }

    public TileId id() {
        return id;
    }

    /** Where the tile came from (file path or a description). */
    public String source() {
        return source;
    }

    /** 1201 (SRTM3), 3601 (SRTM1) or another size for synthetic tiles. */
    public int samplesPerSide() {
        return samplesPerSide;
    }

    /** Sample intervals per degree: samplesPerSide − 1. */
    public int intervalsPerDegree() {
        return samplesPerSide - 1;
    }

    /** Height in metres at a sample; row 0 north, column 0 west. */
    public float heightMetres(int row, int col) {
        int i = row * samplesPerSide + col;
        return wholeMetres != null ? wholeMetres[i] : heightsMetres[i];
    }

    /** Bytes the heights take: 2 per sample when all are whole metres in int16 range, else 4. */
    public long heightBytes() {
        return (wholeMetres != null ? 2L : 4L) * samplesPerSide * samplesPerSide;
    }

    private static final long FNV_PRIME = 0x100000001B3L;
    /** See {@link #contentHash()}. */
    private final long contentHash;

    /**
     * A 64-bit fingerprint of what is drawn from this tile: its size, every height (bit for bit) and which samples
     * are filled voids; not its source, datum or warnings. Tiles with the same heights have the same fingerprint;
     * tiles that differ anywhere have different ones except by a chance of about 2⁻⁶⁴ (FNV-1a over the samples, then
     * a final mix; not made to resist crafted collisions). Computed when the tile is made, in the pass that already
     * reads every height: caches of values derived from a tile's samples tell by it whether a tile read again (its
     * file rewritten, or evicted and read back) holds the same heights.
     */
    public long contentHash() {
        return contentHash;
    }

    /** True if the sample was a void, its height now interpolated. */
    public boolean isFilledVoid(int row, int col) {
        return filledVoids.get(row * samplesPerSide + col);
    }

    /**
     * The vertical datum of the heights: {@code EGM96} for .hgt files, from the GeoTIFF keys or the
     * Copernicus naming for GeoTIFFs, {@code unknown} for synthetic tiles; for a tile merged from
     * several sources, the primary source's (each source's is in {@link #contributions()}).
     */
    public String verticalDatum() {
        return verticalDatum;
    }

    /**
     * Which sources served this tile's samples and how many each: one entry (this tile's file, its
     * valid samples) for a tile read from one file; the primary source first, then the sources that
     * filled its voids, for a tile merged by {@link PriorityDem}. Samples are counted on this tile's
     * grid; the rest (voids no source had) were interpolated and are in {@link #voids()}.
     */
    public java.util.List<DemContribution> contributions() {
        if (contributions != null) {
            return contributions;
        }
        long valid = (long) samplesPerSide * samplesPerSide - filledVoids.cardinality();
        return java.util.List.of(new DemContribution(source, verticalDatum, valid));
    }

    /** What void filling found and did. */
    public VoidReport voids() {
        return voids;
    }

    /**
     * What reading found implausible in the data (cheap checks: rows of zeros below land, needles,
     * see {@link HgtReader#decode}); each names the file and the figures. Empty for synthetic tiles.
     */
    public java.util.List<String> warnings() {
        return warnings;
    }

    /** True if the tile had no valid sample at all (then it holds sea level and is treated as missing). */
    public boolean entirelyVoid() {
        return voids.voidCells() == (long) samplesPerSide * samplesPerSide;
    }

    /** Bilinear height at a position inside the tile, metres. */
    public double heightAt(double latDeg, double lonDeg) {
        double row = (id.latSouthDeg() + 1 - latDeg) * intervalsPerDegree();
        double col = (lonDeg - id.lonWestDeg()) * intervalsPerDegree();
        int r = Math.max(0, Math.min(samplesPerSide - 2, (int) Math.floor(row)));
        int c = Math.max(0, Math.min(samplesPerSide - 2, (int) Math.floor(col)));
        double fr = row - r, fc = col - c;
        double h00 = heightMetres(r, c), h01 = heightMetres(r, c + 1);
        double h10 = heightMetres(r + 1, c), h11 = heightMetres(r + 1, c + 1);
        return dempano.util.Bilinear.interpolate(h00, h01, h10, h11, fr, fc);
    }

    @Override
    public String toString() {
        return id.name() + " (" + samplesPerSide + "², " + source + ")";
    }
}
