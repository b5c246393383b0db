package dempano.dem;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Stream;

/**
 * Tiles from one directory: files named like {@code N46E008.hgt}, {@code n46e008.hgt},
 * {@code N19W155v2.3a.hgt.zip}, and GeoTIFFs named like {@code N46E008.tif} or
 * {@code Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif} (read by {@link GeoTiffReader}, resampled
 * onto the tile's grid). The directory is indexed once; loaded tiles are kept in a small
 * least-recently-used cache so a pipeline rendering many nearby panoramas reads each file once. A
 * cached tile whose file changed since (modification time, size or inode) is read again.
 *
 * <p>Indexing never fails on the folder's content. Files named {@code *.hgt} / {@code *.hgt.zip}
 * that are no valid tile name ({@code N99E999.hgt}, {@code foo.hgt}) are ignored with one
 * {@link #warnings() warning}; other files (README, SHA256SUMS) silently. Problems of a tile are
 * reported when the tile is needed ({@link #tile}), so tiles out of range cannot make a render
 * fail: an entry named like the tile that is not a readable file (a directory, a dangling symbolic
 * link, a link loop, no read permission), and several files for one tile ({@code N43E007.hgt} and
 * {@code N43E007-v2.hgt}, {@code n43e007.hgt}, {@code N43E007.hgt.zip}), which is ambiguous: no file
 * is preferred over another.
 */
public final class DemDirectory implements DemSource {
    /** Tiles kept in memory by default: a 3×3 mosaic plus a ring around it. */
    public static final int DEFAULT_CACHED_TILES = 16;

    /** A file (or other entry) named like a tile; problem is null for a readable regular file. */
    private record Candidate(Path path, String problem) {
    }

    private final Path directory;
    private final Map<TileId, List<Candidate>> candidates;
    private final Map<TileId, Path> files;
    private final List<String> warnings;
    private final Map<TileId, Cached> cache;
    private final VoidFill voidFill;
    /** Per tile: files (paths) whose names begin with its name but are not read as tiles. */
    private final Map<TileId, List<String>> unreadNamedFor;

    /** A loaded tile and the file's state when it was read: a changed file is read again. */
    private record Cached(HgtTile tile, Object stamp) {
    }

    public DemDirectory(Path directory) {
        this(directory, DEFAULT_CACHED_TILES);
    }

    public DemDirectory(Path directory, int cachedTiles) {
        this(directory, cachedTiles, VoidFill.DEFAULT);
    }

    /**
     * @param cachedTiles tiles kept in memory
     * @param voidFill    how the voids of its tiles are filled (they are still marked as filled voids)
     */
    /** Why a DEM directory that is none is refused: missing, or a file (a tile given instead of its folder). */
    public static String notAFolder(Path directory) {
        if (Files.exists(directory)) {
            Path parent = directory.toAbsolutePath().getParent();
            return "DEM directory " + directory + " is a file, not a folder: give the folder that holds the tiles"
                    + (parent == null ? "" : " (" + parent + ")");
        }
        return "DEM directory " + directory + " does not exist";
    }

    public DemDirectory(Path directory, int cachedTiles, VoidFill voidFill) {
        this.voidFill = java.util.Objects.requireNonNull(voidFill);
        if (directory.toString().isEmpty()) { // Path.of("") is the working directory: a --dem-dir "" is a mistake
            throw new DemException("DEM directory is empty (\"\"): give a folder");
        }
        if (!Files.isDirectory(directory)) {
            throw new DemException(notAFolder(directory));
        }
        this.directory = directory;
        Map<TileId, List<Candidate>> index = new TreeMap<>();
        Map<TileId, List<String>> unread = new TreeMap<>();
        List<String> junk = new ArrayList<>();
        List<Path> entries = new ArrayList<>();
        try (Stream<Path> list = Files.list(directory)) {
            for (Path p : (Iterable<Path>) list.sorted()::iterator) {
                if (LATITUDE_FOLDER.matcher(p.getFileName().toString()).matches() && Files.isDirectory(p)) {
                    // AWS Terrain Tiles' "skadi" layout: N46/N46E008.hgt.gz, a folder per latitude.
                    try (Stream<Path> inner = Files.list(p)) {
                        inner.sorted().forEach(entries::add);
                    }
                } else {
                    entries.add(p);
                }
            }
        } catch (IOException | java.io.UncheckedIOException e) {
            throw new DemException("cannot list DEM directory " + directory + ": " + e, e);
        }
        for (Path p : entries) {
            String name = p.getFileName().toString();
            boolean tileName = TileId.isTileFileName(name);
            TileId namedFor = tileName ? null : TileId.namedAtStart(name);
            if (namedFor != null) { // N46E008.hgt.bak: a hint should N46E008 be missing
                unread.computeIfAbsent(namedFor, k -> new ArrayList<>()).add(p.toString());
            }
            if (!TileId.looksLikeTileFile(name)) {
                continue; // README, SHA256SUMS, ...
            }
            if (!tileName) {
                junk.add(name);
                continue;
            }
            index.computeIfAbsent(TileId.parseFileName(name), k -> new ArrayList<>()).add(new Candidate(p, problem(p)));
        }
        unread.replaceAll((id, paths) -> List.copyOf(paths));
        this.unreadNamedFor = Collections.unmodifiableMap(unread);
        Map<TileId, Path> usable = new TreeMap<>();
        index.forEach((id, c) -> {
            if (c.size() == 1 && c.get(0).problem() == null) {
                usable.put(id, c.get(0).path());
            }
        });
        this.candidates = Collections.unmodifiableMap(index);
        this.files = Collections.unmodifiableMap(usable);
        this.warnings = junk.isEmpty() ? List.of() : List.of("ignored " + junk.size() + " file" + (junk.size() == 1 ? "" : "s")
                + " in " + directory + " named like tiles but with no valid tile name " + junk
                + " (" + TileId.expectedNames() + ")");
        int capacity = Math.max(1, cachedTiles);
        this.cache = new LinkedHashMap<>(capacity * 2, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<TileId, Cached> eldest) {
                return size() > capacity;
            }
        };
    }

    /** What is wrong with an entry named like a tile, or null for a readable regular file. */
    private static String problem(Path p) {
        if (Files.isRegularFile(p)) { // follows links
            return Files.isReadable(p) ? null : "is not readable (permission denied)";
        }
        if (Files.isDirectory(p)) {
            return Files.isSymbolicLink(p) ? "is a symbolic link to a directory, not a tile file" : "is a directory, not a tile file";
        }
        if (Files.isSymbolicLink(p)) {
            String target;
            try {
                target = String.valueOf(Files.readSymbolicLink(p));
            } catch (IOException e) {
                target = "?";
            }
            try {
                p.toRealPath();
            } catch (java.nio.file.NoSuchFileException e) {
                return "is a dangling symbolic link (to " + target + ", which does not exist)";
            } catch (java.nio.file.FileSystemException e) {
                String reason = String.valueOf(e.getReason());
                return reason.toLowerCase(java.util.Locale.ROOT).contains("levels")
                        ? "is a symbolic link loop (to " + target + ": " + reason + ")"
                        : "is a symbolic link that cannot be followed (to " + target + ": " + reason + ")";
            } catch (IOException e) {
                return "is a symbolic link that cannot be followed (to " + target + ": " + e + ")";
            }
            return "is a symbolic link to something that is not a regular file (" + target + ")";
        }
        return Files.exists(p) ? "is not a regular file (a device, pipe or socket?)" : "cannot be accessed";
    }

    /** The tiles that have exactly one readable file, and their files. */
    public Map<TileId, Path> files() {
        return files;
    }

    /**
     * Problems found while indexing that do not stop rendering: files named like tiles whose names
     * are not valid tile names (ignored). At most one message.
     */
    public List<String> warnings() {
        return warnings;
    }

    @Override
    public Optional<HgtTile> tile(TileId id) {
        List<Candidate> found = candidates.get(id);
        if (found == null) {
            return Optional.empty();
        }
        if (found.size() > 1) {
            StringBuilder names = new StringBuilder();
            for (Candidate c : found) {
                names.append(names.length() == 0 ? "" : ", ").append(c.path().getFileName())
                        .append(c.problem() == null ? "" : " (" + c.problem().replaceFirst("^is ", "") + ")");
            }
            throw new DemException("tile " + id + " is ambiguous: " + directory + " holds " + found.size()
                    + " files for it (" + names + "); keep one");
        }
        Path file = found.get(0).path();
        if (found.get(0).problem() != null) {
            throw new DemException("tile " + id + ": " + file + " " + found.get(0).problem());
        }
        Object stamp = stamp(file);
        if (TileId.isGeoTiffFileName(file.getFileName().toString())) {
            // Its edges come from the neighbours' files (see GeoTiffReader.read): their changes count too.
            stamp = List.of(stamp, neighbourStamp(TileId.of(id.latSouthDeg(), id.lonWestDeg() + 1)),
                    id.latSouthDeg() > -90 ? neighbourStamp(TileId.of(id.latSouthDeg() - 1, id.lonWestDeg())) : "",
                    id.latSouthDeg() > -90 ? neighbourStamp(TileId.of(id.latSouthDeg() - 1, id.lonWestDeg() + 1)) : "");
        }
        synchronized (cache) {
            Cached cached = cache.get(id);
            if (cached != null && cached.stamp().equals(stamp)) {
                return Optional.of(cached.tile());
            }
        }
        // Outside the lock: reading takes a while.
        HgtTile tile = TileId.isGeoTiffFileName(file.getFileName().toString())
                ? GeoTiffReader.read(file, this::geoTiffOf, voidFill) : HgtReader.read(file, voidFill);
        synchronized (cache) {
            cache.put(id, new Cached(tile, stamp));
        }
        return Optional.of(tile);
    }

    private Object neighbourStamp(TileId id) {
        Path p = geoTiffOf(id);
        if (p == null) {
            return "";
        }
        try {
            return stamp(p);
        } catch (DemException e) {
            return "unreadable";
        }
    }

    /** The one usable GeoTIFF of a tile, or null: a GeoTIFF tile's neighbours complete its eastern and southern edges. */
    private Path geoTiffOf(TileId id) {
        Path p = files.get(id);
        return p != null && TileId.isGeoTiffFileName(p.getFileName().toString()) ? p : null;
    }

    /**
     * What identifies a file's content cheaply: its modification time, size and file key (inode), so
     * a tile replaced or rewritten since it was cached is read again.
     */
    private static Object stamp(Path file) {
        try {
            java.nio.file.attribute.BasicFileAttributes a =
                    Files.readAttributes(file, java.nio.file.attribute.BasicFileAttributes.class);
            return java.util.List.of(a.lastModifiedTime(), a.size(), String.valueOf(a.fileKey()));
        } catch (java.nio.file.NoSuchFileException e) {
            throw new DemException("tile " + TileId.parseFileName(file.getFileName().toString()) + ": " + file
                    + " is gone (removed since the folder was indexed)", e);
        } catch (IOException e) {
            throw new DemException("tile " + TileId.parseFileName(file.getFileName().toString()) + ": " + file
                    + " cannot be read (" + e.getMessage() + ")", e);
        }
    }

    @Override
    public String describe() {
        return directory.toString();
    }

    @Override
    public List<String> unreadFilesNamedFor(TileId id) {
        return unreadNamedFor.getOrDefault(id, List.of());
    }

    /** A folder per latitude, as AWS Terrain Tiles' "skadi" layout has them ({@code N46}, {@code S16}). */
    private static final java.util.regex.Pattern LATITUDE_FOLDER = java.util.regex.Pattern.compile("^[NS]\\d{2}$",
            java.util.regex.Pattern.CASE_INSENSITIVE);
}
