package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Memory in a real JVM of a small heap: the issue's request (-Xmx400m, 60 px/°, 30 km) is refused
 * before rendering with the figures; a heap that runs out anyway (here: filled by ballast the estimate
 * cannot see) ends in one line with the way out, exit 1, no stack trace, and no file of the new set.
 */
class OutOfMemoryCliTest {
    /**
     * The child: fills the heap with ballast until it runs out, gives back {@code args[0]} MB of it,
     * then runs the CLI with the other arguments (the estimate sees the whole heap, not the ballast).
     */
    public static void main(String[] args) {
        int giveBackQuarters = args[0].equals("none") ? -1 : 4 * Integer.parseInt(args[0]);
        byte[][] ballast = new byte[8192][]; // up to 2 GB in quarter megabytes (not humongous G1 allocations)
        int n = 0;
        if (giveBackQuarters >= 0) {
            byte[] reserve = new byte[8 << 20]; // room to stop filling gracefully
            try {
                while (n < ballast.length) {
                    ballast[n] = new byte[1 << 18];
                    n++;
                }
            } catch (OutOfMemoryError full) {
                reserve = null;
                for (int i = 0; i < giveBackQuarters && n > 0; i++) {
                    ballast[--n] = null;
                }
            }
        }
        int code = Main.run(java.util.Arrays.copyOfRange(args, 1, args.length));
        System.out.println("ballast " + n);
        System.exit(code);
    }

    static String[] child(String heap, String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heap, "-cp", System.getProperty("java.class.path"), OutOfMemoryCliTest.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(180, TimeUnit.SECONDS), out);
        return new String[] {Integer.toString(p.exitValue()), out};
    }

    @Test
    void theIssuesRequestIsRefusedBeforeRendering(@TempDir Path d) throws Exception {
        String[] r = child("400m", "none", "--ppd", "60", "--range-km", "30", "--out", d + "/p");
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano: this panorama needs about ") && r[1].contains("but the limit is 0.42 GB"), r[1]);
        assertFalse(r[1].contains("rendering 8 views"), r[1]);
        try (Stream<Path> s = Files.list(d)) {
            assertEquals(0, s.count());
        }
    }

    @Test
    void aHeapThatRunsOutAnywayEndsInOneLineWithTheWayOut(@TempDir Path d) throws Exception {
        String[] r = child("300m", "40", "--renderer", "reference", "--ppd", "14", "--out", d + "/p");
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano: out of memory (") && r[1].matches("(?s).*; Java heap limit (2[89]\\d|3[0-2]\\d) MB\\): lower --ppd.*"), r[1]); // MB: '0.0 GB' for a small heap
        assertTrue(r[1].contains("DEMPANO_OPTS=-Xmx2g"), r[1]);
        assertFalse(r[1].contains("\tat ") || r[1].contains("Exception in"), "no stack trace: " + r[1]);
        try (Stream<Path> s = Files.list(d)) {
            assertEquals(0, s.count(), "no file of the new set, nothing hidden");
        }
    }
}
