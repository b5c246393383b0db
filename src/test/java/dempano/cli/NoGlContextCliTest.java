package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.SharedData;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Where no OpenGL context can be made (here: {@code DEMPANO_GL=x11} without {@code $DISPLAY}), the
 * commands that open the renderer in the background (the panorama and {@code dempano batch}) fail with
 * the cause said once, exit code 1, no jME log line or stack trace, and the batch stops after the first
 * row instead of failing every row. Each case runs in its own JVM with the environment it needs.
 */
class NoGlContextCliTest {
    private static final String CAUSE = "The DISPLAY environment variable is missing";

    private static Object[] run(Path dir, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx512m", "-cp", System.getProperty("java.class.path"), "dempano.cli.Main"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
        for (String k : List.of("DISPLAY", "WAYLAND_DISPLAY", "DEMPANO_DEBUG")) {
            pb.environment().remove(k);
        }
        pb.environment().put("DEMPANO_GL", "x11");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(2, TimeUnit.MINUTES), "dempano did not finish");
        return new Object[] {p.exitValue(), out};
    }

    private static void saidOnceWithoutInternals(String out) {
        for (String line : out.lines().toList()) {
            assertTrue(line.indexOf(CAUSE) == line.lastIndexOf(CAUSE), "the cause is said once: " + line);
        }
        for (String internal : List.of("SEVERE", "com.jme3", "Exception", "\tat ", "Display initialization failed")) {
            assertFalse(out.contains(internal), internal + " in: " + out);
        }
    }

    @Test
    void thePanoramaSaysWhyInOneLine(@TempDir Path dir) throws Exception {
        Path dem = SharedData.demFile("N46E008.hgt").getParent().toAbsolutePath();
        Object[] r = run(dir, "--lat", "46.4", "--lon", "8.1", "--range-km", "20", "--ppd", "5",
                "--dem-dir", dem.toString(), "--out", dir.resolve("p").toString());
        String out = (String) r[1];
        assertEquals(1, r[0], out);
        String last = out.strip().lines().reduce((a, b) -> b).orElse("");
        assertTrue(last.startsWith("dempano: cannot create an OpenGL context (") && last.contains(CAUSE), last);
        saidOnceWithoutInternals(out);
        try (var files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "no output is written");
        }
    }

    @Test
    void theBatchStopsAfterTheFirstRowAndSaysWhy(@TempDir Path dir) throws Exception {
        Path dem = SharedData.demFile("N46E008.hgt").getParent().toAbsolutePath();
        Files.writeString(dir.resolve("v.csv"), "id,lat,lon\na,46.4,8.1\nb,46.41,8.11\nc,46.42,8.12\n");
        Object[] r = run(dir, "batch", "v.csv", "--out-dir", "out", "--range-km", "20", "--ppd", "5",
                "--dem-dir", dem.toString());
        String out = (String) r[1];
        assertEquals(1, r[0], out);
        assertTrue(out.contains("dempano batch: 0 ok, 1 failed, 2 not run of 3 rows"), out);
        assertTrue(out.contains("dempano batch: stopped: cannot create an OpenGL context (X11: " + CAUSE + ")"), out);
        saidOnceWithoutInternals(out);
        List<String> results = Files.readAllLines(dir.resolve("out/results.csv"));
        assertEquals(2, results.size(), "header and the one row tried: " + results);
        assertTrue(results.get(1).startsWith("a,error,,") && results.get(1).contains(CAUSE), results.get(1));
    }
}
