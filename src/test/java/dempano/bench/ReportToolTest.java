package dempano.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The report tools' command lines: a bad value, an unknown name or an output folder that cannot be written is one
 * line and exit status 2, found before the work (an unknown scene wrote an empty report with exit 0; a bench whose
 * folder was a file lost its cases at the end; {@code -Pphotos=0} crashed after two minutes, its files half
 * replaced).
 */
class ReportToolTest {
    @TempDir
    Path tmp;

    private record Run(int exit, String err) {
    }

    private static Run run(Object command, String... args) {
        PrintStream err = System.err;
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        try {
            System.setErr(new PrintStream(e, true, StandardCharsets.UTF_8));
            int exit = ReportTool.run(command, args);
            return new Run(exit, e.toString(StandardCharsets.UTF_8));
        } finally {
            System.setErr(err);
        }
    }

    @Test
    void anOutputFolderThatIsAFileIsRefusedAndAMissingOneMade() throws Exception {
        Path file = Files.writeString(tmp.resolve("afile"), "x");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ReportTool.outputFolder(file));
        assertEquals("the output folder " + file + " is a file, not a folder", e.getMessage());
        Path made = ReportTool.outputFolder(tmp.resolve("a/b"));
        assertTrue(Files.isDirectory(made));
        try (var listing = Files.list(made)) {
            assertEquals(0, listing.count(), "the write check leaves nothing behind");
        }
    }

    @Test
    void aSubsetNamesWhatIsUnknownAndWhatIsKnown() {
        List<String> known = List.of("a", "b", "c");
        assertEquals(Set.of("a", "b", "c"), ReportTool.subset(null, known, "scene"));
        assertEquals(Set.of("a", "c"), ReportTool.subset(List.of("c", "a"), known, "scene"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ReportTool.subset(List.of("a", "x", "y"), known, "case"));
        assertEquals("unknown cases x, y; the cases are a, b, c", e.getMessage());
    }

    /** Each tool, with a value it cannot use: one line naming it, exit 2, no stack trace, nothing written. */
    @Test
    void eachToolRefusesABadValueInOneLineBeforeAnyWork() throws Exception {
        Path file = Files.writeString(tmp.resolve("afile"), "x");
        Object[][] cases = {
            {OrientationReport.class, new String[] {"--photos", "0", "--out", tmp.toString()}, "--photos must be at least 1, got 0"},
            {OrientationReport.class, new String[] {"--photos", "4", "--only", "4", "--out", tmp.toString()},
                "--only lists photo 4, but the run's photos are 0–3"},
            {OrientationReport.class, new String[] {"--out", file.toString()}, "is a file, not a folder"},
            {dempano.cli.AccuracyReport.class, new String[] {"--scenes", "nosuch", "--out", tmp.toString()},
                "unknown scene nosuch; the scenes are synthetic"},
            {CameraAccuracyReport.class, new String[] {"--size", "600", "--out", tmp.toString()},
                "--size must be WIDTHxHEIGHT, each 16–4000 pixels, got '600'"},
            {CameraAccuracyReport.class, new String[] {"--size", "99999x99999"}, "each 16–4000 pixels"},
            {VoidFillReport.Command.class, new String[] {"--out", file.toString()}, "is a file, not a folder"},
            {CoarseFillReport.Command.class, new String[] {"--dem", tmp.resolve("none").toString(), "--out", tmp.toString()},
                tmp.resolve("none").resolve("N46E008.hgt") + " does not exist"},
            {BatchBenchmark.class, new String[] {"--rounds", "0"}, "--rounds must be at least 1"},
        };
        for (Object[] c : cases) {
            java.lang.reflect.Constructor<?> ctor = ((Class<?>) c[0]).getDeclaredConstructor();
            ctor.setAccessible(true);
            Run r = run(ctor.newInstance(), (String[]) c[1]);
            String what = ((Class<?>) c[0]).getSimpleName() + " " + String.join(" ", (String[]) c[1]);
            assertEquals(2, r.exit(), what + ": " + r.err());
            assertTrue(r.err().contains((String) c[2]), what + ": " + r.err());
            assertFalse(r.err().contains("\tat "), what + ": " + r.err());
            assertEquals(1, r.err().strip().lines().count(), what + ": " + r.err());
        }
        try (var listing = Files.list(tmp)) {
            assertEquals(List.of(file), listing.toList(), "nothing written");
        }
    }

    @Test
    void aRunOfSomePhotosSaysWhichInItsHeadings() {
        assertEquals("100 photos, seed 1", new OrientationReport.Run(100, 1, Set.of()).describe());
        assertEquals("photos 0, 99 of a run of 100, seed 1 (`-Ponly`)",
                new OrientationReport.Run(100, 1, new java.util.TreeSet<>(Set.of(99, 0))).describe());
    }
}
