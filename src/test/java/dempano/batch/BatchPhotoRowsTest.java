package dempano.batch;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.camera.ExifJpeg;
import dempano.camera.PhotoOverrides;
import dempano.dem.DemDirectory;
import dempano.io.PanoramaWriter;
import dempano.io.SummitWriter;
import dempano.panorama.ElevationRange;
import dempano.photo.PhotoJob;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Photo rows in a batch: a viewpoint file mixing viewpoints and photographs (JPEGs this test renders and
 * writes, with EXIF/XMP it writes), one renderer for all; a missing or corrupt photo is that row's error.
 */
class BatchPhotoRowsTest {
    @TempDir
    Path tmp;

    /** An SRTM3 tile of smooth hills (400–1000 m). */
    static void tile(Path dir) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(2 * 1201 * 1201);
        for (int r = 0; r < 1201; r++) {
            for (int c = 0; c < 1201; c++) {
                double la = 47 - r / 1200.0, lo = 8 + c / 1200.0;
                b.putShort((short) Math.round(700 + 150 * Math.sin(la * 20) + 150 * Math.cos(lo * 15)));
            }
        }
        Files.write(dir.resolve("N46E008.hgt"), b.array());
    }

    @Test
    void aMixedFileRendersViewpointsAndPhotosAndReportsBadPhotosPerRow() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem);
        Path out = Files.createDirectories(tmp.resolve("out"));
        PanoramaRequest defaults = PanoramaRequest.at(0, 0).withRangeMetres(20_000).withPixelsPerDegree(4)
                .withElevationRange(ElevationRange.parse("-10:10"));
        try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(dem))) {
            // The "photo": a camera view from flags alone (1500 m over 400–1000 m hills, heading 120°, pitch -5°,
            // 35 mm equivalent), saved as a JPEG whose EXIF/XMP says where and how it was taken.
            PhotoOverrides pose = PhotoOverrides.NONE.withPosition(46.5, 8.5).withAltitudeMetres(1500).withHeadingDeg(120)
                    .withPitchDeg(-5).withRollDeg(0).withFocal35mmMm(35).withCameraHeightMetres(0); // GPS altitude is the camera's
            PhotoJob.Result truth = PhotoJob.run(r, new PhotoJob.Input(null, pose, 240, 160, dempano.orient.SearchRanges.NONE, defaults, null,
                    tmp.resolve("truth").toString()), PhotoJob.Log.NONE);
            Path photos = Files.createDirectories(tmp.resolve("photos"));
            java.awt.image.BufferedImage view = ImageIO.read(tmp.resolve("truth.png").toFile());
            new ExifJpeg().orientation(1).position(46.5, 8.5).altitude(0, 150_000).direction("T", 12_000).focal35(35)
                    .xmp("drone-dji:GimbalPitchDegree=\"-5.0\" drone-dji:GimbalRollDegree=\"+0.0\"")
                    .write(photos, "full.jpg", view);
            // No compass: the heading comes from the row's heading_deg column.
            new ExifJpeg().orientation(1).position(46.5, 8.5).altitude(0, 150_000).focal35(35)
                    .xmp("drone-dji:GimbalPitchDegree=\"-5.0\" drone-dji:GimbalRollDegree=\"+0.0\"")
                    .write(photos, "nohead.jpg", view);
            byte[] full = Files.readAllBytes(photos.resolve("full.jpg"));
            Files.write(photos.resolve("broken.jpg"), Arrays.copyOf(full, 40)); // cut inside its EXIF
            Path csv = Files.writeString(tmp.resolve("v.csv"), "id,lat,lon,image,heading_deg\n"
                    + "view,46.45,8.45,,\n"
                    + "photo,,,photos/full.jpg,\n"
                    + "column,,,photos/nohead.jpg,120\n"
                    + "gone,,,photos/gone.jpg,\n"
                    + "broken,,,photos/broken.jpg,\n"
                    + "mixed,46.4,8.4,,90\n"
                    + "half,46.5,,photos/full.jpg,\n");
            ViewpointCsv.Parsed parsed = ViewpointCsv.read(csv, defaults);
            assertEquals(List.of(), parsed.ignoredColumns());
            BatchSummary s = new BatchRenderer(r, out, new PanoramaWriter.Options(false, null, SummitWriter.LabelOptions.DEFAULT))
                    .render(parsed.rows(), null);
            Map<String, BatchResult> byId = s.results().stream().collect(Collectors.toMap(BatchResult::id, x -> x));
            assertEquals(7, byId.size());
            for (String ok : List.of("view", "photo", "column")) {
                assertTrue(byId.get(ok).ok(), ok + ": " + byId.get(ok).error());
            }
            assertEquals(List.of("photo.png", "photo-distance.npy", "photo-overlay.png", "photo.json"),
                    byId.get("photo").files().stream().map(f -> f.getFileName().toString()).toList());
            assertError(byId.get("gone"), "gone.jpg");
            assertError(byId.get("broken"), "broken.jpg");
            assertError(byId.get("mixed"), "heading_deg is for photo rows");
            assertError(byId.get("half"), "both lat and lon");
            assertFalse(Files.exists(out.resolve("gone.png")) || Files.exists(out.resolve("broken.png")));

            // The camera the EXIF gives (or the EXIF and the heading column) is the camera the photo was made with:
            // the same distance for every pixel, byte for byte.
            byte[] expected = Files.readAllBytes(tmp.resolve("truth-distance.npy"));
            assertArrayEquals(expected, Files.readAllBytes(out.resolve("photo-distance.npy")));
            assertArrayEquals(expected, Files.readAllBytes(out.resolve("column-distance.npy")));
            assertEquals(240, ImageIO.read(out.resolve("photo-overlay.png").toFile()).getWidth());
            assertTrue(Files.readString(out.resolve("column.json")).contains("\"headingDeg\": 120.0"));
            assertEquals(truth.files().size(), byId.get("photo").files().size());

            // The viewpoint row is the panorama a single render makes.
            PanoramaWriter.Options plain = new PanoramaWriter.Options(false, null, SummitWriter.LabelOptions.DEFAULT);
            try (dempano.io.OutputSet set = dempano.io.OutputSet.open(tmp.resolve("single").toString())) {
                PanoramaWriter.stage(set, r.render(ViewpointCsv.atViewpoint(defaults, 46.45, 8.45)), plain);
                set.commit();
            }
            assertArrayEquals(Files.readAllBytes(tmp.resolve("single-distance.npy")),
                    Files.readAllBytes(out.resolve("view-distance.npy")));
        }
        List<String> results = Files.readAllLines(BatchRenderer.resultsFile(out));
        assertEquals(8, results.size());
        assertTrue(results.get(2).startsWith("photo,ok,photo.png photo-distance.npy photo-overlay.png photo.json,"),
                results.get(2));
    }

    private static void assertError(BatchResult r, String part) {
        assertFalse(r.ok(), r.id());
        assertTrue(r.error().contains(part), r.id() + ": " + r.error());
        assertFalse(r.error().contains("Exception"), r.error());
    }
}
