package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraPose;
import dempano.camera.DirectionReference;
import dempano.camera.PhotoCamera;
import dempano.camera.PhotoMetadata;
import dempano.camera.PhotoOverrides;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * How the photo command carries an estimate through the overrides: which values get placeholders, what the camera
 * becomes, and what its provenance says.
 */
class PhotoOrientationOverridesTest {
    static final double N = Double.NaN;

    /** A 480 × 320 photo with a GPS position, and optionally a true heading, a GPS altitude, a 35 mm focal length. */
    static PhotoMetadata meta(double headingDeg, double gpsAltitudeMetres, double focal35mm) {
        return new PhotoMetadata("test.jpg", 480, 320, 1, new PhotoMetadata.Gps(46.43, 8.09, gpsAltitudeMetres, headingDeg,
                Double.isNaN(headingDeg) ? DirectionReference.NOT_GIVEN : DirectionReference.TRUE),
                new PhotoMetadata.Lens(N, focal35mm, N), PhotoMetadata.XmpAttitude.NONE, List.of());
    }

    static OrientationEstimate estimate(double heading, double pitch, double roll, double hfov, double offsetMetres) {
        return new OrientationEstimate(heading, pitch, roll, hfov, 0.3, 1, 0.05, N, null, 0.3, false, 300, 1,
                offsetMetres, Double.isNaN(offsetMetres) ? N : 1);
    }

    @Test
    void aHeadingPriorIsCentredOnTheMetadatasHeadingNotOnAPlaceholder() {
        PhotoMetadata m = meta(87.5, N, 35);
        PhotoOrientation open = PhotoOrientation.open(m, PhotoOverrides.NONE, true);
        assertTrue(open.heading() && open.pitch() && open.roll(), open.toString());
        assertFalse(open.hfov(), "the focal length is in the EXIF");
        PhotoCamera c = m.resolve(open.placeholders(m, PhotoOverrides.NONE));
        assertEquals(87.5, c.pose().orientation().headingDeg(), 0);
        // Without a heading in the metadata the placeholder fills it, and the heading is searched all round.
        PhotoMetadata bare = meta(N, N, 35);
        PhotoOrientation open2 = PhotoOrientation.open(bare, PhotoOverrides.NONE, false);
        assertEquals(0, bare.resolve(open2.placeholders(bare, PhotoOverrides.NONE)).pose().orientation().headingDeg(), 0);
    }

    @Test
    void estimatedValuesSaySoInTheProvenanceAndNamesNoFlag() {
        PhotoMetadata m = meta(N, N, N);
        PhotoOrientation open = PhotoOrientation.open(m, PhotoOverrides.NONE, false);
        assertTrue(open.heading() && open.pitch() && open.roll() && open.hfov() && open.altitude(), open.toString());
        PhotoCamera placeholder = m.resolve(open.placeholders(m, PhotoOverrides.NONE));
        OrientationEstimate e = estimate(235.5, 1.25, -4, 60, 12.5);
        PhotoOverrides applied = open.apply(PhotoOverrides.NONE, e, placeholder.pose());
        PhotoCamera c = m.resolve(applied, Double.NaN, open.estimatedFlags(PhotoOverrides.NONE, e));
        List<String> lines = c.provenance();
        String all = String.join("\n", lines);
        for (String flag : new String[] {PhotoOverrides.HEADING, PhotoOverrides.PITCH, PhotoOverrides.ROLL,
            PhotoOverrides.HFOV, PhotoOverrides.OFFSET}) {
            assertFalse(all.contains(flag), flag + " named in\n" + all);
        }
        assertTrue(lines.contains("heading 235.5° " + PhotoMetadata.ESTIMATED), all);
        assertTrue(lines.contains("pitch 1.25° " + PhotoMetadata.ESTIMATED), all);
        assertTrue(lines.contains("roll -4° " + PhotoMetadata.ESTIMATED), all);
        assertTrue(lines.contains("standing on the DEM corrected by 12.5 m (" + PhotoMetadata.ESTIMATED + ")"), all);
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("focal length ") && l.contains("field of view of 60°")
                && l.endsWith(PhotoMetadata.ESTIMATED)), all);
        assertEquals(12.5, c.pose().offsetMetres(), 0);
        // Before the estimate the placeholders are the lines that naming them changes (the job leaves them out of its log).
        List<String> before = m.resolve(open.placeholders(m, PhotoOverrides.NONE), Double.NaN,
                open.estimatedFlags(PhotoOverrides.NONE, null)).provenance();
        assertEquals(placeholder.provenance().size(), before.size());
        long changed = java.util.stream.IntStream.range(0, before.size())
                .filter(i -> !before.get(i).equals(placeholder.provenance().get(i))).count();
        assertEquals(4, changed, String.join("\n", before));
    }

    @Test
    void anAltitudeFromGpsMovesTheCameraItselfNotAStandingEyeTwoMetresUp() {
        // The EXIF GPS altitude is the camera's (camera height 0): the estimated offset moves it, and the camera
        // height stays 0 (a standing altitude from a flag would add the default 2 m).
        PhotoMetadata m = meta(N, 1500, 35);
        PhotoOrientation open = PhotoOrientation.open(m, PhotoOverrides.NONE, false);
        CameraPose pose = m.resolve(open.placeholders(m, PhotoOverrides.NONE)).pose();
        assertEquals(0, pose.cameraHeightMetres(), 0);
        OrientationEstimate e = estimate(10, 0, 0, 54, -20);
        PhotoCamera c = m.resolve(open.apply(PhotoOverrides.NONE, e, pose), Double.NaN,
                open.estimatedFlags(PhotoOverrides.NONE, e));
        assertEquals(1480, c.pose().altitudeMetres() + c.pose().cameraHeightMetres(), 1e-9);
        String all = String.join("\n", c.provenance());
        assertFalse(all.contains(PhotoOverrides.ALTITUDE) || all.contains(PhotoOverrides.CAMERA_HEIGHT), all);
        assertTrue(all.contains("standing altitude 1480 m (the camera's altitude"), all);
        assertTrue(c.provenance().contains("camera 0 m above the standing altitude (the altitude is the camera's)"), all);
    }

    @Test
    void aValueTheUserGaveKeepsItsFlagBesideEstimatedOnes() {
        PhotoMetadata m = meta(N, N, 35);
        PhotoOverrides given = PhotoOverrides.NONE.withPitchDeg(2).withOffsetMetres(3);
        PhotoOrientation open = PhotoOrientation.open(m, given, false);
        assertTrue(open.heading() && !open.pitch() && open.roll() && !open.altitude(), open.toString());
        PhotoCamera placeholder = m.resolve(open.placeholders(m, given));
        OrientationEstimate e = estimate(100, 2, 1.5, 50, 7);
        PhotoCamera c = m.resolve(open.apply(given, e, placeholder.pose()), Double.NaN, open.estimatedFlags(given, e));
        String all = String.join("\n", c.provenance());
        assertTrue(c.provenance().contains("pitch 2° from " + PhotoOverrides.PITCH), all);
        assertTrue(c.provenance().contains("standing on the DEM corrected by 3 m (" + PhotoOverrides.OFFSET + ")"), all);
        assertTrue(c.provenance().contains("heading 100° " + PhotoMetadata.ESTIMATED), all);
        assertTrue(c.provenance().contains("roll 1.5° " + PhotoMetadata.ESTIMATED), all);
    }
}
