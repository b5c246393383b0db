package dempano.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.geo.Refraction;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.lang.management.BufferPoolMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;

/** Many renders in one JVM: no growth of native memory; concurrent callers get the same answers. */
class RendererLifecycleTest {
    static PanoramaRequest small() {
        return PanoramaRequest.at(RenderGeometryTest.EYE_LAT, RenderGeometryTest.EYE_LON).withRangeMetres(25_000)
                .withPixelsPerDegree(4).withRefraction(Refraction.NONE).withElevationRange(new ElevationRange(-10, 10, false));
    }

    static long directBytes() {
        for (BufferPoolMXBean b : ManagementFactory.getPlatformMXBeans(BufferPoolMXBean.class)) {
            if (b.getName().equals("direct")) {
                return b.getMemoryUsed();
            }
        }
        throw new IllegalStateException("no direct buffer pool");
    }

    static long rssBytes() throws Exception {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("VmRSS:")) {
                return Long.parseLong(line.replaceAll("[^0-9]", "")) * 1024;
            }
        }
        return -1;
    }

    @Test
    void hundredRendersDoNotLeak() throws Exception {
        try (PanoramaRenderer r = PanoramaRenderer.open(RenderGeometryTest.dem(RenderGeometryTest.TERRAIN, 46, 8, 1, 1))) {
            for (int i = 0; i < 10; i++) {
                r.render(small());
            }
            System.gc();
            long direct0 = directBytes(), rss0 = rssBytes();
            for (int i = 0; i < 90; i++) {
                r.render(small());
            }
            System.gc();
            long direct1 = directBytes(), rss1 = rssBytes();
            // One scene's buffers are ~60 MB here: 90 leaked scenes would be gigabytes.
            assertTrue(direct1 - direct0 < 16L << 20, "direct memory grew by " + (direct1 - direct0) / 1e6 + " MB");
            assertTrue(rss1 - rss0 < 300L << 20, "RSS grew by " + (rss1 - rss0) / 1e6 + " MB");
        }
    }

    @Test
    void concurrentCallersGetIdenticalPanoramas() throws Exception {
        try (PanoramaRenderer r = PanoramaRenderer.open(RenderGeometryTest.dem(RenderGeometryTest.TERRAIN, 46, 8, 1, 1))) {
            float[] reference = r.render(small()).distanceArray();
            ExecutorService pool = Executors.newFixedThreadPool(3);
            List<Future<Panorama>> futures = new ArrayList<>();
            for (int i = 0; i < 6; i++) {
                futures.add(pool.submit(() -> r.render(small())));
            }
            for (Future<Panorama> f : futures) {
                assertArrayEquals(reference, f.get().distanceArray());
            }
            pool.shutdown();
        }
    }

    @Test
    void contextIsCreatedAgainAfterTheLastUserCloses() throws Exception {
        float[] first = null;
        for (int round = 0; round < 6; round++) {
            try (PanoramaRenderer r = PanoramaRenderer.open(RenderGeometryTest.dem(RenderGeometryTest.TERRAIN, 46, 8, 1, 1))) {
                float[] d = r.render(small()).distanceArray();
                if (first == null) {
                    first = d;
                } else {
                    assertArrayEquals(first, d, "round " + round);
                }
            }
        }
    }
}
