package dempano.photo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading a photograph's pixels (whole, cut short, or in a format without a reader), and the job's input checks. */
class PhotoJobReadTest {
    @TempDir
    Path tmp;

    static BufferedImage gradient(int w, int h) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.setRGB(x, y, (x * 255 / w) << 16 | (y * 255 / h) << 8 | 0x40);
            }
        }
        return img;
    }

    @Test
    void aWholeJpegIsReadAndOneCutShortIsAnErrorNotGreyRows() throws IOException {
        Path whole = tmp.resolve("whole.jpg");
        ImageIO.write(gradient(320, 240), "jpg", whole.toFile());
        BufferedImage img = PhotoJob.readPixels(whole);
        assertEquals(320, img.getWidth());
        assertEquals(240, img.getHeight());
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = Files.write(tmp.resolve("cut.jpg"), Arrays.copyOf(bytes, bytes.length / 2));
        // ImageIO.read decodes it without a word, the lower rows grey.
        assertEquals(240, ImageIO.read(cut.toFile()).getHeight());
        IOException e = assertThrows(IOException.class, () -> PhotoJob.readPixels(cut));
        assertTrue(e.getMessage().contains("ends before the image does"), e.getMessage());
    }

    @Test
    void aPngCutShortIsAnErrorAndAFormatWithoutAReaderIsNull() throws IOException {
        Path whole = tmp.resolve("whole.png");
        ImageIO.write(gradient(320, 240), "png", whole.toFile());
        assertEquals(320, PhotoJob.readPixels(whole).getWidth());
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = Files.write(tmp.resolve("cut.png"), Arrays.copyOf(bytes, bytes.length / 2));
        assertThrows(IOException.class, () -> PhotoJob.readPixels(cut));
        Path text = Files.writeString(tmp.resolve("notes.heic"), "not an image the JDK reads");
        assertNull(PhotoJob.readPixels(text));
    }

    @Test
    void aHeadingRangeOutsideZeroToHundredEightyDegreesIsRefusedBeforeAnythingIsRead() {
        dempano.PanoramaRequest settings = dempano.PanoramaRequest.at(46.43, 8.09);
        for (double bad : new double[] {-3, 0, 180.5, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new PhotoJob.Input(
                    tmp.resolve("absent.jpg"), dempano.camera.PhotoOverrides.NONE, null, null,
                    dempano.orient.SearchRanges.NONE.withHeadingRangeDeg(bad), settings, null, "x"));
            assertTrue(e.getMessage().contains("--heading-range-deg"), e.getMessage());
        }
        for (double ok : new double[] {Double.NaN, 0.5, 180}) {
            assertEquals(ok, new PhotoJob.Input(tmp.resolve("absent.jpg"), dempano.camera.PhotoOverrides.NONE, null, null,
                    dempano.orient.SearchRanges.NONE.withHeadingRangeDeg(ok), settings, null, "x").headingRangeDeg(), 0);
        }
    }

    @Test
    void anEstimateNoSkylineSampleFitsIsRefusedAndOneThatFitsSomewhereIsKept() {
        dempano.orient.PhotoOrientation open = new dempano.orient.PhotoOrientation(false, true, true, false, false);
        java.util.function.DoubleFunction<dempano.orient.OrientationEstimate> fitting = share ->
                new dempano.orient.OrientationEstimate(90, 0, 0, 50, share > 0 ? 1.5 : Double.NaN, share, 1 - share, Double.NaN,
                        null, -0.1, true, 300, 1, Double.NaN, Double.NaN);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> PhotoJob.checkMatched(
                fitting.apply(0), open, java.util.List.of("no camera pitch in the metadata: give --pitch-deg")));
        assertEquals("could not estimate the pitch, roll from the photo: its skyline fits the panorama at 0 % of its samples,"
                + " in no pose (is the photo upright, and the position right?); give them instead:\n"
                + "  - no camera pitch in the metadata: give --pitch-deg", e.getMessage());
        PhotoJob.checkMatched(fitting.apply(0.05), open, java.util.List.of()); // unsure, but a pose: written, flagged
    }

    /** Floating-point pixels (a float TIFF of 0…255 values) become 8-bit RGB scaled by their largest value (they threw). */
    @Test
    void floatPixelsBecomeEightBitScaledByTheirLargestValue() {
        int w = 4, h = 2;
        java.awt.image.WritableRaster raster = java.awt.image.Raster.createWritableRaster(
                new java.awt.image.BandedSampleModel(java.awt.image.DataBuffer.TYPE_FLOAT, w, h, 1),
                new java.awt.image.DataBufferFloat(w * h, 1), null);
        float[] values = {0, 51, 102, 255, 25.5f, 127.5f, Float.NaN, -3};
        raster.setPixels(0, 0, w, h, values);
        java.awt.image.ColorModel cm = new java.awt.image.ComponentColorModel(
                java.awt.color.ColorSpace.getInstance(java.awt.color.ColorSpace.CS_GRAY), false, false,
                java.awt.Transparency.OPAQUE, java.awt.image.DataBuffer.TYPE_FLOAT);
        BufferedImage in = new BufferedImage(cm, raster, false, null);
        BufferedImage out = PhotoJob.eightBit(in);
        int[] expected = {0, 51, 102, 255, 26, 128, 0, 0};
        for (int i = 0; i < values.length; i++) {
            int rgb = out.getRGB(i % w, i / w);
            assertEquals(expected[i] * 0x010101, rgb & 0xffffff, "pixel " + i + " of value " + values[i]);
        }
        BufferedImage eight = gradient(3, 3);
        assertTrue(PhotoJob.eightBit(eight) == eight, "8-bit images are returned as they are");
    }

    /**
     * A CMYK JPEG of three bars (red, green, blue as 200/40 mixes) written by the JDK, its inks as they are, and the
     * same file with an Adobe APP14 marker and the inks inverted, as Photoshop and Pillow write them: both read as the
     * bars' RGB within JPEG's error (the JDK's own conversion gave red as 229,110,110, washed out).
     */
    @Test
    void cmykJpegsReadAsTheirColours() throws IOException {
        int[][] bars = {{200, 40, 40}, {40, 200, 40}, {40, 40, 200}};
        for (boolean adobe : new boolean[] {false, true}) {
            java.awt.image.WritableRaster r = java.awt.image.Raster.createInterleavedRaster(
                    java.awt.image.DataBuffer.TYPE_BYTE, 120, 80, 4, null);
            for (int y = 0; y < 80; y++) {
                for (int x = 0; x < 120; x++) {
                    int[] rgb = bars[x / 40];
                    int[] ink = {255 - rgb[0], 255 - rgb[1], 255 - rgb[2], 0}; // C, M, Y, K
                    for (int b = 0; b < 4; b++) {
                        ink[b] = adobe ? 255 - ink[b] : ink[b];
                    }
                    r.setPixel(x, y, ink);
                }
            }
            java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
            javax.imageio.ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
            try (javax.imageio.stream.ImageOutputStream out = ImageIO.createImageOutputStream(bytes)) {
                writer.setOutput(out);
                javax.imageio.ImageWriteParam p = writer.getDefaultWriteParam();
                p.setCompressionMode(javax.imageio.ImageWriteParam.MODE_EXPLICIT);
                p.setCompressionQuality(0.95f);
                writer.write(null, new javax.imageio.IIOImage(r, null, null), p);
            } finally {
                writer.dispose();
            }
            byte[] jpeg = bytes.toByteArray();
            if (adobe) { // APP14 "Adobe", version 100, flags 0, transform 0 (no colour transform), right after SOI
                byte[] app14 = {(byte) 0xFF, (byte) 0xEE, 0, 14, 'A', 'd', 'o', 'b', 'e', 0, 100, 0, 0, 0, 0, 0};
                byte[] with = new byte[jpeg.length + app14.length];
                System.arraycopy(jpeg, 0, with, 0, 2);
                System.arraycopy(app14, 0, with, 2, app14.length);
                System.arraycopy(jpeg, 2, with, 2 + app14.length, jpeg.length - 2);
                jpeg = with;
            }
            Path file = Files.write(tmp.resolve("cmyk-" + adobe + ".jpg"), jpeg);
            BufferedImage img = PhotoJob.readPixels(file);
            for (int bar = 0; bar < 3; bar++) {
                int rgb = img.getRGB(20 + 40 * bar, 40);
                int[] got = {rgb >> 16 & 255, rgb >> 8 & 255, rgb & 255};
                for (int b = 0; b < 3; b++) {
                    assertTrue(Math.abs(got[b] - bars[bar][b]) <= 6, (adobe ? "Adobe" : "plain") + " bar " + bar
                            + ": " + Arrays.toString(got) + " for " + Arrays.toString(bars[bar]));
                }
            }
        }
    }

    /** A header declaring more pixels than any view is refused before the pixels are decoded. */
    @Test
    void aPhotoLargerThanAnyViewIsRefusedFromItsHeader() throws IOException {
        Path big = tmp.resolve("big.png");
        ImageIO.write(new BufferedImage(16_385, 2, BufferedImage.TYPE_BYTE_BINARY), "png", big.toFile());
        IOException e = assertThrows(IOException.class, () -> PhotoJob.readPixels(big));
        assertEquals("16385×2 pixels: at most 16384 on a side (the render of its view could not be made); scale it down",
                e.getMessage());
    }
}
