package dempano;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraPose;
import dempano.dem.InMemoryDem;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The views stitched in passes while the others are drawn ({@link PanoramaRenderer#STITCH_PASSES}) give the bits
 * one stitch of all views gives: every pixel reads one view's samples and the triangles seen there only. Pass
 * counts that split the 8 views evenly, unevenly and one by one, for a panorama and a camera.
 */
class StitchPassesRenderTest {
    /** Ridges and valleys in both directions, 200–2 200 m. */
    static double relief(double lat, double lon) {
        return 1200 + 700 * Math.sin(lat * 47) * Math.cos(lon * 61) + 300 * Math.sin(lat * 173 + lon * 131);
    }

    @Test
    void anyPassCountGivesThePanoramaOneStitchGives() {
        InMemoryDem dem = Synthetic.dem(StitchPassesRenderTest::relief, 46, 8, 1, 1);
        PanoramaRequest request = PanoramaRequest.at(46.5, 8.5).withRangeMetres(40_000).withPixelsPerDegree(8)
                .withElevationRange(new ElevationRange(-20, 10, false));
        Panorama one;
        List<String> oneProgress = new ArrayList<>();
        try (PanoramaRenderer r = PanoramaRenderer.open(dem).withStitchPasses(1)) {
            one = r.render(request, oneProgress::add);
        }
        String distances = distancesLine(oneProgress);
        assertTrue(one.distanceArray().length > 0 && distances.contains("0 by inverse depth"), distances);
        for (int passes : new int[] {3, 8}) {
            List<String> progress = new ArrayList<>();
            Panorama p;
            try (PanoramaRenderer r = PanoramaRenderer.open(dem).withStitchPasses(passes)) {
                p = r.render(request, progress::add);
            }
            float[] a = one.distanceArray(), b = p.distanceArray();
            for (int i = 0; i < a.length; i++) {
                assertEquals(0, Float.compare(a[i], b[i]), passes + " passes: distance at pixel " + i);
            }
            for (int row = 0; row < one.heightPx(); row++) {
                for (int col = 0; col < one.widthPx(); col++) {
                    assertEquals(one.argb(col, row), p.argb(col, row), passes + " passes: colour at " + col + ", " + row);
                }
            }
            // The same pixels exact and probed (the triangles seen are counted per pass: a few seen twice).
            assertEquals(distances.replaceAll("from the \\d+ triangles", ""),
                    distancesLine(progress).replaceAll("from the \\d+ triangles", ""));
        }
    }

    @Test
    void aCameraStitchedInPassesMatchesOneStitch() {
        InMemoryDem dem = Synthetic.dem(StitchPassesRenderTest::relief, 46, 8, 1, 1);
        CameraPose pose = new CameraPose(46.5, 8.5, 0, Double.NaN, 2, new CameraOrientation(40, -5, 3));
        CameraRequest request = CameraRequest.of(CameraIntrinsics.fromHorizontalFov(300, 200, 150), pose)
                .withSettings(PanoramaRequest.at(46.5, 8.5).withRangeMetres(40_000).withExactDistances(true));
        CameraImage one, two;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem).withStitchPasses(1)) {
            one = r.render(request);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(dem).withStitchPasses(2)) {
            two = r.render(request);
        }
        assertTrue(one.metadata().views() >= 2, "a camera drawn in one view cannot be split");
        float[] a = one.distanceArray(), b = two.distanceArray();
        for (int i = 0; i < a.length; i++) {
            assertEquals(0, Float.compare(a[i], b[i]), "distance at pixel " + i);
        }
        assertArrayEquals(one.argbArray(), two.argbArray());
    }

    /**
     * A caller interrupted while the views are drawn gets "interrupted while rendering" with its interrupt flag kept,
     * once the drawing has ended and the scene's buffers are released: the same renderer then draws the same
     * panorama a fresh one does.
     */
    @Test
    void anInterruptedRenderSaysSoAndLeavesTheRendererUsable() {
        InMemoryDem dem = Synthetic.dem(StitchPassesRenderTest::relief, 46, 8, 1, 1);
        PanoramaRequest request = PanoramaRequest.at(46.5, 8.5).withRangeMetres(30_000).withPixelsPerDegree(6)
                .withElevationRange(new ElevationRange(-20, 10, false));
        Panorama again, fresh;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem).withoutMeshCache()) {
            // A CancellationException: an IllegalStateException, as it was, that a caller can tell from a closed renderer's.
            IllegalStateException e = org.junit.jupiter.api.Assertions.assertThrows(java.util.concurrent.CancellationException.class,
                    () -> r.render(request, line -> {
                        if (line.startsWith("rendering")) {
                            Thread.currentThread().interrupt(); // as a caller's cancel would, while drawing starts
                        }
                    }));
            assertTrue(Thread.interrupted(), "the interrupt flag is kept (and cleared here)");
            assertEquals("interrupted while rendering", e.getMessage());
            again = r.render(request);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            fresh = r.render(request);
        }
        float[] a = fresh.distanceArray(), b = again.distanceArray();
        for (int i = 0; i < a.length; i++) {
            assertEquals(0, Float.compare(a[i], b[i]), "distance at pixel " + i);
        }
    }

    private static String distancesLine(List<String> progress) {
        return progress.stream().filter(l -> l.startsWith("distances:")).findFirst()
                .orElseThrow(() -> new AssertionError("no distances line: " + progress));
    }
}
