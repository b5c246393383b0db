package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.cli.Main;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code dempano photo} end to end: a camera from a JPEG's EXIF/XMP alone, from flags alone, and what is missing. */
class PhotoCliTest {
    @TempDir
    Path tmp;

    /** An SRTM3 tile of smooth hills (400–1000 m). */
    static Path tile(Path dir, int lat, int lon) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(2 * 1201 * 1201);
        for (int r = 0; r < 1201; r++) {
            for (int c = 0; c < 1201; c++) {
                double la = lat + 1 - r / 1200.0, lo = lon + c / 1200.0;
                b.putShort((short) Math.round(700 + 150 * Math.sin(la * 20) + 150 * Math.cos(lo * 15)));
            }
        }
        return Files.write(dir.resolve(String.format("N%02dE%03d.hgt", lat, lon)), b.array());
    }

    private record Run(int exit, String out, String err) {
    }

    private static Run run(String... args) {
        PrintStream out = System.out, err = System.err;
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(o, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            int exit = Main.run(args);
            return new Run(exit, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
    }

    /** The shape and values of a float32 .npy file. */
    static float[] npy(Path file, int rows, int cols) throws IOException {
        byte[] b = Files.readAllBytes(file);
        ByteBuffer buf = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int headerLen = buf.getShort(8) & 0xffff;
        String header = new String(b, 10, headerLen, StandardCharsets.US_ASCII);
        assertTrue(header.contains("'shape': (" + rows + ", " + cols + ")"), header);
        assertTrue(header.contains("<f4"), header);
        float[] v = new float[rows * cols];
        buf.position(10 + headerLen);
        buf.asFloatBuffer().get(v);
        return v;
    }

    private void checkOutputs(String prefix, int w, int h) throws IOException {
        BufferedImage png = ImageIO.read(Path.of(prefix + ".png").toFile());
        BufferedImage overlay = ImageIO.read(Path.of(prefix + "-overlay.png").toFile());
        assertEquals(w, png.getWidth());
        assertEquals(h, png.getHeight());
        assertEquals(w, overlay.getWidth());
        assertEquals(h, overlay.getHeight());
        float[] d = npy(Path.of(prefix + "-distance.npy"), h, w);
        long sky = 0, terrain = 0;
        for (float v : d) {
            if (v == Float.POSITIVE_INFINITY) {
                sky++;
            } else if (v > 0 && v < 25_000) {
                terrain++;
            }
        }
        assertEquals(d.length, sky + terrain, "every pixel is sky (+inf) or terrain within range");
        assertTrue(sky > 0 && terrain > 0, sky + " sky, " + terrain + " terrain");
        String json = Files.readString(Path.of(prefix + ".json"));
        assertTrue(json.contains("\"width\": " + w) && json.contains("\"height\": " + h), json);
        assertTrue(json.contains("\"conventions\"") && json.contains("N46E008"), json);
        // The fields a panorama's P.json has too (the camera's had drifted: no DEM sources, near plane or bound).
        com.google.gson.JsonObject doc = com.google.gson.JsonParser.parseString(json).getAsJsonObject();
        com.google.gson.JsonObject source = doc.getAsJsonArray("demSources").get(0).getAsJsonObject();
        assertEquals("N46E008", source.get("tile").getAsString(), json);
        assertEquals("EGM96", source.get("verticalDatum").getAsString(), json);
        assertTrue(doc.get("nearMetres").getAsDouble() > 0 && doc.get("terrainTriangles").getAsLong() > 0, json);
        assertEquals(dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX, doc.get("lodErrorPx").getAsDouble(), 0, json);
        assertTrue(doc.getAsJsonObject("eye").has("eyeHeightMetres"), json);
    }

    /**
     * {@code dempano photo} on a drone's JPEG over the hills of {@link #tile}: at 46.5° N 8.5° E, GPS altitude
     * {@code altitudeCentimetres}, facing east (GPS true), DJI gimbal pitch and roll; 160 × 120 px, 20 km range. It must
     * succeed with every output in place; returns its stderr.
     */
    private String droneRun(long altitudeCentimetres, String prefix) throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).altitude(0, altitudeCentimetres).direction("T", 9000)
                .focal35(35).xmp("drone-dji:GimbalYawDegree=\"+90.0\" drone-dji:GimbalPitchDegree=\"-8.0\""
                        + " drone-dji:GimbalRollDegree=\"+0.0\"")
                .write(tmp, prefix + ".jpg", 160, 120);
        Run r = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve(prefix).toString(),
                "--range-km", "20");
        assertEquals(0, r.exit(), r.err());
        checkOutputs(tmp.resolve(prefix).toString(), 160, 120);
        return r.err();
    }

    @Test
    void aJpegsExifAndXmpAloneGiveTheCamera() throws IOException {
        // 2000 m above sea level over 400–1000 m hills.
        String err = droneRun(200_000, "exif");
        assertTrue(err.contains("35"), err); // the provenance names the 35 mm-equivalent focal length
    }

    @Test
    void aGpsAltitudeBelowTheTerrainIsLeftOutAndTheCameraStandsOnTheDem() throws IOException {
        // The drone photo's camera, but its GPS altitude 100 m, below the 400–1000 m hills: it was an error ("the eye
        // would be … below the DEM surface").
        String err = droneRun(10_000, "low");
        String prefix = tmp.resolve("low").toString();
        assertTrue(err.contains("camera altitude 100 m from EXIF GPSAltitude not used: "), err);
        com.google.gson.JsonObject json = com.google.gson.JsonParser.parseString(Files.readString(Path.of(prefix + ".json")))
                .getAsJsonObject();
        com.google.gson.JsonObject eye = json.getAsJsonObject("eye"), pose = json.getAsJsonObject("pose");
        assertEquals(0, pose.get("offsetMetres").getAsDouble(), json.toString());
        assertEquals(eye.get("groundElevationMetres").getAsDouble() + dempano.geo.Viewpoint.DEFAULT_EYE_HEIGHT_METRES,
                eye.get("eyeAltitudeMetres").getAsDouble(), 1e-6, json.toString());
        assertTrue(eye.get("groundElevationMetres").getAsDouble() > 400, json.toString());
    }

    @Test
    void aFieldOfViewRangeBoundsTheEstimateAndIsSaidWhereItIsNotUsed() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        // A "photo" of the hills rendered from flags (50° field of view), then matched with the field of view open but
        // bounded to 45–48°: the estimate stays within the bound (3 % beyond it is the flag's own margin), and says so.
        String truth = tmp.resolve("truth").toString();
        Run t = run("photo", "--dem-dir", dem.toString(), "--out", truth, "--range-km", "20", "--lat", "46.5", "--lon",
                "8.5", "--offset-m", "0", "--heading-deg", "200", "--pitch-deg", "-2", "--roll-deg", "0", "--hfov-deg", "50",
                "--width-px", "240", "--height-px", "160");
        assertEquals(0, t.exit(), t.err());
        String prefix = tmp.resolve("ranged").toString();
        Run r = run("photo", truth + ".png", "--dem-dir", dem.toString(), "--out", prefix, "--range-km", "20", "--lat",
                "46.5", "--lon", "8.5", "--offset-m", "0", "--hfov-range-deg", "45,48");
        assertEquals(0, r.exit(), r.err());
        double hfov = com.google.gson.JsonParser.parseString(Files.readString(Path.of(prefix + "-orientation.json")))
                .getAsJsonObject().get("hfovDeg").getAsDouble();
        assertTrue(hfov >= 45 * 0.97 - 1e-9 && hfov <= 48 * 1.03 + 1e-9, "hfov " + hfov + "\n" + r.err());
        assertTrue(Files.readString(Path.of(prefix + ".json")).contains("field of view searched within 45.0°–48.0°"
                + " (--hfov-range-deg)"), Files.readString(Path.of(prefix + ".json")));
        // With the field of view given, the range is not used, and said so.
        Run given = run("photo", truth + ".png", "--dem-dir", dem.toString(), "--out", tmp.resolve("given").toString(),
                "--range-km", "20", "--lat", "46.5", "--lon", "8.5", "--offset-m", "0", "--hfov-deg", "50",
                "--focal35-range-mm", "24,70");
        assertEquals(0, given.exit(), given.err());
        assertTrue(given.err().contains("not used: the field of view is known"), given.err());
        // The estimate's files are the set's: listed in P.json, and gone after a run of the prefix that estimates nothing.
        assertTrue(Files.readString(Path.of(prefix + ".json")).contains("ranged-orientation.json"));
        Run pinned = run("photo", truth + ".png", "--dem-dir", dem.toString(), "--out", prefix, "--range-km", "20",
                "--lat", "46.5", "--lon", "8.5", "--offset-m", "0", "--heading-deg", "200", "--pitch-deg", "-2",
                "--roll-deg", "0", "--hfov-deg", "50");
        assertEquals(0, pinned.exit(), pinned.err());
        for (String stale : new String[] {"-orientation.json", "-orientation.png"}) {
            assertFalse(Files.exists(Path.of(prefix + stale)), prefix + stale + " left from the run before");
        }
        assertTrue(Files.exists(Path.of(prefix + "-overlay.png")));
    }

    @Test
    void anOutputPrefixThatWouldWriteOverThePhotoIsRefusedAndThePhotoKept() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path photo = tmp.resolve("f.png");
        javax.imageio.ImageIO.write(new java.awt.image.BufferedImage(64, 48, java.awt.image.BufferedImage.TYPE_INT_RGB),
                "png", photo.toFile());
        byte[] before = Files.readAllBytes(photo);
        Run r = run("photo", photo.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("f").toString(),
                "--range-km", "20", "--lat", "46.5", "--lon", "8.5", "--offset-m", "0", "--heading-deg", "200",
                "--pitch-deg", "-2", "--roll-deg", "0", "--hfov-deg", "50");
        assertTrue(r.exit() != 0, r.err());
        assertTrue(r.err().contains("cannot write " + photo + ": it is the photo"), r.err());
        assertFalse(r.err().contains("\tat "), r.err());
        assertArrayEquals(before, Files.readAllBytes(photo));
    }

    @Test
    void flagsAloneGiveASyntheticCamera() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        String prefix = tmp.resolve("flags").toString();
        Run r = run("photo", "--dem-dir", dem.toString(), "--out", prefix, "--range-km", "20", "--lat", "46.5",
                "--lon", "8.5", "--altitude-m", "1500", "--heading-deg", "200", "--pitch-deg", "-5", "--roll-deg", "10",
                "--hfov-deg", "60", "--width-px", "200", "--height-px", "100", "--distortion", "-0.1,0,0,0,0",
                "--exact-distances");
        assertEquals(0, r.exit(), r.err());
        checkOutputs(prefix, 200, 100);
        String json = Files.readString(Path.of(prefix + ".json"));
        assertTrue(json.contains("\"k1\": -0.1") && json.contains("\"rollDeg\": 10.0"), json);
    }

    /** Flags that would be left unused without a word are refused before anything is read or rendered. */
    @Test
    void twoLensesOrHalfAPositionAreBadArguments() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        String[] common = {"photo", "--dem-dir", dem.toString(), "--out", tmp.resolve("x").toString(), "--width-px", "64",
            "--height-px", "48", "--heading-deg", "10", "--pitch-deg", "0", "--roll-deg", "0", "--altitude-m", "1500"};
        String[][] cases = {
            {"--hfov-deg and --focal35-mm each set the field of view: give one", "--lat", "46.5", "--lon", "8.5",
                "--hfov-deg", "50", "--focal35-mm", "200"},
            {"--hfov-deg and --focal-mm/--sensor-width-mm each set", "--lat", "46.5", "--lon", "8.5", "--hfov-deg", "50",
                "--focal-mm", "20"},
            {"--lat given without --lon", "--lat", "46.5", "--hfov-deg", "50"},
            {"--lon given without --lat", "--lon", "8.5", "--hfov-deg", "50"},
        };
        for (String[] c : cases) {
            String[] args = java.util.stream.Stream.concat(java.util.Arrays.stream(common),
                    java.util.Arrays.stream(c, 1, c.length)).toArray(String[]::new);
            Run r = run(args);
            assertEquals(2, r.exit(), r.err());
            assertTrue(r.err().contains(c[0]), r.err());
        }
    }

    /**
     * Before an estimate, what the flags or the photo gave but cannot be used is said; an eye below the ground is
     * that error alone, not a failed estimate listing flags that would not help.
     */
    @Test
    void anEstimateSaysWhatItReplacesAndAnEyeBelowGroundIsItsOwnError() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).write(tmp, "lensless.jpg", 64, 48);
        Run focal = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("f").toString(),
                "--range-km", "20", "--focal-mm", "50");
        assertTrue(focal.err().contains("estimated instead: --focal-mm needs --sensor-width-mm"), focal.err());
        Run low = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("low").toString(),
                "--range-km", "20", "--altitude-m", "100");
        assertEquals(2, low.exit(), low.err());
        assertTrue(low.err().contains("below the DEM surface"), low.err());
        assertFalse(low.err().contains("could not estimate"), low.err());
    }

    /** An unwritable destination is found before the estimate and the render, not after them. */
    @Test
    void aMissingOutputFolderIsFoundBeforeTheEstimate() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).write(tmp, "open.jpg", 64, 48);
        Run r = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("absent/p").toString());
        assertEquals(1, r.exit(), r.err());
        assertTrue(r.err().contains("does not exist"), r.err());
        assertFalse(r.err().contains("estimating from the skyline"), r.err());
    }

    @Test
    void theRendersWarningsAreSaidAsWellAsKeptInTheJson() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        String prefix = tmp.resolve("edge").toString();
        // 20 km reach N45E008 and N46E007, absent: sea level, which the render warns of
        Run r = run("photo", "--dem-dir", dem.toString(), "--out", prefix, "--range-km", "20", "--lat", "46.05",
                "--lon", "8.05", "--altitude-m", "1500", "--heading-deg", "200", "--pitch-deg", "0", "--roll-deg", "0",
                "--hfov-deg", "60", "--width-px", "120", "--height-px", "80");
        assertEquals(0, r.exit(), r.err());
        com.google.gson.JsonArray warnings = com.google.gson.JsonParser.parseString(
                Files.readString(Path.of(prefix + ".json"))).getAsJsonObject().getAsJsonArray("warnings");
        assertTrue(warnings.size() > 0, "no warning in P.json");
        for (com.google.gson.JsonElement w : warnings) {
            assertTrue(r.err().contains("warning: " + w.getAsString()), "not said: " + w.getAsString() + "\n" + r.err());
        }
    }

    @Test
    void aFieldOfViewTooWideToRenderNamesWhereItCameFrom() throws IOException {
        // FocalLengthIn35mmFilm 1 or 2 mm (a fisheye's or a broken EXIF's) gives a view no perspective render holds:
        // the error says so and names the tag and the flags that set the field of view instead.
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        for (int mm : new int[] {1, 2}) {
            Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).focal35(mm).write(tmp, "wide" + mm + ".jpg", 64, 48);
            for (boolean poseGiven : new boolean[] {true, false}) { // rendered at once, or estimated first
                java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("photo", jpg.toString(),
                        "--dem-dir", dem.toString(), "--out", tmp.resolve("w" + mm).toString(), "--range-km", "20"));
                if (poseGiven) {
                    args.addAll(java.util.List.of("--heading-deg", "10", "--pitch-deg", "0", "--roll-deg", "0"));
                }
                Run r = run(args.toArray(String[]::new));
                assertTrue(r.exit() != 0, r.err());
                String error = r.err().substring(r.err().lastIndexOf("dempano: "));
                assertTrue(error.startsWith("dempano: field of view too wide for perspective views")
                        && error.contains("EXIF FocalLengthIn35mmFilm " + mm + " mm")
                        && error.contains(PhotoOverrides.HFOV), r.err());
                assertFalse(r.err().contains("\tat "), r.err());
                assertTrue(Files.notExists(tmp.resolve("w" + mm + ".png")));
            }
        }
    }

    /**
     * An uncompressed RGB TIFF of {@code w} × {@code h} pixels (a sky-blue upper half, green below) whose EXIF sub-IFD
     * keeps another size, as a resized camera file does: PixelX/YDimension {@code exifW} × {@code exifH}.
     */
    static Path tiffWithStaleExifSize(Path file, int w, int h, int exifW, int exifH) throws IOException {
        int ifd0 = 8, entries0 = 10, bits = ifd0 + 2 + entries0 * 12 + 4, exifIfd = bits + 6, pixels = exifIfd + 2 + 2 * 12 + 4;
        ByteBuffer b = ByteBuffer.allocate(pixels + w * h * 3).order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt(ifd0);
        b.putShort((short) entries0);
        int[][] tags = { // tag, type (3 SHORT, 4 LONG), count, value or offset
            {256, 3, 1, w}, {257, 3, 1, h}, {258, 3, 3, bits}, {259, 3, 1, 1}, {262, 3, 1, 2}, {273, 4, 1, pixels},
            {277, 3, 1, 3}, {278, 3, 1, h}, {279, 4, 1, w * h * 3}, {34665, 4, 1, exifIfd}};
        for (int[] t : tags) {
            b.putShort((short) t[0]).putShort((short) t[1]).putInt(t[2]);
            if (t[1] == 3 && t[2] == 1) {
                b.putShort((short) t[3]).putShort((short) 0);
            } else {
                b.putInt(t[3]);
            }
        }
        b.putInt(0);
        b.putShort((short) 8).putShort((short) 8).putShort((short) 8);
        b.putShort((short) 2);
        b.putShort((short) 40962).putShort((short) 4).putInt(1).putInt(exifW);
        b.putShort((short) 40963).putShort((short) 4).putInt(1).putInt(exifH);
        b.putInt(0);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean sky = y < h / 2;
                b.put((byte) (sky ? 120 : 40)).put((byte) (sky ? 170 : 110)).put((byte) (sky ? 230 : 40));
            }
        }
        return Files.write(file, b.array());
    }

    @Test
    void aTiffWhoseExifKeepsAnotherSizeIsRenderedAtItsPixelsSizeAndSaysSo() throws IOException {
        // A TIFF resized from 1200 × 800 stopped with "the photo is 64×48 pixels as displayed, the camera's image
        // 1200×800", naming neither the file nor the tag.
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path tif = tiffWithStaleExifSize(tmp.resolve("resized.tif"), 64, 48, 1200, 800);
        assertEquals(64, ImageIO.read(tif.toFile()).getWidth(), "the JDK decodes the hand-made TIFF");
        String prefix = tmp.resolve("tif").toString();
        Run r = run("photo", tif.toString(), "--dem-dir", dem.toString(), "--out", prefix, "--range-km", "20", "--lat",
                "46.5", "--lon", "8.5", "--heading-deg", "200", "--pitch-deg", "-2", "--roll-deg", "0", "--hfov-deg", "50");
        assertEquals(0, r.exit(), r.err());
        checkOutputs(prefix, 64, 48);
        assertTrue(r.err().contains("the file's tags give 1200 × 800 px (as displayed) but its pixels are 64 × 48: the"
                + " pixels' size is used"), r.err());
    }

    @Test
    void whatIsMissingIsNamedWithItsFlag() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).focal35(35).write(tmp, "bare.jpg", 64, 48);
        Run r = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("x").toString());
        assertEquals(2, r.exit(), r.err());
        assertTrue(r.err().contains(PhotoOverrides.HEADING) && r.err().contains(PhotoOverrides.PITCH)
                && r.err().contains(PhotoOverrides.ROLL), r.err());
        Run noSize = run("photo", "--dem-dir", dem.toString(), "--lat", "46.5", "--lon", "8.5");
        assertEquals(2, noSize.exit(), noSize.err());
        assertTrue(noSize.err().contains("--width-px"), noSize.err());
        assertTrue(Files.notExists(tmp.resolve("x.png")));
    }

    @Test
    void cameraFlagsOutOfRangeOrNotANumberAreClearErrorsNotEstimates() throws IOException {
        Path dem = Files.createDirectories(tmp.resolve("dem"));
        tile(dem, 46, 8);
        Path jpg = new ExifJpeg().orientation(1).position(46.5, 8.5).write(tmp, "plain.jpg", 64, 48);
        String[][] cases = {
            {"--hfov-deg", "0", "horizontal field of view must be in"},
            {"--hfov-deg", "NaN", "--hfov-deg must be a finite number"},
            {"--heading-deg", "NaN", "--heading-deg must be a finite number"},
            {"--altitude-m", "Infinity", "--altitude-m must be a finite number"},
            {"--focal35-mm", "-5", "35 mm-equivalent focal length must be positive"},
            {"--heading-range-deg", "-3", "--heading-range-deg must be in"},
            {"--hfov-range-deg", "60,40", "--hfov-range-deg must be MIN,MAX with 0 < MIN ≤ MAX < 180"},
            {"--hfov-range-deg", "40", "--hfov-range-deg must be MIN,MAX (two finite numbers)"},
            {"--hfov-range-deg", "40,NaN", "--hfov-range-deg must be MIN,MAX (two finite numbers)"},
            {"--focal35-range-mm", "0,70", "--focal35-range-mm must be MIN,MAX with 0 < MIN"},
            {"--heading-deg", "1e308", "--heading-deg must be within ±360 degrees"},
            {"--roll-deg", "181", "--roll-deg must be within ±180 degrees"},
            {"--pitch-deg", "-91", "--pitch-deg must be within ±90 degrees"},
            {"--declination-deg", "200", "--declination-deg must be within ±180 degrees"},
        };
        for (String[] c : cases) {
            Run r = run("photo", jpg.toString(), "--dem-dir", dem.toString(), "--out", tmp.resolve("y").toString(), c[0], c[1]);
            String what = String.join(" ", c) + ": " + r.err();
            assertEquals(2, r.exit(), what);
            assertTrue(r.err().contains(c[2]), what);
            assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), what);
        }
        assertTrue(Files.notExists(tmp.resolve("y.png")));
    }
}
