package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The photo scaled for matching: sizes, scale and area averaging against block means computed here. */
class MatchImageTest {
    @ParameterizedTest(name = "{0} × {1} → {2} × {3}")
    @CsvSource({
            "480, 320, 480, 320", // the benchmark's size: as it is
            "300, 200, 300, 200", // smaller: never enlarged
            "480, 1000, 480, 1000", // as wide as needed already
            "2000, 300, 2000, 300", // a panoramic strip no taller than needed
            "6000, 4000, 480, 320", // a 24 MP photo
            "4000, 3000, 480, 360", // 4:3: the width decides
            "3000, 4000, 480, 640", // portrait: the width decides
            "12000, 2000, 1920, 320", // a wide panoramic photo: the height decides
            "1000, 700, 480, 336" // a non-integer factor (2.083)
    })
    void sizes(int w, int h, int sw, int sh) {
        BufferedImage photo = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        MatchImage m = MatchImage.of(photo);
        assertEquals(sw, m.image().getWidth());
        assertEquals(sh, m.image().getHeight());
        assertEquals((double) h / sh, m.scale(), 1e-12);
        if (sw == w) {
            assertSame(photo, m.image());
        }
    }

    @Test
    void integerFactorsAverageEachBlockExactly() {
        int f = 4, w = 480 * f, h = 320 * f;
        BufferedImage photo = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR); // as JPEGs decode
        java.util.Random rnd = new java.util.Random(7);
        int[] pixel = new int[w * h];
        for (int i = 0; i < pixel.length; i++) {
            pixel[i] = rnd.nextInt(1 << 24);
        }
        photo.setRGB(0, 0, w, h, pixel, 0, w);
        MatchImage m = MatchImage.of(photo);
        assertEquals(4.0, m.scale(), 0);
        for (int y = 0; y < 320; y += 7) {
            for (int x = 0; x < 480; x += 5) {
                int got = m.image().getRGB(x, y);
                for (int shift = 16; shift >= 0; shift -= 8) {
                    int sum = 0;
                    for (int dy = 0; dy < f; dy++) {
                        for (int dx = 0; dx < f; dx++) {
                            sum += pixel[(y * f + dy) * w + x * f + dx] >> shift & 0xff;
                        }
                    }
                    // BoofCV rounds the mean of a block of integers to the nearest (half up).
                    assertEquals((sum + f * f / 2) / (f * f), got >> shift & 0xff, 1.0, "pixel " + x + "," + y);
                }
            }
        }
    }

    @Test
    void aNonIntegerFactorKeepsTheMeanAndAUniformColour() {
        int w = 1000, h = 700;
        BufferedImage photo = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        double sum = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int v = x * 255 / (w - 1); // a ramp in red, a constant green and blue
                photo.setRGB(x, y, v << 16 | 0x40 << 8 | 0xc8);
                sum += v;
            }
        }
        BufferedImage s = MatchImage.of(photo).image();
        double scaledSum = 0;
        for (int y = 0; y < s.getHeight(); y++) {
            for (int x = 0; x < s.getWidth(); x++) {
                int c = s.getRGB(x, y);
                assertEquals(0x40, c >> 8 & 0xff);
                assertEquals(0xc8, c & 0xff);
                scaledSum += c >> 16 & 0xff;
            }
        }
        assertEquals(sum / (w * h), scaledSum / (s.getWidth() * s.getHeight()), 0.5);
    }
}
