package dempano.terrain;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Function;

/**
 * Per-patch deviations ({@link LevelOfDetail#deviationsMetres}) kept across renders, so that a
 * pipeline rendering many viewpoints of one area measures each patch of the DEM once. Patches lie
 * on a grid aligned to whole multiples of {@link TerrainBuilder#PATCH_INTERVALS} samples from 90°N
 * and 180°W, so the same patch has the same key whatever the viewpoint. Valid for one DEM source
 * only (the key holds no tile contents), whose neighbouring tiles agree on their shared edges (as
 * SRTM tiles do): which of two tiles supplies an edge sample depends on which are loaded. A tile whose
 * heights change while the cache is in use (its file rewritten and read again) is noticed by
 * {@link #forgetChanged}, which every build calls first: the entries of the patches within two samples of it
 * are dropped and measured again. Bounded (least recently used entries go first) and thread-safe.
 */
public final class DeviationCache {
    /** Default capacity, patches: a 5×5 block of SRTM1 tiles is about 80 000 (a few MB each 10 000). */
    public static final int DEFAULT_PATCHES = 400_000;

    private final Map<Key, float[]> map;

    /** Key of a patch: grid intervals per degree and its north-west sample counted from 90°N, 180°W. */
    record Key(int intervalsPerDegree, long globalRow, long globalCol) {
    }

    public DeviationCache() {
        this(DEFAULT_PATCHES);
    }

    public DeviationCache(int capacityPatches) {
        int capacity = Math.max(1, capacityPatches);
        this.map = new LinkedHashMap<>(1024, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Key, float[]> eldest) {
                return size() > capacity;
            }
        };
    }

    /**
     * Hands each item the cached values of its key, where held: deviations per level (metres, no
     * chord sag), then the patch's lowest and highest sample (metres), then its least and greatest
     * height steps east and south (metres): all from the heights alone, nothing from the eye.
     */
    <T> void lookUp(List<T> items, Function<T, Key> key, BiConsumer<T, float[]> found) {
        synchronized (map) {
            for (T item : items) {
                float[] d = map.get(key.apply(item));
                if (d != null) {
                    found.accept(item, d);
                }
            }
        }
    }

    private final TileVersions versions = new TileVersions();

    /**
     * Drops the entries derived from heights that {@code mosaic}'s tiles no longer have: where a tile differs from
     * the one this cache last saw under its id ({@link TileVersions}), every patch within two samples of it.
     * Returns how many entries were dropped.
     */
    public int forgetChanged(dempano.dem.Mosaic mosaic) {
        synchronized (map) {
            List<dempano.dem.TileId> changed = versions.changed(mosaic);
            int before = map.size();
            if (!changed.isEmpty()) {
                int n = mosaic.intervalsPerDegree();
                map.keySet().removeIf(k -> TileVersions.touchesAny(changed, n, k.intervalsPerDegree(), k.globalRow(),
                        k.globalCol()));
            }
            return before - map.size();
        }
    }

    /** Keeps the items' raw deviations under their keys. */
    <T> void store(List<T> items, Function<T, Key> key, Function<T, float[]> deviationsMetres) {
        synchronized (map) {
            for (T item : items) {
                map.put(key.apply(item), deviationsMetres.apply(item));
            }
        }
    }

    private volatile DeviationStore disk;

    /**
     * Also keeps the deviations in (and takes them from) a store on disk, from one process to the next
     * ({@link DeviationStore}: content-addressed, so this cache's one-source rule does not bind it); null for none.
     */
    public void useDisk(DeviationStore store) {
        this.disk = store;
    }

    /** The store on disk, or null. */
    public DeviationStore disk() {
        return disk;
    }

    /** Patches held. */
    public int size() {
        synchronized (map) {
            return map.size();
        }
    }
}
