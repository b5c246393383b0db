package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Edge cases of the panorama's accessors on a small grid built from arrays: 2 pixels per degree
 * (720 columns), top edge at 3°, 8 rows (elevations (−1°, 3°]). Every pixel holds its own
 * coordinates (distance = 1000·col + row, colour = col·65536 + row), so a lookup that lands on the
 * wrong pixel shows which one.
 */
class PanoramaAccessTest {
    static final int W = 720, H = 8;
    static final PanoramaGeometry G = new PanoramaGeometry(2, 3, H);

    static Panorama panorama(boolean colour, boolean distance) {
        int[] argb = new int[W * H];
        float[] d = new float[W * H];
        for (int r = 0; r < H; r++) {
            for (int c = 0; c < W; c++) {
                argb[r * W + c] = c * 65536 + r;
                d[r * W + c] = 1000f * c + r;
            }
        }
        PanoramaMetadata m = new PanoramaMetadata(new dempano.geo.Viewpoint(46, 8, 1000, 0, 1000, 2), 100_000, 0.13, DepthMode.SHADER_RANGE,
                1, 100_000, 8, 100, 100, List.of(), List.of(), List.of(), Map.of(), "test", 0, 0, null, List.of());
        return new Panorama(G, colour ? argb : null, distance ? d : null, Map.of(), m);
    }

    static final Panorama P = panorama(true, true);

    /** Direction → the pixel whose [left, right) × (bottom, top] cell contains it, worked out by hand from the grid rule. */
    @ParameterizedTest(name = "az {0}, el {1} -> column {2}, row {3}")
    @CsvSource({
            "0, 3, 0, 0",              // top edge belongs to row 0
            "0.4999, 2.5001, 0, 0",
            "0.5, 2.5, 1, 1",          // column 1 starts at 0.5°; row 1's top edge is 2.5°
            "45.25, 0, 90, 6",
            "359.9, 0, 719, 6",
            "-0.1, 0, 719, 6",         // wrapped: −0.1° is 359.9°
            "360, 0, 0, 6",
            "720.25, 0, 0, 6",
            "-360.5, 0, 719, 6",       // 359.5°
            "-90, -0.999, 540, 7",     // 270°, just above the bottom edge
            "1e10, 1, 560, 4",         // 10^10 mod 360 = 280 (10^10 − 27777777·360)
    })
    void directionsFindTheirPixel(double az, double el, int col, int row) {
        assertEquals(1000.0 * col + row, P.distanceAt(az, el));
        assertEquals(1000.0 * col + row, P.distanceMetres(col, row));
        assertEquals(col * 65536 + row, P.argb(col, row));
    }

    @ParameterizedTest(name = "az {0}, el {1} -> NaN")
    @CsvSource({
            "NaN, 0", "Infinity, 0", "-Infinity, 0", "0, NaN", "0, Infinity", "0, -Infinity", "NaN, NaN",
            "0, -1",        // the bottom edge belongs to no row
            "0, 3.0001", "0, -1.5", "0, 90", "0, -90", "10, 1e300"})
    void outsideTheDomainIsNaN(double az, double el) {
        assertTrue(Double.isNaN(P.distanceAt(az, el)), "got " + P.distanceAt(az, el));
    }

    @ParameterizedTest(name = "({0}, {1})")
    @CsvSource({
            "-1, 0, column -1, 0…719", "720, 0, column 720, 0…719", "720, 7, column 720, 0…719",
            "-2147483648, 0, column -2147483648, 0…719", "0, -1, row -1, 0…7", "0, 8, row 8, 0…7",
            "719, 2147483647, row 2147483647, 0…7"})
    void pixelsOutsideTheImageAreRefusedByName(int col, int row, String named, String range) {
        for (Runnable access : List.<Runnable>of(() -> P.distanceMetres(col, row), () -> P.argb(col, row))) {
            IndexOutOfBoundsException e = assertThrows(IndexOutOfBoundsException.class, access::run);
            assertTrue(e.getMessage().contains(named) && e.getMessage().contains(range), e.getMessage());
        }
    }

    @Test
    void theCornersAreInside() {
        assertEquals(0f, P.distanceMetres(0, 0));
        assertEquals(1000f * 719 + 7, P.distanceMetres(W - 1, H - 1));
        assertEquals(719 * 65536 + 7, P.argb(W - 1, H - 1));
    }

    @Test
    void missingPicturesAreStillIllegalState() {
        Panorama colourOnly = panorama(true, false), distanceOnly = panorama(false, true);
        assertThrows(IllegalStateException.class, () -> colourOnly.distanceMetres(0, 0));
        assertThrows(IllegalStateException.class, () -> colourOnly.distanceAt(Double.NaN, 0));
        assertThrows(IllegalStateException.class, () -> distanceOnly.argb(0, 0));
        assertEquals(5 * 65536 + 1, colourOnly.argb(5, 1));
        assertEquals(5001.0, distanceOnly.distanceAt(2.75, 2.25));
    }

    @Test
    void angleConversionsExtrapolateOutsideTheImage() {
        assertEquals(0.25, P.azimuthOfColumn(0), 1e-12);
        assertEquals(-0.25, P.azimuthOfColumn(-1), 1e-12);
        assertEquals(360.25, P.azimuthOfColumn(W), 1e-12);
        assertEquals(3.25, P.elevationOfRow(-1), 1e-12);
        assertEquals(-0.75, P.elevationOfRow(H - 1), 1e-12);
    }
    /** The metadata's lists and maps cannot be changed through its accessors, nor through the caller's lists it was made from. */
    @org.junit.jupiter.api.Test
    void metadataListsAndMapsAreImmutableCopies() {
        java.util.List<String> warnings = new java.util.ArrayList<>(List.of("a warning"));
        java.util.Map<String, Double> timings = new java.util.LinkedHashMap<>(Map.of("draw", 1.0));
        PanoramaMetadata m = new PanoramaMetadata(new dempano.geo.Viewpoint(46, 8, 1000, 0, 1000, 2), 100_000, 0.13,
                DepthMode.SHADER_RANGE, 1, 100_000, 8, 100, 100, new java.util.ArrayList<>(List.of("N46E008")),
                new java.util.ArrayList<>(), warnings, timings, "test", 0, 0, null, new java.util.ArrayList<>());
        warnings.add("added later");
        timings.clear();
        assertEquals(List.of("a warning"), m.warnings());
        assertEquals(Map.of("draw", 1.0), m.timingsMillis());
        assertThrows(UnsupportedOperationException.class, () -> m.warnings().add("x"));
        assertThrows(UnsupportedOperationException.class, () -> m.tilesUsed().clear());
        assertThrows(UnsupportedOperationException.class, () -> m.timingsMillis().clear());
        assertThrows(UnsupportedOperationException.class, () -> m.demSources().clear());
    }
}
