package dempano.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.Synthetic;
import dempano.dem.InMemoryDem;
import dempano.io.PanoramaWriter;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.panorama.Silhouettes;
import dempano.summits.SummitList;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.function.DoubleBinaryOperator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Colour only and distances only against the full rendering of the same request: each skips the
 * other's work and gives the same pixels of what it keeps. Colour only finds its silhouette lines
 * from the nearest view samples; they must be the full rendering's lines, also on a plain seen at
 * grazing incidence (where distances triple from row to row and a coarse test would draw false lines).
 * The comparison is with the full rendering's lines as view samples place them (exact distances
 * off); with exact distances a line may move by a row, decided at the pixel's centre, and nowhere else.
 */
class OutputChoiceRenderTest {
    static final double LAT = 46.5, LON = 8.5;
    static InMemoryDem rugged, plain;
    static PanoramaRenderer gl;

    @BeforeAll
    static void open() {
        rugged = Synthetic.dem(LevelOfDetailRenderTest.RUGGED, 46, 8, 1, 1);
        DoubleBinaryOperator flat = (lat, lon) -> 500;
        plain = Synthetic.dem(flat, 46, 8, 1, 1);
        gl = PanoramaRenderer.open(rugged);
    }

    @AfterAll
    static void close() {
        gl.close();
    }

    static PanoramaRequest request(double eyeHeightMetres) {
        return PanoramaRequest.at(LAT, LON).withRangeMetres(45_000).withEyeHeightMetres(eyeHeightMetres)
                .withPixelsPerDegree(10).withElevationRange(new ElevationRange(-20, 15, false));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"rugged relief, eye 30 m", "plain at grazing incidence, eye 3 m"})
    void colourOnlyDrawsTheFullRenderingsPictureWithItsSilhouettes(String scene) {
        boolean onPlain = scene.startsWith("plain");
        try (PanoramaRenderer r = PanoramaRenderer.open(onPlain ? plain : rugged)) {
            PanoramaRequest req = request(onPlain ? 3 : 30);
            Panorama full = r.render(req.withExactDistances(false));
            Panorama colourOnly = r.render(req.withDistance(false));
            assertTrue(colourOnly.hasColour());
            assertFalse(colourOnly.hasDistance());
            assertThrows(IllegalStateException.class, () -> colourOnly.distanceAt(90, 0));
            assertThrows(IllegalStateException.class, colourOnly::distanceArray);
            assertEquals(full.widthPx(), colourOnly.widthPx());
            assertEquals(full.heightPx(), colourOnly.heightPx());

            int[] sampled = differences(full, colourOnly);
            assertTrue(sampled[0] >= full.widthPx(), "at least the skyline is an edge in every column: " + sampled[0]);
            // Both images come from the same colour samples: they differ only where the lines differ.
            assertTrue(sampled[1] <= 0.05 * sampled[0], sampled[1] + " pixels differ, " + sampled[0] + " silhouette pixels");
            // Measured: rugged 158 of 5255 differ, 37 of them away from edges; the plain 0 of 3600.
            assertTrue(sampled[2] <= 0.015 * sampled[0], sampled[2] + " differing pixels away from any edge");
            // Exact distances decide lines at pixel centres; the nearest samples' lines stay near them.
            // Measured: rugged 169 of 5214 away from an exact edge (a line across a small occluded
            // pocket that the pixel centres' rays miss), the plain 0.
            int[] exact = differences(r.render(req), colourOnly);
            assertTrue(exact[2] <= 0.05 * exact[0], exact[2] + " differing pixels away from any exact edge, of " + exact[0]);
        }
    }

    /**
     * {edges of the full rendering, pixels whose colour differs, differing pixels neither on an edge
     * nor beside one in the row above or below (the nearest sample may put an edge a row off)}.
     */
    private static int[] differences(Panorama full, Panorama colourOnly) {
        float[] d = full.distanceArray();
        int w = full.widthPx(), h = full.heightPx(), edges = 0, differing = 0, differingOffEdges = 0;
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                boolean edge = Silhouettes.isEdge(d, w, h, col, row);
                edges += edge ? 1 : 0;
                if (full.argb(col, row) != colourOnly.argb(col, row)) {
                    differing++;
                    if (!edge && !(row > 0 && Silhouettes.isEdge(d, w, h, col, row - 1))
                            && !(row + 1 < h && Silhouettes.isEdge(d, w, h, col, row + 1))) {
                        differingOffEdges++;
                    }
                }
            }
        }
        return new int[] {edges, differing, differingOffEdges};
    }

    @Test
    void distanceOnlyGivesTheFullRenderingsDistances() {
        PanoramaRequest req = request(30);
        Panorama full = gl.render(req);
        Panorama distanceOnly = gl.render(req.withColour(false));
        assertFalse(distanceOnly.hasColour());
        assertThrows(IllegalStateException.class, distanceOnly::image);
        float[] a = full.distanceArray(), b = distanceOnly.distanceArray();
        int differing = 0;
        for (int i = 0; i < a.length; i++) {
            differing += Float.compare(a[i], b[i]) != 0 ? 1 : 0;
        }
        assertEquals(0, differing, "distances do not depend on whether colour is drawn");
    }

    @Test
    void colourOnlyWritesThePictureAndMetadataAndNoDistanceFiles(@TempDir Path dir) throws Exception {
        Panorama p = gl.render(request(30).withDistance(false));
        List<Path> files = PanoramaWriter.write(p, dir.resolve("p").toString(), false);
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        assertEquals(List.of("p.png", "p.json"), names);
        assertTrue(Files.readString(dir.resolve("p.json")).contains("not rendered (colour only)"));
        assertNotNull(javax.imageio.ImageIO.read(dir.resolve("p.png").toFile()));
        SummitList none = new SummitList("none", List.of(), List.of());
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> p.summits(none));
        assertTrue(e.getMessage().contains("without them"), e.getMessage());
    }

    @Test
    void bothOutputsAreWrittenAndReadBackAsRendered(@TempDir Path dir) throws Exception {
        Panorama p = gl.render(request(30));
        List<Path> files = PanoramaWriter.write(p, dir.resolve("p").toString(), false);
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        assertEquals(List.of("p.png", "p-distance.npy", "p-distance.png", "p.json"), names);
        java.awt.image.BufferedImage colour = javax.imageio.ImageIO.read(dir.resolve("p.png").toFile());
        java.awt.image.BufferedImage distance = javax.imageio.ImageIO.read(dir.resolve("p-distance.png").toFile());
        java.nio.ByteBuffer npy = java.nio.ByteBuffer.wrap(Files.readAllBytes(dir.resolve("p-distance.npy")))
                .order(java.nio.ByteOrder.LITTLE_ENDIAN);
        int header = 10 + (npy.get(8) & 0xff) + ((npy.get(9) & 0xff) << 8);
        float[] d = p.distanceArray();
        float far = Float.NEGATIVE_INFINITY;
        for (float v : d) {
            far = Float.isFinite(v) ? Math.max(far, v) : far;
        }
        int w = p.widthPx();
        for (int row = 0; row < p.heightPx(); row++) {
            for (int col = 0; col < w; col++) {
                assertEquals(p.argb(col, row) & 0xffffff, colour.getRGB(col, row) & 0xffffff, "colour " + col + "," + row);
                assertEquals(d[row * w + col], npy.getFloat(header + 4 * (row * w + col)), "distance " + col + "," + row);
                // The distance picture: sky white, terrain never white.
                int rgb = distance.getRGB(col, row) & 0xffffff;
                assertEquals(Float.isFinite(d[row * w + col]), rgb != 0xffffff, "distance picture " + col + "," + row);
            }
        }
        assertTrue(distance.getHeight() > p.heightPx(), "legend strip");
    }

    @Test
    void anUnwritableOutputNamesTheFileAndLeavesNoWriterRunning(@TempDir Path dir) throws Exception {
        Panorama p = gl.render(request(30));
        Path missing = dir.resolve("no-such-folder");
        java.io.IOException e = assertThrows(java.io.IOException.class,
                () -> PanoramaWriter.write(p, missing.resolve("p").toString(), false));
        assertTrue(e.getMessage().contains(missing.toString()), e.getMessage());
        assertFalse(Files.exists(missing));
        // The colour file fails while the distance picture's thread is writing: write returns only
        // after that thread has ended (joined, not just its result delivered), and no file is left.
        Files.createDirectory(dir.resolve("p.png"));
        java.io.IOException blocked = assertThrows(java.io.IOException.class,
                () -> PanoramaWriter.write(p, dir.resolve("p").toString(), false));
        assertEquals("cannot write " + dir.resolve("p.png") + ": a folder of that name is in the way", blocked.getMessage());
        assertFalse(Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals("dempano-distance-png")),
                "the distance picture's thread ended before write returned");
        try (var left = Files.list(dir)) {
            assertEquals(List.of("p.png"), left.map(f -> f.getFileName().toString()).toList(), "no file of the new set");
        }
    }

    @Test
    void requestsThatWouldRenderNothingOrNeedMissingDistancesAreRefused() {
        PanoramaRequest req = request(30);
        IllegalArgumentException nothing = assertThrows(IllegalArgumentException.class,
                () -> req.withColour(false).withDistance(false));
        assertTrue(nothing.getMessage().contains("nothing to render"), nothing.getMessage());
        IllegalArgumentException layers = assertThrows(IllegalArgumentException.class,
                () -> req.withLayers(EnumSet.of(Layer.ELEVATION)).withDistance(false));
        assertTrue(layers.getMessage().contains("need the distance map"), layers.getMessage());
    }
}
