package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code dempano fly} where no window can open: one "dempano: …" line naming the problem and the way
 * out, exit code 1, and nothing else on the terminal (no jME or GLFW log lines, the cause said once).
 * Each case runs the CLI in its own JVM with the display variables set as the case says, so the
 * result does not depend on the machine running the tests.
 */
class FlyWithoutDisplayTest {
    /** Runs {@code dempano fly} scripted in a fresh JVM; returns exit code and all output. */
    static Object[] fly(Path dir, Map<String, String> env) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx512m", "-cp", System.getProperty("java.class.path"), "dempano.cli.Main", "fly", "--no-dialog",
                "--frames", "2", "--screenshot", dir.resolve("x.png").toString(), "--out-dir", dir.toString())
                .directory(dir.toFile()).redirectErrorStream(true);
        for (String k : List.of("DISPLAY", "WAYLAND_DISPLAY", "DEMPANO_GL", "DEMPANO_DEBUG")) {
            pb.environment().remove(k);
        }
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(2, TimeUnit.MINUTES), "fly did not finish");
        return new Object[] {p.exitValue(), out};
    }

    static void oneClearLine(Object[] r, String problem) {
        String out = (String) r[1];
        assertEquals(1, r[0], out);
        List<String> lines = out.lines().toList();
        assertEquals(1, lines.size(), out);
        String line = lines.get(0);
        assertTrue(line.startsWith("dempano: fly ") && line.contains(problem), line);
        assertTrue(line.contains("DEMPANO_GL=x11 xvfb-run -a"), "names the way out: " + line);
        for (String internal : List.of("INFO", "SEVERE", "com.jme3", "Exception", "\tat ", "glfw", "GLFW")) {
            assertFalse(line.contains(internal), line);
        }
    }

    @Test
    void noDisplaySetFailsBeforeAnythingStarts(@TempDir Path dir) throws Exception {
        oneClearLine(fly(dir, Map.of()), "no display is set ($DISPLAY and $WAYLAND_DISPLAY are empty)");
        assertFalse(Files.exists(dir.resolve("build")), "the demo DEM is not written for a flight that cannot start");
        oneClearLine(fly(dir, Map.of("DEMPANO_GL", "x11", "WAYLAND_DISPLAY", "wayland-0")), "$DISPLAY is not set");
    }

    @Test
    void anUnreachableDisplayIsNamedOnce(@TempDir Path dir) throws Exception {
        Assumptions.assumeFalse(Files.exists(Path.of("/tmp/.X11-unix/X9999")), "an X server runs on :9999");
        Object[] r = fly(dir, Map.of("DISPLAY", ":9999"));
        oneClearLine(r, "could not open its window");
        String line = ((String) r[1]).strip();
        assertTrue(line.contains(":9999"), line);
        String cause = "Failed to open display";
        assertEquals(line.indexOf(cause), line.lastIndexOf(cause), "the cause is said once: " + line);
    }
}
