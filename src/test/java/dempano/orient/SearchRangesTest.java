package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The search ranges of a photo's estimate: the focal range's fields of view in closed form, and what is refused. */
class SearchRangesTest {
    static final double NAN = Double.NaN;

    @Test
    void aFocalRangeOnAThreeByTwoImageGivesTheFullFramesFieldsOfView() {
        // A 3:2 image is a 36 × 24 mm frame scaled: hfov = 2 atan(18 / f) for a 35 mm-equivalent focal length f.
        double[] r = new SearchRanges(NAN, NAN, NAN, 24, 70).hfovRangeDeg(6000, 4000);
        assertArrayEquals(new double[] {Math.toDegrees(2 * Math.atan(18 / 70.0)), Math.toDegrees(2 * Math.atan(18 / 24.0))},
                r, 1e-9);
        // Any shape: the image's width is w / hypot(w, h) of its diagonal, which f spans as it spans 43.27 mm.
        for (int[] size : new int[][] {{4000, 3000}, {1080, 1920}, {960, 640}}) {
            double[] q = new SearchRanges(NAN, NAN, NAN, 28, 28).hfovRangeDeg(size[0], size[1]);
            double halfWidthMm = size[0] / Math.hypot(size[0], size[1]) * Math.hypot(36, 24) / 2;
            double hfov = Math.toDegrees(2 * Math.atan(halfWidthMm / 28));
            assertArrayEquals(new double[] {hfov, hfov}, q, 1e-9);
        }
    }

    @Test
    void aFieldOfViewRangeIsTakenAsGivenAndNoneGivesNone() {
        assertArrayEquals(new double[] {40, 60}, new SearchRanges(NAN, 40, 60, NAN, NAN).hfovRangeDeg(480, 320));
        assertNull(SearchRanges.NONE.hfovRangeDeg(480, 320));
        assertTrue(!SearchRanges.NONE.hasFovRange() && new SearchRanges(NAN, NAN, NAN, 24, 70).hasFovRange());
    }

    @Test
    void outOfRangeValuesAreRefusedNamingTheirFlag() {
        Object[][] bad = {
            {new double[] {-3, NAN, NAN, NAN, NAN}, "--heading-range-deg"},
            {new double[] {181, NAN, NAN, NAN, NAN}, "--heading-range-deg"},
            {new double[] {NAN, 60, 40, NAN, NAN}, "--hfov-range-deg"},
            {new double[] {NAN, 0, 40, NAN, NAN}, "--hfov-range-deg"},
            {new double[] {NAN, 40, 180, NAN, NAN}, "--hfov-range-deg"},
            {new double[] {NAN, 40, NAN, NAN, NAN}, "--hfov-range-deg"},
            {new double[] {NAN, NAN, NAN, 70, 24}, "--focal35-range-mm"},
            {new double[] {NAN, NAN, NAN, -24, 70}, "--focal35-range-mm"},
            {new double[] {NAN, 40, 60, 24, 70}, "not both"},
        };
        for (Object[] c : bad) {
            double[] v = (double[]) c[0];
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new SearchRanges(v[0], v[1], v[2], v[3], v[4]), java.util.Arrays.toString(v));
            assertTrue(e.getMessage().contains((String) c[1]), e.getMessage());
        }
    }
}
