package dempano.io;

import java.awt.image.RenderedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.Iterator;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * PNG encoding into a stream through memory. {@code ImageIO.write(image, "png", stream)} goes through a
 * temporary file in {@code java.io.tmpdir} while ImageIO's cache is on (its default): a process killed while
 * writing leaves that file behind (the kill tests left dozens), and the bytes pass through the disk twice.
 * Stateless: no global ImageIO setting is changed.
 */
public final class Png {
    private Png() {
    }

    /** Encodes {@code image} as PNG into {@code out}, which stays open; throws if no PNG writer takes it. */
    public static void write(RenderedImage image, OutputStream out) throws IOException {
        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("no PNG writer");
        }
        ImageWriter writer = writers.next();
        try (ImageOutputStream stream = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), null);
        } finally {
            writer.dispose();
        }
    }
}
