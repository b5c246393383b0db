package dempano.terrain;

import dempano.dem.HgtTile;
import dempano.dem.Mosaic;
import dempano.dem.TileId;
import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Which heights a cache's entries were derived from, tile by tile, so that a tile whose heights changed since
 * (a {@link dempano.dem.DemDirectory} reads a rewritten file again; a missing tile appears) makes exactly the
 * entries near it stale. {@link DeviationCache} and {@link MeshCache} key their entries by the patch's place
 * alone; each holds one of these and forgets the entries a changed tile touches before it serves any.
 *
 * <p>A tile is the same when it is the same object (tiles are immutable), or a new object with the same
 * {@link HgtTile#contentHash()} (a tile evicted from a source's cache and read back): only then are the
 * entries kept. A slot held at sea level counts as a tile of its own. Not thread-safe.
 */
final class TileVersions {
    /** The fingerprint of a slot held at sea level (no tile's {@link HgtTile#contentHash()} in practice). */
    private static final long SEA_LEVEL = 0x5EA1_E7E1_5EA1_E7E1L;

    private record Key(TileId id, int intervalsPerDegree) {
    }

    /** No fingerprint taken (yet). */
    private static final long UNKNOWN = 0;

    /** A tile as last seen: the object (weakly; null at sea level) and its fingerprint, or {@link #UNKNOWN}. */
    private record Seen(WeakReference<HgtTile> tile, long hash) {
        boolean is(HgtTile t) {
            return t == null ? tile == null : tile != null && tile.get() == t;
        }

        /** The fingerprint of what was seen, where known or still computable; else {@link #UNKNOWN}. */
        long hashNow() {
            if (hash != UNKNOWN || tile == null) {
                return tile == null ? SEA_LEVEL : hash;
            }
            HgtTile t = tile.get();
            return t == null ? UNKNOWN : t.contentHash();
        }
    }

    private final Map<Key, Seen> seen = new HashMap<>();

    private static long hashOf(HgtTile t) {
        return t == null ? SEA_LEVEL : t.contentHash();
    }

    /**
     * The slots of {@code mosaic} whose heights differ from those last seen under the same tile id (at the
     * mosaic's resolution), and remembers the mosaic's tiles as those seen now. A tile seen for the first time is
     * no change. A tile's fingerprint is taken the second time it is seen (so that a single render, the CLI's,
     * takes none), or when another object comes under its id; where by then the first object was collected
     * without one, the slot counts as changed (its entries are measured again: never served stale).
     */
    List<TileId> changed(Mosaic mosaic) {
        List<TileId> out = new ArrayList<>();
        for (Mosaic.TileSlot slot : mosaic.tileSlots()) {
            Key key = new Key(slot.id(), mosaic.intervalsPerDegree());
            HgtTile tile = slot.tile();
            Seen before = seen.get(key);
            WeakReference<HgtTile> ref = tile == null ? null : new WeakReference<>(tile);
            if (before == null) {
                seen.put(key, new Seen(ref, UNKNOWN));
            } else if (before.is(tile)) {
                if (before.hash() == UNKNOWN && tile != null) {
                    seen.put(key, new Seen(before.tile(), tile.contentHash()));
                }
            } else {
                long old = before.hashNow(), now = hashOf(tile);
                if (old == UNKNOWN || old != now) {
                    out.add(slot.id());
                }
                seen.put(key, new Seen(ref, now));
            }
        }
        return out;
    }

    /** Samples beyond a tile's edge whose patches are forgotten with it (a vertex's normal reads its neighbours). */
    static final int MARGIN_SAMPLES = 2;

    /**
     * Whether a patch (its north-west sample counted from 90°N and 180°W at {@code intervalsPerDegree}, spanning
     * {@link TerrainBuilder#PATCH_INTERVALS} intervals each way) comes within {@link #MARGIN_SAMPLES} of a tile
     * (its edges included; the antimeridian wrapped).
     */
    static boolean touches(TileId tile, int intervalsPerDegree, long globalRow, long globalCol) {
        long n = intervalsPerDegree, span = TerrainBuilder.PATCH_INTERVALS, m = MARGIN_SAMPLES;
        long rowMin = (89L - tile.latSouthDeg()) * n, rowMax = rowMin + n;
        if (globalRow > rowMax + m || globalRow + span < rowMin - m) {
            return false;
        }
        long colMin = (tile.lonWestDeg() + 180L) * n, around = 360L * n;
        for (long shift = -around; shift <= around; shift += around) {
            long c0 = colMin + shift, c1 = c0 + n;
            if (globalCol <= c1 + m && globalCol + span >= c0 - m) {
                return true;
            }
        }
        return false;
    }
}
