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

    /** A tile as last seen: the object (weakly; null at sea level) and its fingerprint. */
    private record Seen(WeakReference<HgtTile> tile, long hash) {
        boolean is(HgtTile t) {
            return t == null ? tile == null : tile != null && tile.get() == t;
        }
    }

    private final Map<Key, Seen> seen = new HashMap<>();

    /**
     * The slots of {@code mosaic} whose heights differ from those last seen under the same tile id (at the
     * mosaic's resolution), and remembers the mosaic's tiles as those seen now. A tile seen for the first time is
     * no change; another object with the same fingerprint is none either.
     */
    List<TileId> changed(Mosaic mosaic) {
        List<TileId> out = new ArrayList<>();
        for (Mosaic.TileSlot slot : mosaic.tileSlots()) {
            Key key = new Key(slot.id(), mosaic.intervalsPerDegree());
            HgtTile tile = slot.tile();
            Seen before = seen.get(key);
            if (before != null && before.is(tile)) {
                continue;
            }
            long hash = tile == null ? SEA_LEVEL : tile.contentHash();
            if (before != null && before.hash() != hash) {
                out.add(slot.id());
            }
            seen.put(key, new Seen(tile == null ? null : new WeakReference<>(tile), hash));
        }
        return out;
    }

    /**
     * Whether a cache entry's patch (its grid's resolution, its north-west sample) lies on the grid of
     * {@code intervalsPerDegree} and {@linkplain #touches touches} one of {@code tiles}.
     */
    static boolean touchesAny(List<TileId> tiles, int intervalsPerDegree, int keyIntervalsPerDegree, long globalRow,
                              long globalCol) {
        return keyIntervalsPerDegree == intervalsPerDegree
                && tiles.stream().anyMatch(t -> touches(t, intervalsPerDegree, globalRow, globalCol));
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
