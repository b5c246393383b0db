package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.IIOException;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

class IoMessagesTest {
    @Test
    void anEncodersOwnWordsAreFollowedByTheStreamsReason() {
        assertEquals("I/O error writing PNG file: no space left on device", IoMessages.reason(new IIOException(
                "I/O error writing PNG file!", new FileSystemException("/x/p.png", null, "No space left on device"))));
        assertEquals("cannot write: permission denied", IoMessages.reason(new IOException("cannot write",
                new java.nio.file.AccessDeniedException("/x"))));
        assertEquals("no space left on device", IoMessages.reason(new FileSystemException("/x", null, "No space left on device")));
        assertEquals("disk full", IoMessages.reason(new IOException("disk full", new IOException("disk full"))));
    }

    @Test
    void aPngWrittenToAFullDeviceSaysTheDeviceIsFull() {
        Assumptions.assumeTrue(Files.isWritable(Path.of("/dev/full")), "no /dev/full here");
        IOException e = assertThrows(IOException.class, () -> {
            try (OutputStream out = new FileOutputStream("/dev/full")) {
                Png.write(new BufferedImage(400, 300, BufferedImage.TYPE_INT_RGB), out);
                out.flush();
            }
        });
        assertTrue(IoMessages.reason(e).toLowerCase(java.util.Locale.ROOT).contains("no space left on device"),
                IoMessages.reason(e));
    }
}
