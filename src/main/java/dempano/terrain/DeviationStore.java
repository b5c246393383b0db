package dempano.terrain;

import dempano.io.AtomicFiles;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Patch deviations ({@link DeviationCache}'s values) kept on disk from one process to the next, so that
 * a panorama from the shell does not measure again the patches an earlier run measured (about half of
 * a cold mesh stage: 0.5 s of a Mount Washington panorama's 3.8 s).
 *
 * <p>Cache contract. An entry is served only for the very heights it was measured from: each holds two
 * independent 64-bit hashes of the patch's drawn heights ({@link #hashA}, {@link #hashB}: the
 * (PATCH_INTERVALS + 1)² floats the measurement reads), and a lookup hashes the heights it has now. A
 * changed tile, another DEM source, a void filled otherwise: other heights, other hashes, a miss, and
 * the patch is measured again and its entry replaced. What else the values depend on (the measurement's
 * code, {@link TerrainBuilder#PATCH_INTERVALS}, the levels) is in each file's header ({@link #FORMAT}):
 * a file of another format is ignored and rewritten. A file that cannot be read (truncated, corrupt: each ends
 * with a CRC-32 of all its bytes, so a flipped bit in a stored value, which the heights' hashes do not cover, is
 * caught too) is ignored the same way; one that cannot be written (a read-only folder, a full disk) leaves the run as
 * it would be without the store ({@link #lastWriteError()} says why). Files are replaced whole
 * (written aside, then renamed), so a reader sees a complete file, an old one or none; two processes
 * writing one file at once lose one's new entries, never correctness.
 *
 * <p>Layout: one file per group of 16 × 16 patches of one grid ({@code <dir>/<intervals per degree>/<row
 * group>_<column group>.dev}), about 20 KB. Thread-safe.
 */
public final class DeviationStore {
    /** Bumped whenever what an entry holds, or how it is measured, changes. */
    static final int FORMAT = 2; // 2: a CRC-32 at the end
    private static final int MAGIC = 0x44504456; // "DPDV"
    /** Patches per group side. */
    private static final int GROUP = 16;

    private final Path dir;
    private final Map<GroupKey, Group> groups = new ConcurrentHashMap<>();
    private volatile String lastWriteError;
    private final java.util.concurrent.atomic.LongAdder hits = new java.util.concurrent.atomic.LongAdder();
    private final java.util.concurrent.atomic.LongAdder misses = new java.util.concurrent.atomic.LongAdder();

    private DeviationStore(Path dir) {
        this.dir = dir;
    }

    /** A store in a folder (made when first written). */
    public static DeviationStore in(Path dir) {
        return new DeviationStore(dir);
    }

    /**
     * The user's store: {@code $DEMPANO_CACHE_DIR/deviations}, else {@code $XDG_CACHE_HOME/dempano/deviations},
     * else {@code ~/.cache/dempano/deviations}; null when {@code DEMPANO_CACHE_DIR} is {@code off} or no home is
     * known.
     */
    public static DeviationStore userDefault() {
        String own = System.getenv("DEMPANO_CACHE_DIR");
        if (own != null && !own.isBlank()) {
            return own.equalsIgnoreCase("off") ? null : in(Path.of(own, "deviations"));
        }
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isBlank()) {
            return in(Path.of(xdg, "dempano", "deviations"));
        }
        String home = System.getProperty("user.home");
        return home == null || home.isBlank() ? null : in(Path.of(home, ".cache", "dempano", "deviations"));
    }

    public Path dir() {
        return dir;
    }

    /** Why the last write failed, or null when none did. */
    public String lastWriteError() {
        return lastWriteError;
    }

    /** Lookups served, since this store was made. */
    public long hits() {
        return hits.sum();
    }

    /** Lookups not served (no entry, or one measured from other heights), since this store was made. */
    public long misses() {
        return misses.sum();
    }

    /** The values measured from heights with these hashes at this patch, or null. */
    float[] get(DeviationCache.Key key, long hashA, long hashB) {
        Entry e = group(key).entries.get(new PatchKey(key.globalRow(), key.globalCol()));
        if (e != null && e.hashA == hashA && e.hashB == hashB) {
            hits.increment();
            return e.values.clone();
        }
        misses.increment();
        return null;
    }

    /** Keeps the values measured from heights with these hashes (written by {@link #flush}). */
    void put(DeviationCache.Key key, long hashA, long hashB, float[] values) {
        Group g = group(key);
        synchronized (g) {
            g.entries.put(new PatchKey(key.globalRow(), key.globalCol()), new Entry(hashA, hashB, values.clone()));
            g.dirty = true;
        }
    }

    /** Writes the groups changed since they were read. A failure is kept in {@link #lastWriteError()}, not thrown. */
    public void flush() {
        for (Map.Entry<GroupKey, Group> e : groups.entrySet()) {
            Group g = e.getValue();
            synchronized (g) {
                if (!g.dirty) {
                    continue;
                }
                try {
                    write(file(e.getKey()), g.entries);
                    g.dirty = false;
                } catch (IOException | RuntimeException ex) {
                    lastWriteError = file(e.getKey()) + ": " + ex;
                }
            }
        }
    }

    /** First hash of a patch's heights (their float bits, in order). */
    static long hashA(float[] heights) {
        long h = 0x243F6A8885A308D3L;
        for (float f : heights) {
            h = (h ^ Float.floatToIntBits(f)) * 0x9E3779B97F4A7C15L;
            h ^= h >>> 29;
        }
        return h;
    }

    /** Second, independent hash of the same heights. */
    static long hashB(float[] heights) {
        long h = 0x13198A2E03707344L;
        for (int i = heights.length - 1; i >= 0; i--) {
            h = (h + Float.floatToIntBits(heights[i])) * 0xC2B2AE3D27D4EB4FL;
            h ^= h >>> 31;
        }
        return h ^ heights.length;
    }

    private Group group(DeviationCache.Key key) {
        long span = (long) GROUP * TerrainBuilder.PATCH_INTERVALS;
        GroupKey gk = new GroupKey(key.intervalsPerDegree(), Math.floorDiv(key.globalRow(), span),
                Math.floorDiv(key.globalCol(), span));
        return groups.computeIfAbsent(gk, k -> new Group(read(file(k))));
    }

    private Path file(GroupKey k) {
        return dir.resolve(Integer.toString(k.intervalsPerDegree)).resolve(k.row + "_" + k.col + ".dev");
    }

    private static int valuesPerEntry() {
        return TerrainBuilder.LEVELS + 6;
    }

    /** A group file's entries; empty when missing, unreadable or of another format. */
    private static Map<PatchKey, Entry> read(Path file) {
        Map<PatchKey, Entry> entries = new HashMap<>();
        java.util.zip.CRC32 crc = new java.util.zip.CRC32();
        try (InputStream in = Files.newInputStream(file);
             DataInputStream data = new DataInputStream(new java.util.zip.CheckedInputStream(new BufferedInputStream(in), crc))) {
            if (data.readInt() != MAGIC || data.readInt() != FORMAT || data.readInt() != TerrainBuilder.PATCH_INTERVALS
                    || data.readInt() != valuesPerEntry()) {
                return entries;
            }
            int n = data.readInt();
            if (n < 0 || n > GROUP * GROUP) {
                return entries;
            }
            Map<PatchKey, Entry> read = new HashMap<>();
            for (int i = 0; i < n; i++) {
                PatchKey k = new PatchKey(data.readLong(), data.readLong());
                long a = data.readLong(), b = data.readLong();
                float[] values = new float[valuesPerEntry()];
                for (int v = 0; v < values.length; v++) {
                    values[v] = data.readFloat();
                }
                read.put(k, new Entry(a, b, values));
            }
            int computed = (int) crc.getValue();
            if (data.readInt() != computed || data.read() != -1) {
                return entries; // altered, or trailing bytes: not a file as this wrote it
            }
            return read;
        } catch (IOException | RuntimeException e) {
            return entries; // missing, truncated or corrupt: measured again, rewritten
        }
    }

    /** Replaces a group file whole ({@link AtomicFiles}: written aside, then renamed). */
    private static void write(Path file, Map<PatchKey, Entry> entries) throws IOException {
        Files.createDirectories(file.getParent());
        AtomicFiles.write(file, out -> {
            java.util.zip.CRC32 crc = new java.util.zip.CRC32();
            DataOutputStream data = new DataOutputStream(new java.util.zip.CheckedOutputStream(out, crc));
            data.writeInt(MAGIC);
            data.writeInt(FORMAT);
            data.writeInt(TerrainBuilder.PATCH_INTERVALS);
            data.writeInt(valuesPerEntry());
            data.writeInt(entries.size());
            for (Map.Entry<PatchKey, Entry> e : entries.entrySet()) {
                data.writeLong(e.getKey().globalRow);
                data.writeLong(e.getKey().globalCol);
                data.writeLong(e.getValue().hashA);
                data.writeLong(e.getValue().hashB);
                for (float v : e.getValue().values) {
                    data.writeFloat(v);
                }
            }
            data.writeInt((int) crc.getValue());
            data.flush();
        });
    }

    private record GroupKey(int intervalsPerDegree, long row, long col) {
    }

    private record PatchKey(long globalRow, long globalCol) {
    }

    private record Entry(long hashA, long hashB, float[] values) {
    }

    private static final class Group {
        final Map<PatchKey, Entry> entries;
        boolean dirty;

        Group(Map<PatchKey, Entry> entries) {
            this.entries = new ConcurrentHashMap<>(entries);
        }
    }
}
