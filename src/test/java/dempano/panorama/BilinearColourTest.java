package dempano.panorama;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link Stitcher#bilinearColour}'s unclamped path inside the view must give the bytes the clamped
 * four-sample sum gives (a faster colour that changed images would not be a speed-up), and at the
 * view's edges the samples are clamped.
 */
class BilinearColourTest {
    /** The clamped bilinear sum written out independently: weights (1 − f) and f, samples clamped to the view. */
    private static int reference(byte[] rgba, int w, int h, double px, double py) {
        int x0 = (int) Math.floor(px), y0 = (int) Math.floor(py);
        double fx = px - x0, fy = py - y0;
        double[] sum = new double[3];
        int[][] corners = {{x0, y0}, {x0 + 1, y0}, {x0, y0 + 1}, {x0 + 1, y0 + 1}};
        double[] weights = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
        for (int k = 0; k < 4; k++) {
            int x = Math.max(0, Math.min(w - 1, corners[k][0])), y = Math.max(0, Math.min(h - 1, corners[k][1]));
            for (int c = 0; c < 3; c++) {
                sum[c] += weights[k] * (rgba[(y * w + x) * 4 + c] & 0xff);
            }
        }
        return 0xff000000 | ((int) Math.round(sum[0]) << 16) | ((int) Math.round(sum[1]) << 8) | (int) Math.round(sum[2]);
    }

    @Test
    void sameBytesAsTheClampedSumInsideAndAtTheEdges() {
        int w = 37, h = 23;
        ViewLayout layout = new ViewLayout(8, w, h, 0.6, -0.6);
        byte[] rgba = new byte[w * h * 4];
        Random random = new Random(16);
        random.nextBytes(rgba);
        int compared = 0;
        for (int i = 0; i < 200_000; i++) {
            // From beyond the left/bottom edge to beyond the right/top one, and exact sample centres too.
            double px = i % 10 == 0 ? random.nextInt(w) : -1 + (w + 1) * random.nextDouble();
            double py = i % 10 == 0 ? random.nextInt(h) : -1 + (h + 1) * random.nextDouble();
            assertEquals(reference(rgba, w, h, px, py), Stitcher.bilinearColour(rgba, layout, px, py),
                    () -> "at " + px + ", " + py);
            compared++;
        }
        assertEquals(200_000, compared);
        // A sample centre gives that sample's colour exactly.
        int o = (5 * w + 7) * 4;
        int expected = 0xff000000 | (rgba[o] & 0xff) << 16 | (rgba[o + 1] & 0xff) << 8 | (rgba[o + 2] & 0xff);
        assertEquals(expected, Stitcher.bilinearColour(rgba, layout, 7, 5));
    }

    /**
     * Where all samples around are sky, the stitcher takes one sample's colour ({@link Stitcher#texel}) instead of
     * blending: that must be what the blend gives, for every colour and position (inside the view and beyond
     * its edges), since the weights sum to 1 within rounding far below half a level.
     */
    @Test
    void fourEqualSamplesBlendToThatSampleExactly() {
        int w = 29, h = 17;
        ViewLayout layout = new ViewLayout(8, w, h, 0.6, -0.6);
        Random random = new Random(15);
        byte[] rgba = new byte[w * h * 4];
        for (int i = 0; i < 20_000; i++) {
            if (i % 100 == 0) {
                byte r = (byte) random.nextInt(256), g = (byte) random.nextInt(256), b = (byte) random.nextInt(256);
                for (int k = 0; k < w * h; k++) {
                    rgba[4 * k] = r;
                    rgba[4 * k + 1] = g;
                    rgba[4 * k + 2] = b;
                    rgba[4 * k + 3] = (byte) 255;
                }
            }
            double px = -1 + (w + 1) * random.nextDouble(), py = -1 + (h + 1) * random.nextDouble();
            assertEquals(Stitcher.bilinearColour(rgba, layout, px, py), Stitcher.texel(rgba, layout, px, py),
                    "at " + px + ", " + py);
        }
    }
}
