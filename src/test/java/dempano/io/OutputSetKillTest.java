package dempano.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A writing process killed at every step of a set's commit (a separate JVM halted there, which runs
 * no finally block or shutdown hook: what kill -9 leaves): the folder never shows a JSON that
 * describes other files than those beside it, and after the next run it holds the complete old set
 * (killed before the commit mark) or the complete new one (at or after it), with nothing hidden left.
 */
class OutputSetKillTest {
    /** The child: writes generation 2 over generation 1, halting the JVM at the named step. */
    public static void main(String[] args) throws IOException {
        String haltAt = args[1];
        boolean exit = args.length > 2 && args[2].equals("exit"); // an orderly exit (Ctrl-C): shutdown hooks run
        OutputSet.checkpoint = step -> {
            if (step.equals(haltAt)) {
                if (exit) {
                    System.exit(130);
                }
                Runtime.getRuntime().halt(137);
            }
        };
        OutputSetTest.writeGeneration(Path.of(args[0]), 2, OutputSetTest.NEW);
        System.exit(0);
    }

    static final List<String> STEPS = List.of("staged p.png", "staged p-distance.npy", "staged p-distance.png",
            "staged p-elevation.npy", "staged p.json", "marked", "removed p.json", "moved p-distance.npy",
            "moved p-distance.png", "moved p-elevation.npy", "moved p.png", "moved p.json");

    @ParameterizedTest
    @ValueSource(strings = {"staged p.png", "staged p-distance.npy", "staged p-distance.png", "staged p-elevation.npy",
            "staged p.json", "marked", "removed p.json", "moved p-distance.npy", "moved p-distance.png",
            "moved p-elevation.npy", "moved p.png", "moved p.json"})
    void killedAtEveryStepTheFolderHoldsOneCompleteSetAfterTheNextRun(String step, @TempDir Path dir) throws Exception {
        OutputSetTest.writeGeneration(dir, 1, OutputSetTest.OLD);
        Process child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), OutputSetKillTest.class.getName(), dir.toString(), step)
                .redirectErrorStream(true).start();
        assertTrue(child.waitFor(60, TimeUnit.SECONDS), "child finished");
        String output = new String(child.getInputStream().readAllBytes());
        assertEquals(137, child.exitValue(), "halted at " + step + ": " + output);

        assertJsonDescribesTheFilesBesideIt(dir);
        boolean committed = STEPS.indexOf(step) >= STEPS.indexOf("marked");
        if (!committed) {
            assertEquals(OutputSetTest.expectedSet(1, OutputSetTest.OLD), visible(dir), "before the mark: the old set as it was");
        }
        OutputSet.open(dir.resolve("p").toString()).close(); // the next run with this prefix
        assertEquals(committed ? OutputSetTest.expectedSet(2, OutputSetTest.NEW) : OutputSetTest.expectedSet(1, OutputSetTest.OLD),
                OutputSetTest.contents(dir), "one complete set and nothing hidden after the next run");
    }

    @ParameterizedTest
    @ValueSource(strings = {"staged p.png", "staged p-distance.png", "staged p.json"})
    void interruptedWhileStagingTheOldSetStaysAndNoHiddenFolderIsLeft(String step, @TempDir Path dir) throws Exception {
        // Ctrl-C (SIGINT) runs the shutdown hooks, as System.exit does: the uncommitted staging folder is removed at
        // once, not left for the next run of the prefix.
        OutputSetTest.writeGeneration(dir, 1, OutputSetTest.OLD);
        Process child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), OutputSetKillTest.class.getName(), dir.toString(), step, "exit")
                .redirectErrorStream(true).start();
        assertTrue(child.waitFor(60, TimeUnit.SECONDS), "child finished");
        String output = new String(child.getInputStream().readAllBytes());
        assertEquals(130, child.exitValue(), "exited at " + step + ": " + output);
        assertEquals(OutputSetTest.expectedSet(1, OutputSetTest.OLD), OutputSetTest.contents(dir),
                "the old set as it was, and nothing hidden");
    }

    /** The files a user sees (no hidden staging). */
    static Map<String, String> visible(Path dir) throws IOException {
        Map<String, String> out = new TreeMap<>(OutputSetTest.contents(dir));
        out.keySet().removeIf(n -> n.startsWith("."));
        return out;
    }

    /** If p.json is there, every file it lists is there and of its generation. */
    static void assertJsonDescribesTheFilesBesideIt(Path dir) throws IOException {
        Path json = dir.resolve("p.json");
        if (!Files.exists(json)) {
            return;
        }
        JsonObject doc = JsonParser.parseString(Files.readString(json)).getAsJsonObject();
        int generation = doc.get("generation").getAsInt();
        for (JsonElement f : doc.getAsJsonArray("files")) {
            String name = f.getAsString();
            if (!name.equals("p.json")) {
                assertEquals("generation " + generation, Files.readString(dir.resolve(name)).trim(), name);
            }
        }
    }
}
