package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** PNG through memory: the pixels come back, no file appears in ImageIO's cache folder, the stream stays open. */
class PngTest {
    @Test
    void encodesThroughMemoryLeavingTheStreamOpen(@TempDir Path cache) throws IOException {
        BufferedImage image = new BufferedImage(301, 17, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                image.setRGB(x, y, (x * 7919 + y * 104_729) & 0xffffff);
            }
        }
        boolean usedCache = ImageIO.getUseCache();
        File cacheDirectory = ImageIO.getCacheDirectory();
        ImageIO.setUseCache(true); // ImageIO's default, under which ImageIO.write(image, "png", stream) makes a file
        ImageIO.setCacheDirectory(cache.toFile());
        boolean[] closed = {false};
        long[] filesSeen = {0};
        ByteArrayOutputStream out = new ByteArrayOutputStream() {
            @Override
            public void write(byte[] b, int off, int len) {
                try (Stream<Path> files = Files.list(cache)) {
                    filesSeen[0] += files.count();
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
                super.write(b, off, len);
            }

            @Override
            public void close() {
                closed[0] = true;
            }
        };
        try {
            Png.write(image, out);
        } finally {
            ImageIO.setUseCache(usedCache);
            ImageIO.setCacheDirectory(cacheDirectory);
        }
        assertEquals(0, filesSeen[0], "files in the cache folder while the PNG was written");
        assertFalse(closed[0], "the caller's stream was closed");
        BufferedImage back = ImageIO.read(new ByteArrayInputStream(out.toByteArray()));
        assertTrue(back != null && back.getWidth() == 301 && back.getHeight() == 17);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                assertEquals(image.getRGB(x, y), back.getRGB(x, y), x + "," + y);
            }
        }
    }
}
