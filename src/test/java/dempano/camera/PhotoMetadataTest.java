package dempano.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * EXIF/XMP reading on JPEGs written at test time by {@link ExifJpeg} with known tags, and the merge with the
 * user's overrides.
 */
class PhotoMetadataTest {
    /** A phone photo: 46.5° N 8.25° E, 1234.56 m, facing 123.45° true, 4.25 mm lens, 26 mm equivalent. */
    static ExifJpeg phone() {
        return new ExifJpeg().orientation(1).position(46.5, 8.25).altitude(0, 123456).direction("T", 12345)
                .focal(425).focal35(26);
    }

    static PhotoOverrides level() {
        return PhotoOverrides.NONE.withPitchDeg(0).withRollDeg(0);
    }

    @Test
    void phoneExifIsReadBack(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(phone().write(dir, "phone.jpg", 400, 300));
        assertEquals(400, m.widthPx());
        assertEquals(300, m.heightPx());
        assertEquals(1, m.orientation());
        assertEquals(46.5, m.latDeg(), 1e-7);
        assertEquals(8.25, m.lonDeg(), 1e-7);
        assertEquals(1234.56, m.gpsAltitudeMetres(), 1e-9);
        assertEquals(123.45, m.imageDirectionDeg(), 1e-9);
        assertEquals(DirectionReference.TRUE, m.imageDirectionReference());
        assertEquals(4.25, m.focalLengthMm(), 1e-12);
        assertEquals(26, m.focal35mmMm());
        assertTrue(Double.isNaN(m.sensorWidthMm()));
        assertTrue(Double.isNaN(m.xmpYawDeg()));
        assertNull(m.xmpAttitudeSource());
        assertEquals(List.of(), m.problems());
        assertTrue(m.source().endsWith("phone.jpg"));

        // Pitch and roll are never in a phone's EXIF: they are missing, with their flags.
        List<String> missing = m.missing(PhotoOverrides.NONE);
        assertEquals(2, missing.size(), missing.toString());
        assertTrue(missing.get(0).contains("--pitch-deg"), missing.toString());
        assertTrue(missing.get(1).contains("--roll-deg"), missing.toString());
        PhotoMetadataException e = assertThrows(PhotoMetadataException.class, () -> m.resolve(PhotoOverrides.NONE));
        assertTrue(e.getMessage().startsWith(m.source()) && e.getMessage().contains("--pitch-deg"), e.getMessage());

        PhotoCamera cam = m.resolve(level());
        assertEquals(26 * 500 / Math.hypot(36, 24), cam.intrinsics().fxPx(), 1e-9);
        assertEquals(199.5, cam.intrinsics().cxPx());
        assertEquals(46.5, cam.pose().latDeg(), 1e-7);
        assertEquals(1234.56, cam.pose().altitudeMetres(), 1e-9);
        assertEquals(0, cam.pose().cameraHeightMetres(), "a GPS altitude is the camera's own");
        assertEquals(123.45, cam.pose().orientation().headingDeg(), 1e-9);
        assertTrue(cam.provenance().stream().anyMatch(s -> s.contains("FocalLengthIn35mmFilm")), cam.provenance().toString());
        // The view points where the EXIF says.
        double[] axis = cam.view().rayOf(199.5, 149.5);
        assertEquals(123.45, Math.toDegrees(Math.atan2(axis[0], axis[1])), 1e-9);
    }

    @Test
    void southernWesternAndBelowSeaLevel(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(new ExifJpeg().position(-33.875, -70.5).altitude(1, 41250)
                .write(dir, "dead-sea.jpg", 64, 48));
        assertEquals(-33.875, m.latDeg(), 1e-7);
        assertEquals(-70.5, m.lonDeg(), 1e-7);
        assertEquals(-412.5, m.gpsAltitudeMetres(), 1e-9);
        assertTrue(Double.isNaN(m.imageDirectionDeg()));
        assertEquals(DirectionReference.NOT_GIVEN, m.imageDirectionReference());
    }

    @Test
    void aPhotoWithoutMetadataSaysWhatToGive(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(new ExifJpeg().write(dir, "bare.jpg", 120, 80));
        assertEquals(120, m.widthPx());
        assertEquals(80, m.heightPx());
        assertEquals(0, m.orientation());
        for (double v : new double[] {m.latDeg(), m.lonDeg(), m.gpsAltitudeMetres(), m.imageDirectionDeg(),
                m.focalLengthMm(), m.focal35mmMm(), m.sensorWidthMm(), m.xmpPitchDeg()}) {
            assertTrue(Double.isNaN(v));
        }
        List<String> missing = m.missing(PhotoOverrides.NONE);
        String all = String.join("\n", missing);
        assertEquals(5, missing.size(), all);
        for (String flag : new String[] {"--lat", "--lon", "--heading-deg", "--pitch-deg", "--roll-deg", "--focal-mm",
                "--sensor-width-mm", "--focal35-mm", "--hfov-deg"}) {
            assertTrue(all.contains(flag), flag + " in\n" + all);
        }
        assertTrue(all.contains("no focal length in the EXIF"), all);
        // Everything given by flags: resolves, standing on the DEM with the default eye height.
        PhotoCamera cam = m.resolve(level().withPosition(46, 8).withHeadingDeg(270).withHorizontalFovDeg(60));
        assertEquals(60, cam.intrinsics().horizontalFovDeg(), 1e-12);
        assertFalse(cam.pose().absoluteAltitude());
        assertEquals(0, cam.pose().offsetMetres());
        assertEquals(2, cam.pose().cameraHeightMetres());
        assertEquals(270, cam.pose().orientation().headingDeg());
    }

    @Test
    void magneticDirectionIsNeverTakenAsTrue(@TempDir Path dir) throws Exception {
        PhotoMetadata magnetic = PhotoMetadata.read(new ExifJpeg().position(46.5, 8.25).direction("M", 9000)
                .focal35(26).write(dir, "magnetic2.jpg", 40, 30));
        assertEquals(DirectionReference.MAGNETIC, magnetic.imageDirectionReference());
        assertEquals(90, magnetic.imageDirectionDeg(), 1e-12);
        List<String> missing = magnetic.missing(level());
        assertEquals(1, missing.size(), missing.toString());
        assertTrue(missing.get(0).contains("magnetic") && missing.get(0).contains("--declination-deg")
                && missing.get(0).contains("--heading-deg"), missing.get(0));
        PhotoCamera cam = magnetic.resolve(level().withDeclinationDeg(2.5));
        assertEquals(92.5, cam.pose().orientation().headingDeg(), 1e-12, "true = magnetic + declination (east +)");
        assertEquals(87, magnetic.resolve(level().withDeclinationDeg(-3)).pose().orientation().headingDeg(), 1e-12);
        // A heading flag needs no declination.
        assertEquals(10, magnetic.resolve(level().withHeadingDeg(10)).pose().orientation().headingDeg());
        // No reference at all: also not taken as true.
        PhotoMetadata noRef = PhotoMetadata.read(new ExifJpeg().position(46.5, 8.25).direction(null, 9000)
                .focal35(26).write(dir, "noref.jpg", 40, 30));
        assertEquals(DirectionReference.NOT_GIVEN, noRef.imageDirectionReference());
        assertTrue(noRef.missing(level()).get(0).contains("no reference"), noRef.missing(level()).toString());
        assertEquals(90, noRef.resolve(level().withDeclinationDeg(0)).pose().orientation().headingDeg(), 1e-12);
        // A true direction ignores the declination (and says so).
        PhotoCamera trueCam = PhotoMetadata.read(phone().write(dir, "true.jpg", 40, 30))
                .resolve(level().withDeclinationDeg(5));
        assertEquals(123.45, trueCam.pose().orientation().headingDeg(), 1e-9);
        assertTrue(trueCam.provenance().stream().anyMatch(s -> s.contains("not used")), trueCam.provenance().toString());
    }

    @Test
    void orientationSixSwapsWidthAndHeight(@TempDir Path dir) throws Exception {
        // Stored 400 × 300 (landscape), displayed turned 90° clockwise: 300 × 400.
        PhotoMetadata m = PhotoMetadata.read(phone().orientation(6).write(dir, "portrait.jpg", 400, 300));
        assertEquals(6, m.orientation());
        assertTrue(m.quarterTurn());
        assertEquals(300, m.widthPx());
        assertEquals(400, m.heightPx());
        PhotoCamera cam = m.resolve(level().withHorizontalFovDeg(50));
        assertEquals(300, cam.intrinsics().widthPx());
        assertEquals(149.5, cam.intrinsics().cxPx());
        assertEquals(199.5, cam.intrinsics().cyPx());
        assertEquals(150 / Math.tan(Math.toRadians(25)), cam.intrinsics().fxPx(), 1e-9, "hfov across the displayed width");
        assertTrue(cam.provenance().stream().anyMatch(s -> s.contains("orientation 6")), cam.provenance().toString());
        // A calibration of the stored frames (400 × 300) does not fit the displayed photo.
        PhotoMetadataException e = assertThrows(PhotoMetadataException.class,
                () -> m.resolve(level().withCalibration(CameraIntrinsics.pinhole(400, 300, 350))));
        assertTrue(e.getMessage().contains("400 × 300") && e.getMessage().contains("300 × 400"), e.getMessage());
        // One for the displayed size is used as it is.
        CameraIntrinsics calibration = new CameraIntrinsics(300, 400, 351, 352, 150.2, 198.7,
                new LensDistortion(-0.1, 0.01, 0, 0, 0));
        assertEquals(calibration, m.resolve(level().withCalibration(calibration)).intrinsics());
        // Orientation 8 (turned counter-clockwise) swaps too; 3 (upside down) does not.
        assertEquals(300, PhotoMetadata.read(phone().orientation(8).write(dir, "o8.jpg", 400, 300)).widthPx());
        assertEquals(400, PhotoMetadata.read(phone().orientation(3).write(dir, "o3.jpg", 400, 300)).widthPx());
    }

    @Test
    void droneGimbalAnglesComeFromXmp(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(new ExifJpeg().position(46.5, 8.25).altitude(0, 250000).focal35(24)
                .xmp("drone-dji:GimbalYawDegree=\"+45.30\" drone-dji:GimbalPitchDegree=\"-12.50\""
                        + " drone-dji:GimbalRollDegree=\"+0.20\" drone-dji:FlightYawDegree=\"+40.00\"")
                .write(dir, "dji.jpg", 80, 60));
        assertEquals(45.3, m.xmpYawDeg(), 1e-12);
        assertEquals(-12.5, m.xmpPitchDeg(), 1e-12);
        assertEquals(0.2, m.xmpRollDeg(), 1e-12);
        assertTrue(m.xmpAttitudeSource().startsWith("drone-dji"), m.xmpAttitudeSource());
        assertEquals(List.of(), m.missing(PhotoOverrides.NONE));
        PhotoCamera cam = m.resolve(PhotoOverrides.NONE);
        assertEquals(new CameraOrientation(45.3, -12.5, 0.2), cam.pose().orientation());
        // Flags win over XMP.
        assertEquals(-30, m.resolve(PhotoOverrides.NONE.withPitchDeg(-30)).pose().orientation().pitchDeg());
        // GPano pose when there are no DJI angles.
        PhotoMetadata gpano = PhotoMetadata.read(new ExifJpeg()
                .xmp("GPano:PoseHeadingDegrees=\"350.5\" GPano:PosePitchDegrees=\"3.25\"")
                .write(dir, "gpano.jpg", 80, 60));
        assertEquals(350.5, gpano.xmpYawDeg(), 1e-12);
        assertEquals(3.25, gpano.xmpPitchDeg(), 1e-12);
        assertTrue(Double.isNaN(gpano.xmpRollDeg()));
        assertTrue(gpano.xmpAttitudeSource().startsWith("GPano"));
        assertTrue(gpano.missing(PhotoOverrides.NONE).stream().anyMatch(s -> s.contains("--roll-deg")));
        // A malformed number is reported, not guessed.
        PhotoMetadata bad = PhotoMetadata.read(new ExifJpeg().xmp("drone-dji:GimbalPitchDegree=\"minus ten\"")
                .write(dir, "bad-xmp.jpg", 80, 60));
        assertTrue(Double.isNaN(bad.xmpPitchDeg()));
        assertTrue(bad.problems().stream().anyMatch(s -> s.contains("minus ten")), bad.problems().toString());
        // A long value with a line break: one line, cut to 40 characters and its length.
        PhotoMetadata longValue = PhotoMetadata.read(new ExifJpeg().xmp("drone-dji:GimbalPitchDegree=\"1&#10;" + "x".repeat(5000)
                + "\"").write(dir, "long-xmp.jpg", 80, 60));
        assertEquals(List.of("XMP GimbalPitchDegree \"1?" + "x".repeat(38) + "… (5002 characters)\" is not a number"),
                longValue.problems());
        // Beyond a turn (pitch ±90°, roll ±180°), or not a plain decimal: not used, and said.
        PhotoMetadata huge = PhotoMetadata.read(new ExifJpeg().xmp("drone-dji:GimbalYawDegree=\"1e308\""
                + " drone-dji:GimbalPitchDegree=\"0x1p6\" drone-dji:GimbalRollDegree=\"-180\"").write(dir, "huge.jpg", 80, 60));
        assertTrue(Double.isNaN(huge.xmpYawDeg()) && Double.isNaN(huge.xmpPitchDeg()), huge.toString());
        assertEquals(-180, huge.xmpRollDeg(), 0);
        assertTrue(huge.problems().stream().anyMatch(s -> s.contains("GimbalYawDegree \"1e308\" is beyond ±360°")),
                huge.problems().toString());
        assertTrue(huge.problems().stream().anyMatch(s -> s.contains("0x1p6") && s.contains("is not a number")),
                huge.problems().toString());
    }

    @Test
    void aGpsAltitudeBelowTheDemSurfaceIsNotUsed(@TempDir Path dir) throws Exception {
        // The phone's GPS altitude is 1234.56 m (the camera's own, height 0). Rows: DEM surface there, camera height
        // given (NaN: none), altitude flag, whether the camera then stands on the DEM.
        PhotoMetadata m = PhotoMetadata.read(phone().write(dir, "phone.jpg", 400, 300));
        double tolerance = -dempano.geo.Viewpoint.MIN_EYE_CLEARANCE_METRES; // the camera must be that much above it
        Object[][] cases = {
            {Double.NaN, Double.NaN, Double.NaN, false},            // the surface not known: no check
            {1200.0, Double.NaN, Double.NaN, false},                // 34.56 m above the surface
            {1234.56 + tolerance - 0.001, Double.NaN, Double.NaN, false}, // just high enough above it
            {1234.56 + tolerance + 0.01, Double.NaN, Double.NaN, true},
            {1262.0, Double.NaN, Double.NaN, true},                 // 27.44 m below: GPS altitudes err that much
            {1262.0, 30.0, Double.NaN, false},                      // a camera 30 m up (a mast, a building) is above it
            {1262.0, Double.NaN, 1000.0, false},                    // --altitude-m is the user's: not second-guessed
        };
        for (Object[] c : cases) {
            double ground = (Double) c[0], height = (Double) c[1], flag = (Double) c[2];
            PhotoOverrides o = level();
            o = Double.isNaN(height) ? o : o.withCameraHeightMetres(height);
            o = Double.isNaN(flag) ? o : o.withAltitudeMetres(flag);
            PhotoCamera cam = m.resolve(o, ground);
            String what = java.util.Arrays.toString(c) + ": " + cam.pose() + " " + cam.provenance();
            if ((Boolean) c[3]) {
                assertFalse(cam.pose().absoluteAltitude(), what);
                assertEquals(0, cam.pose().offsetMetres(), what);
                assertEquals(dempano.geo.Viewpoint.DEFAULT_EYE_HEIGHT_METRES, cam.pose().cameraHeightMetres(), what);
                assertTrue(cam.provenance().stream().anyMatch(l -> l.startsWith("camera altitude 1234.56 m from EXIF"
                        + " GPSAltitude not used: ") && l.contains(" the DEM surface (") && l.contains("--offset-m 0")),
                        what);
            } else {
                assertTrue(cam.pose().absoluteAltitude(), what);
                assertEquals(Double.isNaN(flag) ? 1234.56 : flag, cam.pose().altitudeMetres(), 1e-9, what);
            }
        }
        String line = m.resolve(level(), 1262.0).provenance().stream().filter(l -> l.contains("not used")).findFirst()
                .orElseThrow();
        assertTrue(line.contains("27.4 m below the DEM surface (1262.0 m)"), line);
    }

    @Test
    void flagsOverrideTheExif(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(phone().write(dir, "phone.jpg", 400, 300));
        PhotoCamera cam = m.resolve(level().withPosition(45, 7).withHeadingDeg(200).withFocal35mmMm(52)
                .withOffsetMetres(-3));
        assertEquals(45, cam.pose().latDeg());
        assertEquals(7, cam.pose().lonDeg());
        assertEquals(200, cam.pose().orientation().headingDeg());
        assertEquals(52 * 500 / Math.hypot(36, 24), cam.intrinsics().fxPx(), 1e-9);
        assertFalse(cam.pose().absoluteAltitude(), "--offset-m stands on the DEM, not at the GPS altitude");
        assertEquals(-3, cam.pose().offsetMetres());
        assertEquals(2, cam.pose().cameraHeightMetres());
        PhotoCamera absolute = m.resolve(level().withAltitudeMetres(999).withCameraHeightMetres(1.5)
                .withDistortion(LensDistortion.radial(-0.05, 0, 0)));
        assertEquals(999, absolute.pose().altitudeMetres());
        assertEquals(1.5, absolute.pose().cameraHeightMetres());
        assertEquals(-0.05, absolute.intrinsics().distortion().k1());
        // The lens's focal length with a sensor width from a flag beats the rounded 35 mm equivalent.
        assertEquals(4.25 * 400 / 5.6, m.resolve(level().withSensorWidthMm(5.6)).intrinsics().fxPx(), 1e-9);
        // An out-of-range flag is an error naming the file.
        PhotoMetadataException e = assertThrows(PhotoMetadataException.class,
                () -> m.resolve(PhotoOverrides.NONE.withPitchDeg(95).withRollDeg(0)));
        assertTrue(e.getMessage().startsWith(m.source()) && e.getMessage().contains("pitch"), e.getMessage());
    }

    @Test
    void focalLengthNeedsASensorSize(@TempDir Path dir) throws Exception {
        // FocalLength alone: asks for a sensor width, 35 mm equivalent or field of view.
        PhotoMetadata m = PhotoMetadata.read(new ExifJpeg().focal(5000).write(dir, "focal.jpg", 400, 300));
        String missing = String.join("\n", m.missing(level().withPosition(46, 8).withHeadingDeg(0)));
        assertTrue(missing.contains("focal length (50 mm)") && missing.contains("--sensor-width-mm"), missing);
        // --focal-mm without a sensor width says what it needs.
        PhotoMetadata bare = PhotoMetadata.read(new ExifJpeg().write(dir, "bare.jpg", 400, 300));
        String needs = String.join("\n", bare.missing(level().withPosition(46, 8).withHeadingDeg(0).withFocalLengthMm(35)));
        assertTrue(needs.contains("--focal-mm needs --sensor-width-mm"), needs);
        // The focal-plane resolution gives the sensor size: 400 px over 36 mm = 282.2222 px/inch.
        PhotoMetadata fp = PhotoMetadata.read(new ExifJpeg().focal(5000).focalPlane(2822222, 10000, 2822222, 10000, 2)
                .write(dir, "plane.jpg", 400, 300));
        assertEquals(36, fp.sensorWidthMm(), 1e-4);
        PhotoCamera cam = fp.resolve(level().withPosition(46, 8).withHeadingDeg(0));
        assertEquals(50 * 400 / fp.sensorWidthMm(), cam.intrinsics().fxPx(), 1e-9);
        assertEquals(2 * Math.toDegrees(Math.atan(18 / 50.0)), cam.intrinsics().horizontalFovDeg(), 1e-3);
    }

    @Test
    void unreadableFilesGiveAPlainMessageNamingTheFile(@TempDir Path dir) throws Exception {
        Path text = dir.resolve("holiday.jpg");
        Files.writeString(text, "this is not a photograph\n");
        Path truncated = dir.resolve("truncated.jpg");
        byte[] full = phone().jpeg(400, 300);
        Files.write(truncated, Arrays.copyOf(full, 40));
        Path empty = dir.resolve("empty.jpg");
        Files.write(empty, new byte[0]);
        for (Path p : new Path[] {text, truncated, empty, dir.resolve("absent.jpg"), dir}) {
            PhotoMetadataException e = assertThrows(PhotoMetadataException.class, () -> PhotoMetadata.read(p));
            String msg = e.getMessage();
            assertTrue(msg.startsWith(p.toString() + ": "), msg);
            assertFalse(msg.contains("Exception") || msg.contains("\tat ") || msg.contains("com.drew"), msg);
        }
        assertTrue(assertThrows(PhotoMetadataException.class, () -> PhotoMetadata.read(dir.resolve("absent.jpg")))
                .getMessage().contains("no such file"));
    }

    /** {degrees, minutes, seconds as n/d pairs ("n/d n/d n/d"), reference, expected degrees or NaN, problem or ""}. */
    static final String[][] GPS_DMS = {
        {"46/1 30/1 0/1", "N", "46.5", ""},
        {"46/1 30/1 0/1", "S", "-46.5", ""},
        {"8/1 15/1 36/1", "E", "8.26", ""},
        {"8/1 15/1 36/1", "W", "-8.26", ""},
        {"4650/100 0/1 0/1", "N", "46.5", ""},
        {"0/0 0/0 0/0", "N", "NaN", "has a zero denominator"},
        {"44/0 0/1 0/1", "N", "NaN", "has a zero denominator"},
        {"44/1 99/1 0/1", "N", "NaN", "minutes < 60"},
        {"44/1 0/1 60/1", "N", "NaN", "seconds < 60"},
        {"-44/1 0/1 0/1", "N", "NaN", "minutes < 60"},
        {"95/1 0/1 0/1", "N", "NaN", "beyond 90°"},
        {"46/1 30/1 0/1", "X", "NaN", "is neither N nor S"},
        {"46/1 30/1 0/1", null, "NaN", "is neither N nor S"},
    };

    @Test
    void gpsDegreesMinutesSecondsAreReadStrictly() {
        for (String[] row : GPS_DMS) {
            com.drew.lang.Rational[] dms = Arrays.stream(row[0].split(" ")).map(t -> t.split("/"))
                    .map(nd -> new com.drew.lang.Rational(Long.parseLong(nd[0]), Long.parseLong(nd[1])))
                    .toArray(com.drew.lang.Rational[]::new);
            boolean lat = row[1] == null || "NSX".contains(row[1]);
            List<String> problems = new java.util.ArrayList<>();
            double v = PhotoMetadata.degrees(dms, row[1], lat ? "GPSLatitude" : "GPSLongitude", lat ? 'N' : 'E',
                    lat ? 'S' : 'W', lat ? 90 : 180, problems);
            String what = Arrays.toString(row) + " → " + v + " " + problems;
            assertEquals(Double.parseDouble(row[2]), v, 1e-12, what);
            assertEquals(row[3].isEmpty(), problems.isEmpty(), what);
            assertTrue(problems.stream().allMatch(p -> p.contains(row[3])), what);
        }
        // Absent: NaN, nothing said.
        List<String> none = new java.util.ArrayList<>();
        assertTrue(Double.isNaN(PhotoMetadata.degrees(null, null, "GPSLatitude", 'N', 'S', 90, none)) && none.isEmpty());
    }

    @Test
    void gifBmpAndTiffPhotosHaveTheirSize(@TempDir Path dir) throws Exception {
        // Formats without EXIF (before: "corrupt or unsupported photograph: no image size found").
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(123, 45, java.awt.image.BufferedImage.TYPE_INT_RGB);
        for (String format : new String[] {"gif", "bmp", "tiff"}) {
            Path f = dir.resolve("p." + format);
            assertTrue(javax.imageio.ImageIO.write(img, format, f.toFile()), format);
            PhotoMetadata m = PhotoMetadata.read(f);
            assertEquals(123, m.widthPx(), format);
            assertEquals(45, m.heightPx(), format);
        }
    }

    @Test
    void aFocalLengthBeyondAnyLensIsNotUsed(@TempDir Path dir) throws Exception {
        PhotoMetadata unknown = PhotoMetadata.read(new ExifJpeg().orientation(1).focal35(65535).write(dir, "f.jpg", 80, 60));
        assertTrue(Double.isNaN(unknown.focal35mmMm()), unknown.toString());
        assertTrue(unknown.problems().stream().anyMatch(p -> p.contains("FocalLengthIn35mmFilm 65535 mm is beyond any lens")),
                unknown.problems().toString());
        PhotoMetadata superzoom = PhotoMetadata.read(new ExifJpeg().orientation(1).focal35(3000).write(dir, "z.jpg", 80, 60));
        assertEquals(3000, superzoom.focal35mmMm(), 0);
    }

    /** Values no camera writes (placeholders for "unknown", garbage) are said and not used, instead of aborting or misleading. */
    @Test
    void valuesBeyondAnyCameraAreSaidAndNotUsed(@TempDir Path dir) throws Exception {
        PhotoMetadata m = PhotoMetadata.read(new ExifJpeg().orientation(1).position(46.5, 8.25).altitude(7, 4294967295L)
                .direction("T", 40_000).focal(4294967295L).focalPlane(1, 1_000_000, 1, 1_000_000, 4)
                .write(dir, "garbage.jpg", 80, 60));
        String problems = m.problems().toString();
        assertTrue(Double.isNaN(m.gpsAltitudeMetres()), m.toString());
        assertTrue(Double.isNaN(m.imageDirectionDeg()), m.toString());
        assertTrue(Double.isNaN(m.focalLengthMm()), m.toString());
        assertTrue(Double.isNaN(m.sensorWidthMm()), m.toString());
        for (String said : List.of("GPSAltitudeRef 7 is neither 0", "GPSAltitude 42949673 m is beyond 100 km",
                "GPSImgDirection 400° is outside 0–360°", "FocalLength 42949672.95 mm is beyond any lens (5000 mm)",
                "sensor 80000000 mm wide")) {
            assertTrue(problems.contains(said), said + " in " + problems);
        }
        assertEquals(46.5, m.latDeg(), 1e-7, "the rest is read");
    }

    /** A named pipe is refused at once (reading it waited for ever, and stalled a batch). */
    @Test
    void aPipeIsNotAPhotograph(@TempDir Path dir) throws Exception {
        Path fifo = dir.resolve("fifo.jpg");
        org.junit.jupiter.api.Assumptions.assumeTrue(new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0,
                "mkfifo is not available");
        PhotoMetadataException e = assertThrows(PhotoMetadataException.class, () -> PhotoMetadata.read(fifo));
        assertTrue(e.getMessage().equals(fifo + ": is not a regular file (a pipe or a device), not a photograph"), e.getMessage());
    }

    /** Tags present but unusable (a zero denominator, a zero focal length) are named as problems, not taken for absent. */
    @Test
    void unusableLensAndAltitudeTagsAreNamedNotSilentlyDropped(@TempDir Path dir) throws Exception {
        String[][] cases = {
            {"alt-0den", "GPSAltitude 1950/0 has a zero denominator"},
            {"dir-0den", "GPSImgDirection 3000/0 has a zero denominator"},
            {"focal-0den", "FocalLength 50/0 has a zero denominator"},
            {"focal-0", "FocalLength 0 mm is not positive"},
            {"focal35-0", "FocalLengthIn35mmFilm 0 (unknown, by the standard)"},
        };
        for (String[] c : cases) {
            ExifJpeg j = new ExifJpeg().position(46.5, 8.5);
            j = switch (c[0]) {
                case "alt-0den" -> j.altitudeRational(0, 1950, 0);
                case "dir-0den" -> j.directionRational("T", 3000, 0);
                case "focal-0den" -> j.focalRational(50, 0);
                case "focal-0" -> j.focalRational(0, 1);
                default -> j.focal35(0);
            };
            PhotoMetadata m = PhotoMetadata.read(j.write(dir, c[0] + ".jpg", 40, 30));
            assertTrue(m.problems().stream().anyMatch(l -> l.contains(c[1])), c[0] + ": " + m.problems());
        }
    }
}
