package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.SharedData;
import dempano.dem.DemDirectory;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A panorama does not depend on what the renderer drew before: a viewpoint rendered after another, whose mosaic
 * covers another block of tiles, has the bits a fresh renderer gives it (what lets a Spark job's rows equal a
 * {@code dempano batch}'s, whatever the rows before them). It did not: a mesh cached from the first viewpoint's
 * mosaic had vertices one bit away from those this render's probe placed from its own (longitudes as
 * {@code west + col / n}), and one pixel of 0.46 million came out one float step off.
 */
class HistoryFreeRenderTest {
    /** Real SRTM3 tiles of the White Mountains: the two viewpoints' 40 km mosaics have west edges 73°W and 72°W. */
    static PanoramaRequest at(double lat, double lon) {
        return PanoramaRequest.at(lat, lon).withRangeMetres(40_000).withPixelsPerDegree(8)
                .withElevationRange(new ElevationRange(-10, 10, false));
    }

    @Test
    void aViewpointRenderedAfterAnotherEqualsItsFreshRender() {
        DemDirectory dem = new DemDirectory(SharedData.demDir());
        PanoramaRequest before = at(44.15, -71.60), after = at(44.25, -71.48);
        Panorama fresh, second;
        List<String> progress = new ArrayList<>();
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            fresh = r.render(after);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            r.render(before);
            second = r.render(after, progress::add);
        }
        assertTrue(MeshReuseRenderTest.reusedPatches(progress) > 0, "the second render reuses patches: " + progress);
        float[] a = fresh.distanceArray(), b = second.distanceArray();
        int differing = 0;
        for (int i = 0; i < a.length; i++) {
            differing += Float.compare(a[i], b[i]) != 0 ? 1 : 0;
        }
        assertEquals(0, differing, "distances differ in " + differing + " of " + a.length + " pixels");
        int colours = 0;
        for (int row = 0; row < fresh.heightPx(); row++) {
            for (int c = 0; c < fresh.widthPx(); c++) {
                colours += fresh.argb(c, row) != second.argb(c, row) ? 1 : 0;
            }
        }
        assertEquals(0, colours, "colours differ in " + colours + " pixels");
    }
}
