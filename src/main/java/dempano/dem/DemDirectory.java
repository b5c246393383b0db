package dempano.dem;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Stream;

/**
 * Tiles from one directory: files named like {@code N46E008.hgt}, {@code n46e008.hgt},
 * {@code N19W155v2.3a.hgt.zip}. The directory is indexed once; loaded tiles are kept in a small
 * least-recently-used cache so a pipeline rendering many nearby panoramas reads each file once.
 */
public final class DemDirectory implements DemSource {
    /** Tiles kept in memory by default: a 3×3 mosaic plus a ring around it. */
    public static final int DEFAULT_CACHED_TILES = 16;

    private final Path directory;
    private final Map<TileId, Path> files;
    private final Map<TileId, HgtTile> cache;

    public DemDirectory(Path directory) {
        this(directory, DEFAULT_CACHED_TILES);
    }

    public DemDirectory(Path directory, int cachedTiles) {
        if (!Files.isDirectory(directory)) {
            throw new DemException("DEM directory " + directory + " does not exist or is not a directory");
        }
        this.directory = directory;
        Map<TileId, Path> index = new TreeMap<>();
        try (Stream<Path> list = Files.list(directory)) {
            for (Path p : (Iterable<Path>) list::iterator) {
                String name = p.getFileName().toString();
                if (!TileId.isTileFileName(name) || !Files.isRegularFile(p)) {
                    continue;
                }
                TileId id = TileId.parseFileName(name);
                Path other = index.get(id);
                // Prefer a plain .hgt over a zip of the same tile; otherwise the first name in order.
                if (other == null || (other.toString().endsWith(".zip") && !name.endsWith(".zip"))
                        || (other.toString().endsWith(".zip") == name.endsWith(".zip") && p.compareTo(other) < 0)) {
                    index.put(id, p);
                }
            }
        } catch (IOException e) {
            throw new DemException("cannot list DEM directory " + directory + ": " + e, e);
        }
        this.files = Collections.unmodifiableMap(index);
        int capacity = Math.max(1, cachedTiles);
        this.cache = new LinkedHashMap<>(capacity * 2, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<TileId, HgtTile> eldest) {
                return size() > capacity;
            }
        };
    }

    /** The tiles this directory holds and their files. */
    public Map<TileId, Path> files() {
        return files;
    }

    @Override
    public Optional<HgtTile> tile(TileId id) {
        Path file = files.get(id);
        if (file == null) {
            return Optional.empty();
        }
        synchronized (cache) {
            HgtTile cached = cache.get(id);
            if (cached != null) {
                return Optional.of(cached);
            }
        }
        HgtTile tile = HgtReader.read(file); // outside the lock: reading takes a while
        synchronized (cache) {
            cache.put(id, tile);
        }
        return Optional.of(tile);
    }

    @Override
    public String describe() {
        return directory.toString();
    }
}
