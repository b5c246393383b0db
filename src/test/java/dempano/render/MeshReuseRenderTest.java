package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.panorama.ElevationRange;
import dempano.panorama.Panorama;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Terrain geometry kept on the GPU from one viewpoint and drawn from another gives the panorama a
 * fresh renderer gives there: the vertices do not depend on the eye, the shader places them.
 */
class MeshReuseRenderTest {
    static PanoramaRequest at(double lat, double lon, double eyeHeightMetres) {
        return PanoramaRequest.at(lat, lon).withRangeMetres(40_000).withEyeHeightMetres(eyeHeightMetres)
                .withPixelsPerDegree(10).withElevationRange(new ElevationRange(-30, 15, false));
    }

    @Test
    void aViewpointDrawnWithGeometryCachedElsewhereMatchesAFreshRenderer() {
        InMemoryDem dem = Synthetic.dem(LevelOfDetailRenderTest.RUGGED, 46, 8, 1, 1);
        PanoramaRequest first = at(46.5, 8.5, 2), second = at(46.518, 8.51, 2), third = at(46.518, 8.51, 300);
        Panorama reused, reusedHigh, fresh, freshHigh;
        try (PanoramaRenderer warm = PanoramaRenderer.open(dem)) {
            warm.render(first);
            reused = warm.render(second);
            reusedHigh = warm.render(third);
        }
        try (PanoramaRenderer cold = PanoramaRenderer.open(dem)) {
            fresh = cold.render(second);
        }
        try (PanoramaRenderer cold = PanoramaRenderer.open(dem)) {
            freshHigh = cold.render(third);
        }
        for (Panorama[] pair : new Panorama[][] {{reused, fresh}, {reusedHigh, freshHigh}}) {
            float[] a = pair[0].distanceArray(), b = pair[1].distanceArray();
            int differing = 0;
            for (int i = 0; i < a.length; i++) {
                differing += Float.compare(a[i], b[i]) != 0 ? 1 : 0;
            }
            assertEquals(0, differing, "distances differ in " + differing + " of " + a.length + " pixels");
            int colours = 0;
            for (int r = 0; r < pair[0].heightPx(); r++) {
                for (int c = 0; c < pair[0].widthPx(); c++) {
                    colours += pair[0].argb(c, r) != pair[1].argb(c, r) ? 1 : 0;
                }
            }
            assertEquals(0, colours, "colours differ in " + colours + " pixels");
            assertEquals(pair[1].metadata().terrainTriangles(), pair[0].metadata().terrainTriangles());
        }
        assertTrue(reused.metadata().terrainTriangles() > 0);
    }

    /**
     * Without the mesh cache (the CLI's one panorama), a render draws no patch kept from the one before, and the
     * panorama is the same as with it.
     */
    @Test
    void aRendererWithoutMeshCacheKeepsNoPatchAndDrawsTheSame() {
        InMemoryDem dem = Synthetic.dem(LevelOfDetailRenderTest.RUGGED, 46, 8, 1, 1);
        PanoramaRequest request = at(46.518, 8.51, 2);
        List<String> keeping = new ArrayList<>(), notKeeping = new ArrayList<>();
        Panorama kept, notKept;
        try (PanoramaRenderer r = PanoramaRenderer.open(dem)) {
            r.render(request);
            kept = r.render(request, keeping::add);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(dem).withoutMeshCache()) {
            r.render(request);
            notKept = r.render(request, notKeeping::add);
        }
        assertTrue(reusedPatches(keeping) > 0, "with the cache the second render reuses patches: " + keeping);
        assertEquals(0, reusedPatches(notKeeping), "without it none: " + notKeeping);
        float[] a = kept.distanceArray(), b = notKept.distanceArray(); // copies: taken once
        for (int i = 0; i < a.length; i++) {
            assertEquals(0, Float.compare(a[i], b[i]), "distance at pixel " + i);
        }
        for (int r = 0; r < kept.heightPx(); r++) {
            for (int c = 0; c < kept.widthPx(); c++) {
                assertEquals(kept.argb(c, r), notKept.argb(c, r), "colour at " + c + ", " + r);
            }
        }
    }

    /** The patches a render reused, from its progress line ("… N patches reused)"). */
    static long reusedPatches(List<String> progress) {
        Pattern p = Pattern.compile("(\\d+) patches reused");
        for (String line : progress) {
            Matcher m = p.matcher(line);
            if (m.find()) {
                return Long.parseLong(m.group(1));
            }
        }
        throw new AssertionError("no line names the patches reused: " + progress);
    }
}
