package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The set is all-or-nothing, takes the umask's permissions, and cleans up after killed runs. */
class OutputSetTest {
    /** A prefix too long for the staging folder's name is refused saying how long it may be; that length works. */
    @Test
    void aPrefixTooLongForTheStagingFolderSaysHowLongItMayBe(@TempDir Path dir) throws IOException {
        // 225 bytes: every output name fits in 255, the hidden staging folder did not ("file name too long").
        IOException e = assertThrows(IOException.class, () -> OutputSet.open(dir.resolve("y".repeat(225)).toString()));
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("its last part is 225 bytes long, at most (\\d+) fit")
                .matcher(e.getMessage());
        assertTrue(m.find() && e.getMessage().endsWith("shorten it"), e.getMessage());
        int most = Integer.parseInt(m.group(1));
        assertTrue(most > 200 && most < 225, e.getMessage());
        try (OutputSet set = OutputSet.open(dir.resolve("y".repeat(most)).toString())) {
            set.write(".json", out -> out.write("{}".getBytes(StandardCharsets.UTF_8)));
            set.commit();
        }
        assertTrue(Files.exists(dir.resolve("y".repeat(most) + ".json")));
    }

    /** Writes a set whose every file says which generation it belongs to; the JSON lists the files. */
    static void writeGeneration(Path dir, int generation, List<String> suffixes) throws IOException {
        try (OutputSet set = OutputSet.open(dir.resolve("p").toString())) {
            stage(set, generation, suffixes);
            set.commit();
        }
    }

    static void stage(OutputSet set, int generation, List<String> suffixes) throws IOException {
        StringBuilder json = new StringBuilder("{\"generation\": " + generation + ", \"files\": [");
        for (String s : suffixes) {
            set.write(s, out -> out.write(("generation " + generation + "\n").getBytes(StandardCharsets.UTF_8)));
            json.append('"').append("p").append(s).append("\", ");
        }
        json.append("\"p.json\"]}\n");
        set.write(".json", out -> out.write(json.toString().getBytes(StandardCharsets.UTF_8)));
    }

    /** Every entry of the folder and its content (hidden staging entries included). */
    static Map<String, String> contents(Path dir) throws IOException {
        Map<String, String> out = new TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                out.put(p.getFileName().toString(), Files.isDirectory(p) ? "<dir>" : Files.readString(p).trim());
            }
        }
        return out;
    }

    static Map<String, String> expectedSet(int generation, List<String> suffixes) {
        Map<String, String> out = new TreeMap<>();
        StringBuilder files = new StringBuilder();
        for (String s : suffixes) {
            out.put("p" + s, "generation " + generation);
            files.append("\"p").append(s).append("\", ");
        }
        out.put("p.json", "{\"generation\": " + generation + ", \"files\": [" + files + "\"p.json\"]}");
        return out;
    }

    static final List<String> OLD = List.of(".png", "-distance.npy", "-distance.png", "-summits.csv");
    static final List<String> NEW = List.of(".png", "-distance.npy", "-distance.png", "-elevation.npy");

    @Test
    void aNewSetReplacesTheOldOneWholeAndRemovesTheOldFilesItLacks(@TempDir Path dir) throws IOException {
        writeGeneration(dir, 1, OLD);
        Files.writeString(dir.resolve("p-notes.txt"), "mine"); // not listed in the old JSON: kept
        writeGeneration(dir, 2, NEW);
        Map<String, String> expected = expectedSet(2, NEW);
        expected.put("p-notes.txt", "mine");
        assertEquals(expected, contents(dir), "p-summits.csv of the old set is gone, nothing hidden is left");
    }

    @Test
    void aFileTheRunReadsIsNeitherOverwrittenNorDeletedAsTheOldSets(@TempDir Path dir) throws IOException {
        // The old set listed p-summits.csv; this run reads it as its summit list, and a photo named like its picture.
        writeGeneration(dir, 1, OLD);
        Path photo = Files.writeString(dir.resolve("p.png"), "the photo");
        Path summits = dir.resolve("p-summits.csv");
        Files.writeString(summits, "name,lat,lon");
        try (OutputSet set = OutputSet.open(dir.resolve("p").toString())) {
            set.protect(photo, "the photo").protect(summits, "the summit list");
            IOException e = assertThrows(IOException.class, () -> set.checkTargets(List.of(".png")));
            assertEquals("cannot write " + dir.resolve("p.png") + ": it is the photo (" + photo + "), which this run reads;"
                    + " choose another output prefix", e.getMessage());
            assertThrows(IOException.class, () -> set.write(".png", out -> out.write(1)));
            set.write("-distance.npy", out -> out.write(2));
            set.write(".json", out -> out.write("{\"files\": [\"p-distance.npy\", \"p.json\"]}".getBytes(StandardCharsets.UTF_8)));
            set.commit();
        }
        assertEquals("the photo", Files.readString(photo));
        assertEquals("name,lat,lon", Files.readString(summits), "listed by the old set, read by this one: kept");
        assertFalse(Files.exists(dir.resolve("p-distance.png")), "the old set's other file is gone");
    }

    @Test
    void theExitCleanupLetsRegisteredWorkCommitFirstAndDiscardsTheRest(@TempDir Path dir) throws IOException {
        // What Ctrl-C does (the cleanup runs as a shutdown hook): a batch's row in progress is let finish, an
        // abandoned set is discarded, and nothing hidden is left.
        OutputSet finishing = OutputSet.open(dir.resolve("p").toString());
        OutputSet abandoned = OutputSet.open(dir.resolve("q").toString());
        stage(finishing, 1, List.of(".png"));
        abandoned.write(".png", out -> out.write(1));
        Runnable commitIt = () -> {
            try {
                finishing.commit();
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };
        OutputSet.finishBeforeCleanup(commitIt);
        try {
            OutputSet.discardUncommitted();
        } finally {
            OutputSet.noLongerFinishing(commitIt);
        }
        assertEquals(expectedSet(1, List.of(".png")), contents(dir), "p committed, q's staging gone");
        abandoned.close(); // already discarded: nothing to do
    }

    @Test
    void aFailureWhileStagingLeavesTheOldSetAndNothingElse(@TempDir Path dir) throws IOException {
        writeGeneration(dir, 1, OLD);
        try (OutputSet set = OutputSet.open(dir.resolve("p").toString())) {
            set.write(".png", out -> out.write(1));
            IOException e = assertThrows(IOException.class, () -> set.write("-distance.npy", out -> {
                out.write(2);
                throw new IOException("No space left on device");
            }));
            assertEquals("cannot write " + dir.resolve("p-distance.npy") + ": No space left on device", e.getMessage());
        }
        assertEquals(expectedSet(1, OLD), contents(dir));
    }

    @Test
    void filesGetTheUmasksPermissionsAlsoWhenReplacingA0600File(@TempDir Path dir) throws IOException {
        Path reference = Files.createFile(dir.resolve("made-by-any-program"));
        Set<PosixFilePermission> umaskMode = Files.getPosixFilePermissions(reference);
        Files.delete(reference);
        writeGeneration(dir, 1, OLD);
        for (String name : expectedSet(1, OLD).keySet()) {
            Files.setPosixFilePermissions(dir.resolve(name), PosixFilePermissions.fromString("rw-------"));
        }
        writeGeneration(dir, 2, OLD);
        for (String name : expectedSet(2, OLD).keySet()) {
            assertEquals(umaskMode, Files.getPosixFilePermissions(dir.resolve(name)), name);
        }
        // The single-file writer too.
        AtomicFiles.write(dir.resolve("single.bin"), out -> out.write(1));
        assertEquals(umaskMode, Files.getPosixFilePermissions(dir.resolve("single.bin")));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', nullValues = "NULL", value = {
            "NULL|the output prefix is empty",
            "''|the output prefix is empty",
            "'  '|the output prefix is empty",
            "o/|names a folder: add the start of a file name, such as o/panorama",
            "/|names a folder",
            ".|names a folder",
            "o/..|names a folder",
            "o/.|names a folder",
    })
    void prefixesThatNameNoFileAreRefused(String prefix, String message) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> OutputSet.checkPrefix(prefix));
        assertTrue(e.getMessage().contains(message), e.getMessage());
    }

    @Test
    void destinationProblemsAreFoundAtOpenOrBeforeStagingAndNameThePath(@TempDir Path dir) throws IOException {
        IOException missing = assertThrows(IOException.class, () -> OutputSet.open(dir.resolve("no/p").toString()));
        assertEquals("cannot write " + dir.resolve("no/p") + ".*: folder " + dir.resolve("no") + " does not exist",
                missing.getMessage());
        Files.writeString(dir.resolve("file"), "x");
        IOException file = assertThrows(IOException.class, () -> OutputSet.open(dir.resolve("file/p").toString()));
        assertEquals("cannot write " + dir.resolve("file/p") + ".*: " + dir.resolve("file") + " is a file, not a folder",
                file.getMessage());
        IOException proc = assertThrows(IOException.class, () -> OutputSet.open("/proc/dempano-test"));
        assertTrue(proc.getMessage().startsWith("cannot write /proc/dempano-test.*: cannot create files in /proc ("),
                proc.getMessage());
        Files.createDirectory(dir.resolve("p.json"));
        try (OutputSet set = OutputSet.open(dir.resolve("p").toString())) {
            IOException blocked = assertThrows(IOException.class, () -> set.checkTargets(List.of(".png", ".json")));
            assertEquals("cannot write " + dir.resolve("p.json") + ": a folder of that name is in the way",
                    blocked.getMessage());
        }
        assertEquals(Map.of("file", "x", "p.json", "<dir>"), contents(dir), "nothing written, nothing left behind");
    }

    @Test
    void staleStagingOfADeadProcessIsRemovedOrFinishedAndALiveOnesIsLeftAlone(@TempDir Path dir) throws IOException {
        writeGeneration(dir, 1, OLD);
        // A dead process's staging without the commit mark: discarded. With the mark: finished.
        Path uncommitted = Files.createDirectory(dir.resolve(".p.dempano-999999999-0-0000000a"));
        Files.writeString(uncommitted.resolve("p.png"), "generation 9");
        Path live = dir.resolve(".p.dempano-" + ProcessHandle.current().parent().orElseThrow().pid() + "-"
                + ProcessHandle.current().parent().orElseThrow().info().startInstant().orElseThrow().toEpochMilli()
                + "-0000000b");
        Files.createDirectory(live);
        Files.writeString(live.resolve("p.png"), "generation 8");
        OutputSet.open(dir.resolve("p").toString()).close();
        Map<String, String> expected = expectedSet(1, OLD);
        expected.put(live.getFileName().toString(), "<dir>");
        assertEquals(expected, contents(dir), "the dead one's staging is gone, the live one's kept");
        Files.delete(live.resolve("p.png"));
        Files.delete(live);

        Path committed = Files.createDirectory(dir.resolve(".p.dempano-999999999-0-0000000c"));
        for (Map.Entry<String, String> e : expectedSet(2, NEW).entrySet()) {
            Files.writeString(committed.resolve(e.getKey()), e.getValue() + "\n");
        }
        Files.writeString(committed.resolve("COMMIT"), "p-summits.csv\n");
        OutputSet.open(dir.resolve("p").toString()).close();
        assertEquals(expectedSet(2, NEW), contents(dir));
    }

    @Test
    void aCommittedOrClosedSetRefusesMoreWork(@TempDir Path dir) throws IOException {
        OutputSet set = OutputSet.open(dir.resolve("p").toString());
        set.write(".png", out -> out.write(1));
        set.commit();
        assertThrows(IllegalStateException.class, () -> set.write(".json", out -> { }));
        assertThrows(IllegalStateException.class, set::commit);
        assertFalse(contents(dir).keySet().stream().anyMatch(n -> n.startsWith(".")), contents(dir).toString());
    }
}
