package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.dem.DemoTerrain;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A whole {@code dempano batch} process sent SIGTERM (what {@code kill} and a closing terminal send; Ctrl-C's SIGINT
 * takes the same shutdown path) after its first row: the batch's hook lets the row in progress finish while the exit
 * cleanup of uncommitted output sets waits for it (BatchRunTest covers the cancel itself in one process; this checks the
 * two shutdown hooks together). Whatever the moment the signal lands: every row listed is "ok" (none failed because its
 * staging was discarded under it), every row listed has its whole set, no file belongs to a row not listed, and no
 * hidden staging folder or lock is left.
 */
class BatchSignalTest {
    @Test
    void sigtermAfterTheFirstRowLeavesOnlyCompleteListedSets(@TempDir Path d) throws Exception {
        Path demo = DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR);
        double[] vp = DemoTerrain.viewpoint();
        int rows = 30; // the signal lands within a row or two; the rest are "not run"
        StringBuilder csv = new StringBuilder("id,lat,lon\n");
        for (int i = 0; i < rows; i++) {
            csv.append(String.format(Locale.ROOT, "r%02d,%.6f,%.6f%n", i, vp[0] + 0.002 * i, vp[1]));
        }
        Path viewpoints = Files.writeString(d.resolve("rows.csv"), csv);
        Path out = d.resolve("out");
        List<String> args = new ArrayList<>(List.of("batch", viewpoints.toString(), "--out-dir", out.toString(),
                "--dem-dir", demo.toString()));
        args.addAll(BatchCommandTest.SMALL);
        Process child = KillWhileWritingTest.start(args.toArray(new String[0]));
        BufferedReader lines = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8));
        StringBuilder seen = new StringBuilder();
        String line;
        while ((line = lines.readLine()) != null) {
            seen.append(line).append('\n');
            if (line.contains("[1/" + rows + "] r00 ok")) {
                break;
            }
        }
        assertTrue(seen.toString().contains("r00 ok"), seen.toString());
        child.toHandle().destroy(); // SIGTERM (Process.destroy would also close our end of its output)
        while ((line = lines.readLine()) != null) {
            seen.append(line).append('\n');
        }
        assertTrue(child.waitFor(120, TimeUnit.SECONDS), seen.toString());
        assertNotEquals(0, child.exitValue(), seen.toString());

        List<String> results = Files.readAllLines(out.resolve("results.csv"));
        Set<String> listed = new TreeSet<>();
        for (String r : results.subList(1, results.size())) {
            String[] cells = r.split(",", -1);
            assertEquals("ok", cells[1], "row " + r + "\n" + seen);
            listed.add(cells[0]);
            for (String suffix : List.of(".png", "-distance.npy", "-distance.png", ".json")) {
                assertTrue(Files.size(out.resolve(cells[0] + suffix)) > 0, cells[0] + suffix);
            }
        }
        assertTrue(listed.contains("r00") && listed.size() < rows, listed + "\n" + seen);
        assertTrue(seen.toString().contains(listed.size() + " ok, 0 failed, " + (rows - listed.size()) + " not run of " + rows),
                seen.toString());
        Set<String> withFiles = new TreeSet<>();
        try (Stream<Path> files = Files.list(out)) {
            for (String name : files.map(p -> p.getFileName().toString()).toList()) {
                assertTrue(!name.startsWith("."), "hidden staging or lock left: " + name);
                if (!name.equals("results.csv")) {
                    withFiles.add(name.substring(0, 3));
                }
            }
        }
        assertEquals(listed, withFiles, "files of rows not in results.csv");
        System.out.println("batch SIGTERM test: rows done " + listed);
    }
}
