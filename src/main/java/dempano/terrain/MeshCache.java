package dempano.terrain;

import com.jme3.scene.Geometry;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Finished patch geometries, kept (with their GL buffers) from one render to the next: a patch's
 * vertices do not depend on the eye ({@link EyePlacement}), so a patch drawn again at the same
 * level with the same skirts is neither placed nor uploaded again. Least recently used first out
 * beyond a vertex budget; what leaves must have its buffers released by the caller (GL side
 * first). Belongs to one DEM source, like {@link DeviationCache}, and like it forgets the patches near a tile
 * whose heights changed ({@link #forgetChanged}, called first by every build). Not thread-safe: one build
 * and render at a time.
 */
public final class MeshCache {
    /** Default budget: about 3 million vertices (about 200 MB of vertex data, held in memory and by GL). */
    public static final long DEFAULT_VERTICES = 3_000_000;

    /**
     * What makes a patch geometry: the patch (global grid, samples per degree), its level, its skirt
     * depths (north, east, south, west; 0 = none) and the vertical exaggeration.
     */
    record Key(int intervalsPerDegree, long globalRow, long globalCol, int level, double skirtNorth, double skirtEast,
               double skirtSouth, double skirtWest, double exaggeration) {
    }

    /** A cached geometry and the ECEF points whose hull holds it. */
    record Entry(Geometry geometry, double[] hull, int vertices) {
    }

    private final long capacityVertices;
    private final LinkedHashMap<Key, Entry> map = new LinkedHashMap<>(1024, 0.75f, true);
    private long vertices;

    public MeshCache() {
        this(DEFAULT_VERTICES);
    }

    public MeshCache(long capacityVertices) {
        if (capacityVertices < 0) {
            throw new IllegalArgumentException("capacity must be ≥ 0 vertices, got " + capacityVertices);
        }
        this.capacityVertices = capacityVertices;
    }

    Entry get(Key key) {
        return map.get(key);
    }

    void put(Key key, Entry entry) {
        Entry old = map.put(key, entry);
        vertices += entry.vertices() - (old == null ? 0 : old.vertices());
    }

    /**
     * Drops the least recently used entries beyond the budget, never one in {@code inUse} (those
     * the current render draws); returns the geometries dropped, whose buffers the caller releases.
     */
    List<Geometry> trim(Set<Key> inUse) {
        List<Geometry> dropped = new ArrayList<>();
        Iterator<Map.Entry<Key, Entry>> it = map.entrySet().iterator();
        while (vertices > capacityVertices && it.hasNext()) {
            Map.Entry<Key, Entry> e = it.next();
            if (inUse.contains(e.getKey())) {
                continue;
            }
            vertices -= e.getValue().vertices();
            dropped.add(e.getValue().geometry());
            it.remove();
        }
        return dropped;
    }

    private final TileVersions versions = new TileVersions();

    /**
     * Removes the geometries built from heights that {@code mosaic}'s tiles no longer have: where a tile differs
     * from the one this cache last saw under its id ({@link TileVersions}), every patch within two samples of it.
     * Returns the geometries removed, whose buffers the caller releases.
     */
    public List<Geometry> forgetChanged(dempano.dem.Mosaic mosaic) {
        List<dempano.dem.TileId> changed = versions.changed(mosaic);
        List<Geometry> dropped = new ArrayList<>();
        if (changed.isEmpty()) {
            return dropped;
        }
        int n = mosaic.intervalsPerDegree();
        Iterator<Map.Entry<Key, Entry>> it = map.entrySet().iterator();
        while (it.hasNext()) {
            Map.Entry<Key, Entry> e = it.next();
            Key k = e.getKey();
            if (TileVersions.touchesAny(changed, n, k.intervalsPerDegree(), k.globalRow(), k.globalCol())) {
                vertices -= e.getValue().vertices();
                dropped.add(e.getValue().geometry());
                it.remove();
            }
        }
        return dropped;
    }

    /** Removes every entry; returns their geometries, whose buffers the caller releases. */
    public List<Geometry> clear() {
        List<Geometry> all = new ArrayList<>();
        map.values().forEach(e -> all.add(e.geometry()));
        map.clear();
        vertices = 0;
        return all;
    }

    public int size() {
        return map.size();
    }

    public long vertices() {
        return vertices;
    }
}
