package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A panorama from a shell whose DISPLAY names an X server nobody runs (a stale DISPLAY in tmux or over ssh): the views
 * need no display, and the images are drawn without one. AWT tried to connect once the render was done, failed with a
 * stack trace and every output was lost (a hostile test of the environment).
 */
class DeadDisplayTest {
    @Test
    void aDisplayNobodyServesDoesNotMatter(@TempDir Path d) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "--ppd", "4", "--elevation-range", "-10:10", "--out", d.resolve("p").toString()));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("DISPLAY", ":77"); // no X server answers there
        pb.environment().remove("WAYLAND_DISPLAY");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), out);
        assertEquals(0, p.exitValue(), out);
        assertTrue(Files.size(d.resolve("p.png")) > 0 && Files.size(d.resolve("p-distance.png")) > 0, out);
        assertTrue(!out.contains("AWTError") && !out.contains("Exception"), out);
    }
}
