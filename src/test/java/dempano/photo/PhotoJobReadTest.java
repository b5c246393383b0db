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
}
