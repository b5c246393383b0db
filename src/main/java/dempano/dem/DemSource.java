package dempano.dem;

import java.util.Optional;

/**
 * Where tiles come from: a directory of .hgt and GeoTIFF files ({@link DemDirectory}), several sources in
 * priority ({@link PriorityDem}), or tiles held in memory. Implementations are thread-safe.
 */
public interface DemSource {
    /**
     * The tile, loaded and void-filled, or empty if this source has no data for it.
     *
     * @throws DemException if the tile exists but cannot be read
     */
    Optional<HgtTile> tile(TileId id);

    /** A short description for messages and metadata (e.g. the directory). */
    String describe();

    /**
     * Files this source holds whose names begin with the tile's name but are not read as tiles ({@code N46E008.hgt.bak},
     * {@code N46E008.dem}), as paths for a hint where the tile is missing; none by default.
     */
    default java.util.List<String> unreadFilesNamedFor(TileId id) {
        return java.util.List.of();
    }
}
