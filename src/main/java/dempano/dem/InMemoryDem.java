package dempano.dem;

import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/** Tiles held in memory (synthetic terrain, tests, tiles from elsewhere). Immutable. */
public final class InMemoryDem implements DemSource {
    private final Map<TileId, HgtTile> tiles = new TreeMap<>();
    private final String description;

    public InMemoryDem(String description, Collection<HgtTile> tiles) {
        this.description = description;
        for (HgtTile t : tiles) {
            if (this.tiles.put(t.id(), t) != null) {
                throw new IllegalArgumentException("two tiles for " + t.id());
            }
        }
    }

    @Override
    public Optional<HgtTile> tile(TileId id) {
        return Optional.ofNullable(tiles.get(id));
    }

    @Override
    public String describe() {
        return description;
    }
}
