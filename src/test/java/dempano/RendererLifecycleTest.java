package dempano;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraPose;
import dempano.dem.DemDirectory;
import dempano.dem.DemSource;
import dempano.dem.DemoTerrain;
import dempano.dem.HgtTile;
import dempano.dem.TileId;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * What a Java caller meets around the renders (found by a hostile test of the API): a second close does nothing, a
 * render on a closed renderer is refused before any tile is read, a camera image's pixels are checked as a panorama's.
 */
class RendererLifecycleTest {
    @Test
    void aSecondCloseDoesNothingAndARenderAfterCloseIsRefusedBeforeReadingTiles() throws Exception {
        DemSource demo = new DemDirectory(DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR));
        AtomicInteger reads = new AtomicInteger();
        DemSource counting = new DemSource() {
            @Override
            public Optional<HgtTile> tile(TileId id) {
                reads.incrementAndGet();
                return demo.tile(id);
            }

            @Override
            public String describe() {
                return demo.describe();
            }
        };
        double[] vp = DemoTerrain.viewpoint();
        PanoramaRequest small = PanoramaRequest.at(vp[0], vp[1]).withPixelsPerDegree(2).withRangeMetres(10_000);
        PanoramaRenderer r = PanoramaRenderer.open(counting);
        try (r) {
            assertTrue(r.render(small).hasDistance());
            r.close(); // and try-with-resources closes it again: it threw "renderer handle is closed"
        }
        r.close();
        int before = reads.get();
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> r.render(small));
        assertTrue(e.getMessage().contains("closed"), e.getMessage());
        CameraRequest camera = CameraRequest.of(CameraIntrinsics.fromHorizontalFov(40, 30, 40),
                new CameraPose(vp[0], vp[1], 0, Double.NaN, 2, new CameraOrientation(0, 0, 0)));
        assertThrows(IllegalStateException.class, () -> r.render(camera));
        assertEquals(before, reads.get(), "no tile read for a refused render");

        // The reference renderer too.
        PanoramaRenderer ref = PanoramaRenderer.openReference(demo);
        ref.close();
        ref.close();
        assertThrows(IllegalStateException.class, () -> ref.render(small));
    }

    @Test
    void aCameraImagesPixelsAreCheckedAsAPanoramas() throws Exception {
        double[] vp = DemoTerrain.viewpoint();
        CameraRequest camera = CameraRequest.of(CameraIntrinsics.fromHorizontalFov(30, 20, 40),
                new CameraPose(vp[0], vp[1], 0, Double.NaN, 2, new CameraOrientation(0, -5, 0)));
        CameraImage both, colourOnly;
        try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR)))) {
            PanoramaRequest settings = PanoramaRequest.at(vp[0], vp[1]).withRangeMetres(10_000);
            both = r.render(camera.withSettings(settings));
            colourOnly = r.render(camera.withSettings(settings.withDistance(false)));
        }
        float[] d = both.distanceArray();
        assertEquals(d[19 * 30 + 29], both.distanceMetres(29, 19));
        assertEquals(d[0], both.distanceMetres(0, 0));
        // Column 30 of row 10 was row 11's column 0, column -1 row 9's last: another pixel's distance.
        for (int[] outside : new int[][] {{30, 10}, {-1, 10}, {0, 20}, {0, -1}}) {
            IndexOutOfBoundsException e = assertThrows(IndexOutOfBoundsException.class,
                    () -> both.distanceMetres(outside[0], outside[1]));
            assertTrue(e.getMessage().contains(outside[0] < 0 || outside[0] >= 30 ? "column" : "row"), e.getMessage());
        }
        assertThrows(IllegalStateException.class, colourOnly::distanceBuffer); // was a NullPointerException
        assertThrows(IllegalStateException.class, () -> colourOnly.distanceMetres(0, 0));
    }
}
