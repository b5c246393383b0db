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
     * A DEM folder on this node: a local path as it is; a Hadoop URI (hdfs://, s3a://, …) copied
     * once per node into {@code java.io.tmpdir/dempano-dem-<hash>} (all its files: meant for regional
     * tile sets; for a continent, put the tiles on every node's disk or a shared mount instead).
     */
    static Path localDem(String dir, JobSettings s) {
        URI uri = URI.create(dir.replace(" ", "%20"));
        if (uri.getScheme() == null || uri.getScheme().equals("file")) {
            return uri.getScheme() == null ? Path.of(dir) : Path.of(uri);
        }
        Path local = Path.of(System.getProperty("java.io.tmpdir"),
                "dempano-dem-" + sha256(dir).substring(0, 16));
        if (Files.isDirectory(local)) {
            return local; // staged earlier (by this or another executor on the node)
        }
        try {
            Path staging = Files.createTempDirectory(local.getParent(), local.getFileName() + ".part-");
            org.apache.hadoop.fs.Path src = new org.apache.hadoop.fs.Path(dir);
            FileSystem fs = src.getFileSystem(Hadoop.configuration(s.hadoop));
            for (FileStatus f : fs.listStatus(src)) {
                if (f.isFile()) {
                    fs.copyToLocalFile(false, f.getPath(), new org.apache.hadoop.fs.Path(staging.resolve(f.getPath().getName()).toUri()), true);
                }
            }
            try {
                Files.move(staging, local, StandardCopyOption.ATOMIC_MOVE);
            } catch (IOException e) {
                if (!Files.isDirectory(local)) {
                    throw e;
                } // another executor won the race
            }
            return local;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot copy the DEM folder " + dir + " to " + local + ": " + e.getMessage(), e);
        }
    }
}
