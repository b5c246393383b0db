package dempano.spark;

import dempano.PanoramaRenderer;
import dempano.dem.DemSource;
import dempano.dem.PriorityDem;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;

/**
 * One {@link PanoramaRenderer} per executor JVM (per DEM and renderer kind), opened by the first
 * task that needs it and shared by all the executor's tasks, so that its caches (tiles, patch
 * deviations, meshes) serve every row the executor renders. Closed when the JVM shuts down.
 *
 * <p>Sharing is safe: {@link PanoramaRenderer} is thread-safe (tile loading and mesh building run on
 * the calling task's thread, GL work is serialized onto the renderer's one GL thread; the mesh cache
 * is used by one render at a time, a concurrent render builds its meshes afresh, with equal output).
 * With {@code spark.executor.cores} = 2, two rows are in flight: one on the GL thread while the
 * other loads tiles, builds meshes or stitches.
 *
 * <p>A renderer whose GL thread failed is dropped; the next row opens a new one.
 */
final class ExecutorRenderer {
    private static final Map<String, PanoramaRenderer> OPEN = new HashMap<>();
    private static boolean hooked;

    private ExecutorRenderer() {
    }

    /** The JVM's renderer for these settings, opened on first use. */
    static synchronized PanoramaRenderer get(JobSettings s) {
        String key = s.rendererKey();
        PanoramaRenderer r = OPEN.get(key);
        if (r == null) {
            if (System.getProperty("java.awt.headless") == null) {
                System.setProperty("java.awt.headless", "true"); // as the CLI: a stale DISPLAY must not fail the rows
            }
            javax.imageio.ImageIO.setUseCache(false); // as dempano batch: PNGs through memory
            DemSource dem = dem(s);
            r = s.reference() ? PanoramaRenderer.openReference(dem) : PanoramaRenderer.open(dem);
            OPEN.put(key, r);
            if (!hooked) {
                Runtime.getRuntime().addShutdownHook(new Thread(ExecutorRenderer::closeAll, "dempano-spark-renderer-close"));
                hooked = true;
            }
        }
        return r;
    }

    /** Forgets (and closes) a renderer that failed, so that the next row opens a fresh one. */
    static synchronized void discard(JobSettings s, PanoramaRenderer failed) {
        if (OPEN.get(s.rendererKey()) == failed) {
            OPEN.remove(s.rendererKey());
        }
        try {
            failed.close();
        } catch (RuntimeException e) {
            // already broken
        }
    }

    /** Closes every renderer of this JVM (the shutdown hook; tests). */
    static synchronized void closeAll() {
        for (PanoramaRenderer r : OPEN.values()) {
            try {
                r.close();
            } catch (RuntimeException e) {
                // shutting down
            }
        }
        OPEN.clear();
    }

    /** How many renderers this JVM holds (tests). */
    static synchronized int openCount() {
        return OPEN.size();
    }

    private static String sha256(String s) {
        try {
            return java.util.HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256")
                    .digest(s.getBytes(StandardCharsets.UTF_8)));
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    private static DemSource dem(JobSettings s) {
        List<java.nio.file.Path> dirs = new ArrayList<>();
        for (String d : s.demDirs) {
            dirs.add(localDem(d, s));
        }
        return PriorityDem.open(dirs, s.panorama.demFill(), w -> System.err.println("  warning: " + w)); // in the executor's log
    }

    /**
     * A DEM folder on this node: a local path as it is (any characters: it is not read as a URI); a {@code file:} URI
     * as its path; another Hadoop URI (hdfs://, s3a://, …) copied into {@code java.io.tmpdir/dempano-dem-<hash>} (all
     * its files: meant for regional tile sets; for a continent, put the tiles on every node's disk or a shared mount
     * instead). The copy is keyed by the URI and the folder's listing (every file's name, length and modification
     * time), so a tile changed at the source is copied afresh by the next renderer opened, never served from an old
     * copy; a copy that fails leaves nothing behind.
     */
    static Path localDem(String dir, JobSettings s) {
        if (!Hadoop.isUri(dir)) {
            return Path.of(dir); // a plain path: '%' or '[' in it are characters, not URI syntax
        }
        if (dir.regionMatches(true, 0, "file:", 0, 5)) {
            try {
                return Path.of(URI.create(dir).getPath()); // %20 and the like decoded
            } catch (IllegalArgumentException e) {
                return Path.of(new org.apache.hadoop.fs.Path(dir).toUri().getPath()); // not a valid URI: as Hadoop reads it
            }
        }
        org.apache.hadoop.fs.Path src = new org.apache.hadoop.fs.Path(dir);
        Path staging = null;
        try {
            FileSystem fs = src.getFileSystem(Hadoop.configuration(s.hadoop));
            List<FileStatus> files = new ArrayList<>();
            StringBuilder listing = new StringBuilder(dir);
            FileStatus[] statuses = fs.listStatus(src);
            java.util.Arrays.sort(statuses, java.util.Comparator.comparing(f -> f.getPath().getName()));
            for (FileStatus f : statuses) {
                if (f.isFile()) {
                    files.add(f);
                    listing.append('\u0000').append(f.getPath().getName()).append('\u0000').append(f.getLen())
                            .append('\u0000').append(f.getModificationTime());
                }
            }
            Path local = Path.of(System.getProperty("java.io.tmpdir"), "dempano-dem-" + sha256(listing.toString()).substring(0, 16));
            if (Files.isDirectory(local)) {
                return local; // staged earlier from the same files (by this or another executor on the node)
            }
            staging = Files.createTempDirectory(local.getParent(), local.getFileName() + ".part-");
            for (FileStatus f : files) {
                fs.copyToLocalFile(false, f.getPath(), new org.apache.hadoop.fs.Path(staging.resolve(f.getPath().getName()).toUri()), true);
            }
            try {
                Files.move(staging, local, StandardCopyOption.ATOMIC_MOVE);
                staging = null;
            } catch (IOException e) {
                if (!Files.isDirectory(local)) {
                    throw e;
                } // another executor won the race
            }
            return local;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot copy the DEM folder " + dir + " to this node: " + e.getMessage(), e);
        } finally {
            if (staging != null) {
                deleteQuietly(staging);
            }
        }
    }

    private static void deleteQuietly(Path dir) {
        try (java.util.stream.Stream<Path> walk = Files.walk(dir)) {
            walk.sorted(java.util.Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    // left behind
                }
            });
        } catch (IOException e) {
            // left behind
        }
    }
}
