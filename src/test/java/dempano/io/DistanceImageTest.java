package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.FloatBuffer;
import org.junit.jupiter.api.Test;

/** The distance picture: the log ramp's ends and middle, sky, clamping, and each pixel where its distance says. */
class DistanceImageTest {
    private static int rgb(double r, double g, double b) {
        return ((int) Math.round(255 * r) << 16) | ((int) Math.round(255 * g) << 8) | (int) Math.round(255 * b);
    }

    @Test
    void rampTable() {
        double min = 100, max = 100_000; // three decades: the ramp's 6 segments are half a decade each
        // {metres, expected RGB}: the ramp's stops fall at min·10^(k/2).
        Object[][] table = {
                {100.0, rgb(0.70, 0.05, 0.05)},
                {10.0, rgb(0.70, 0.05, 0.05)},                  // nearer than min: clamped
                {100 * Math.sqrt(10), rgb(0.95, 0.55, 0.05)},
                {1000.0, rgb(0.85, 0.85, 0.15)},
                {10_000.0, rgb(0.15, 0.65, 0.75)},
                {100_000.0, rgb(0.35, 0.15, 0.55)},
                {1e9, rgb(0.35, 0.15, 0.55)},                   // beyond max: clamped
                {Double.POSITIVE_INFINITY, 0xffffff},            // sky
                {Double.NaN, 0xffffff},
                // Halfway (in log) between the 1 km and 3.16 km stops: the mean of the two colours.
                {1000 * Math.pow(10, 0.25), rgb((0.85 + 0.25) / 2, (0.85 + 0.70) / 2, (0.15 + 0.30) / 2)},
        };
        for (Object[] row : table) {
            int got = DistanceImage.colour((double) row[0], min, max);
            int want = (int) row[1];
            for (int shift = 0; shift <= 16; shift += 8) { // one unit of rounding either way
                assertTrue(Math.abs(((got >> shift) & 0xff) - ((want >> shift) & 0xff)) <= 1,
                        row[0] + " m: " + Integer.toHexString(got) + " vs " + Integer.toHexString(want));
            }
        }
    }

    @Test
    void pixelsFollowTheirDistancesAndTheLegendIsBelow() {
        int w = 37, h = 5;
        float[] d = new float[w * h + 3];
        for (int i = 0; i < d.length; i++) {
            d[i] = i % 11 == 0 ? Float.POSITIVE_INFINITY : 50f * (i + 1);
        }
        FloatBuffer buffer = FloatBuffer.wrap(d);
        buffer.position(3); // a view that does not start at 0
        BufferedImage img = DistanceImage.render(buffer.slice(), w, h, 8000);
        assertEquals(w, img.getWidth());
        assertTrue(img.getHeight() > h, "legend strip below the picture");
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                assertWithinOneLevel(DistanceImage.colour(d[3 + r * w + c], 100, 8000), img.getRGB(c, r) & 0xffffff, "pixel " + c + "," + r);
            }
        }
    }

    /**
     * The tabulated ramp the picture uses against the exact colour: a million log-uniform distances from 1 m to
     * 1000 km and the edge cases, for two ranges; every channel within one level, nearly all identical.
     */
    @Test
    void tabulatedRampMatchesTheExactColour() {
        java.util.Random random = new java.util.Random(19);
        for (double max : new double[] {100_000, 8_765.4321}) {
            DistanceImage.Ramp ramp = new DistanceImage.Ramp(100, max);
            float[] edges = {0f, -0f, -5f, 100f, Math.nextDown(100f), Math.nextUp(100f), (float) max, Math.nextDown((float) max),
                    Math.nextUp((float) max), Float.MIN_VALUE, Float.MAX_VALUE, Float.POSITIVE_INFINITY,
                    Float.NEGATIVE_INFINITY, Float.NaN};
            for (float m : edges) {
                assertWithinOneLevel(DistanceImage.colour(m, 100, max), ramp.colour(m), m + " m");
            }
            assertEquals(0xffffff, ramp.colour(Float.NaN));
            assertEquals(0xffffff, ramp.colour(Float.POSITIVE_INFINITY));
            assertEquals(DistanceImage.colour(100, 100, max), ramp.colour(3f));
            int same = 0, n = 1_000_000;
            for (int i = 0; i < n; i++) {
                float m = (float) Math.pow(10, 6 * random.nextDouble());
                int exact = DistanceImage.colour(m, 100, max), tabulated = ramp.colour(m);
                assertWithinOneLevel(exact, tabulated, m + " m");
                same += exact == tabulated ? 1 : 0;
            }
            assertTrue(same > 0.99 * n, same + " of " + n + " identical");
        }
    }

    private static void assertWithinOneLevel(int want, int got, String where) {
        for (int shift = 0; shift <= 16; shift += 8) {
            assertTrue(Math.abs(((got >> shift) & 0xff) - ((want >> shift) & 0xff)) <= 1,
                    where + ": " + Integer.toHexString(got) + " vs " + Integer.toHexString(want));
        }
    }
}
