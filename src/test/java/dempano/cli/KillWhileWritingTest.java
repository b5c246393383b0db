package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import dempano.io.OutputSet;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real CLI killed (SIGKILL) at several moments around writing: the JSON beside the files always
 * describes them, and after the next run the prefix holds one complete set, old or new, with no
 * hidden file left. (Every step of the commit is covered deterministically by io.OutputSetKillTest.)
 */
class KillWhileWritingTest {
    static Process start(String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true).start();
    }

    @Test
    void killedAroundWritingTheSetIsOldOrNewNeverAMix(@TempDir Path d) throws Exception {
        String prefix = d.resolve("p").toString();
        String[] first = MainTest.run("--ppd", "4", "--elevation-range", "-10:10", "--out", prefix);
        assertEquals("0", first[0], first[1]);
        // One whole run times the stretch from "stitching" to the end (stitch, write, commit, exit); the
        // kills then fall at fractions of it, so they land in the writing on a machine of any speed.
        long stretchMs = untilEndAfterStitching(prefix + "-timing");
        List<Integer> widths = new ArrayList<>();
        for (double fraction : new double[] {0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
            long delayMs = Math.round(fraction * stretchMs);
            Process child = start("--ppd", "12", "--elevation-range", "-10:10", "--out", prefix);
            BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8));
            String line;
            StringBuilder seen = new StringBuilder();
            while ((line = out.readLine()) != null) {
                seen.append(line).append('\n');
                if (line.contains("stitching")) {
                    break;
                }
            }
            assertTrue(seen.toString().contains("stitching"), seen.toString());
            Thread.sleep(delayMs);
            child.destroyForcibly();
            assertTrue(child.waitFor(30, TimeUnit.SECONDS));
            assertConsistent(d, false);
            OutputSet.open(prefix).close(); // what the next run does first
            widths.add(assertConsistent(d, true));
        }
        System.out.println("kill test: stitching to exit " + stretchMs + " ms; set widths after each kill and the next run: " + widths);
        // The test is meant to hit the writing: at least one kill must have left the old set and one the new.
        assertTrue(widths.contains(4 * 360), "some kills came before the commit: " + widths);
    }

    static long untilEndAfterStitching(String prefix) throws Exception {
        Process child = start("--ppd", "12", "--elevation-range", "-10:10", "--out", prefix);
        BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8));
        String line;
        long stitching = 0;
        while ((line = out.readLine()) != null) {
            if (line.contains("stitching")) {
                stitching = System.nanoTime();
            }
        }
        assertTrue(child.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, child.exitValue());
        return (System.nanoTime() - stitching) / 1_000_000;
    }

    /** Checks the JSON (if any) against the files beside it; returns the set's width. */
    static int assertConsistent(Path d, boolean complete) throws IOException {
        Path json = d.resolve("p.json");
        if (!Files.exists(json)) {
            assertFalse(complete, "after the next run a complete set is there");
            return -1;
        }
        JsonObject doc = JsonParser.parseString(Files.readString(json)).getAsJsonObject();
        int w = doc.getAsJsonObject("grid").get("width").getAsInt(), h = doc.getAsJsonObject("grid").get("height").getAsInt();
        List<String> listed = new ArrayList<>();
        for (JsonElement f : doc.getAsJsonArray("files")) {
            listed.add(f.getAsString());
            assertTrue(Files.isRegularFile(d.resolve(f.getAsString())), f.getAsString() + " listed and present");
        }
        assertEquals(List.of("p.png", "p-distance.npy", "p-distance.png", "p.json"), listed);
        assertEquals(w, javax.imageio.ImageIO.read(d.resolve("p.png").toFile()).getWidth());
        assertEquals(h, javax.imageio.ImageIO.read(d.resolve("p.png").toFile()).getHeight());
        assertEquals(w, javax.imageio.ImageIO.read(d.resolve("p-distance.png").toFile()).getWidth());
        byte[] npy = Files.readAllBytes(d.resolve("p-distance.npy"));
        String header = new String(npy, 10, ByteBuffer.wrap(npy, 8, 2).order(ByteOrder.LITTLE_ENDIAN).getShort(),
                StandardCharsets.US_ASCII);
        assertTrue(header.contains("'shape': (" + h + ", " + w + ")"), header);
        assertEquals(10 + header.length() + 4L * w * h, npy.length);
        if (complete) {
            try (Stream<Path> s = Files.list(d)) {
                assertEquals(List.of(), s.map(p -> p.getFileName().toString()).filter(n -> n.startsWith(".")).toList(),
                        "no hidden staging or lock left");
            }
        }
        return w;
    }
}
