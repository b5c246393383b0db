package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.DemSource;
import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.TileId;
import dempano.panorama.Panorama;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * A renderer kept open while a tile changes (a {@link dempano.dem.DemDirectory} reads a rewritten file
 * again) draws the new heights: the patch deviations and meshes it keeps in memory are not served for
 * the old ones.
 */
class ChangedTileRenderTest {
    /** A source whose tiles can be swapped for another's, as a folder's are when a file is rewritten. */
    private static final class Swappable implements DemSource {
        volatile DemSource now;

        Swappable(DemSource first) {
            now = first;
        }

        @Override
        public Optional<HgtTile> tile(TileId id) {
            return now.tile(id);
        }

        @Override
        public String describe() {
            return "swappable";
        }
    }

    private static InMemoryDem dem(double bumpMetres) {
        // RUGGED raised by bumpMetres on a block 4–7 km north-east of the eye.
        return Synthetic.dem((lat, lon) -> LevelOfDetailRenderTest.RUGGED.applyAsDouble(lat, lon)
                + (lat > 46.55 && lat < 46.58 && lon > 8.55 && lon < 8.60 ? bumpMetres : 0), 46, 8, 1, 1);
    }

    private static int differing(Panorama a, Panorama b) {
        float[] x = a.distanceArray(), y = b.distanceArray();
        int n = 0;
        for (int i = 0; i < x.length; i++) {
            n += Float.compare(x[i], y[i]) != 0 ? 1 : 0;
        }
        return n;
    }

    @Test
    void aTileChangedBetweenRendersIsDrawnAsItIsNow() {
        PanoramaRequest request = MeshReuseRenderTest.at(46.518, 8.51, 2);
        Swappable source = new Swappable(dem(0));
        Panorama before, after, fresh;
        try (PanoramaRenderer r = PanoramaRenderer.open(source)) {
            before = r.render(request);
            source.now = dem(400);
            after = r.render(request);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(dem(400))) {
            fresh = r.render(request);
        }
        assertTrue(differing(before, fresh) > 1000, "the bump shows: " + differing(before, fresh));
        assertEquals(0, differing(after, fresh), "distances differ from a fresh renderer's in " + differing(after, fresh)
                + " pixels");
        assertEquals(fresh.metadata().terrainTriangles(), after.metadata().terrainTriangles());
    }

    /** An SRTM3 file of RUGGED plus a bump. */
    private static void writeTile(java.nio.file.Path dir, double bumpMetres) throws java.io.IOException {
        Synthetic.writeHgt(dir, (lat, lon) -> LevelOfDetailRenderTest.RUGGED.applyAsDouble(lat, lon)
                + (lat > 46.55 && lat < 46.58 && lon > 8.55 && lon < 8.60 ? bumpMetres : 0), 46, 8);
    }

    /** The user's case: a renderer open on a folder whose tile file is rewritten between two renders. */
    @Test
    void aTileFileRewrittenBetweenRendersIsDrawnAsItIsNow(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws java.io.IOException {
        PanoramaRequest request = MeshReuseRenderTest.at(46.518, 8.51, 2);
        java.nio.file.Path file = dir.resolve("N46E008.hgt");
        writeTile(dir, 0);
        Panorama before, after, fresh;
        try (PanoramaRenderer r = PanoramaRenderer.open(new dempano.dem.DemDirectory(dir, 16))) {
            before = r.render(request);
            writeTile(dir, 400);
            // A later modification time, whatever the file system's clock resolution.
            java.nio.file.Files.setLastModifiedTime(file, java.nio.file.attribute.FileTime.fromMillis(
                    java.nio.file.Files.getLastModifiedTime(file).toMillis() + 10_000));
            after = r.render(request);
        }
        try (PanoramaRenderer r = PanoramaRenderer.open(new dempano.dem.DemDirectory(dir, 16))) {
            fresh = r.render(request);
        }
        assertTrue(differing(before, fresh) > 1000, "the bump shows: " + differing(before, fresh));
        assertEquals(0, differing(after, fresh), "distances differ from a fresh renderer's in " + differing(after, fresh)
                + " pixels");
    }
}
