package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The CLI's output files under bad destinations and replaced sets: exit code, a message naming the
 * problem, and the files left behind (none of a new set after a failure; permissions from the umask).
 * Renders use the CPU reference on the demo scene at 2 px/° (about a second).
 */
class OutputFilesCliTest {
    static final String[] SMALL = {"--renderer", "reference", "--ppd", "2", "--elevation-range", "-10:10"};

    static String[] args(String... more) {
        List<String> a = new ArrayList<>(List.of(SMALL));
        a.addAll(List.of(more));
        return a.toArray(new String[0]);
    }

    static Set<String> names(Path dir) throws IOException {
        Set<String> out = new TreeSet<>();
        try (Stream<Path> s = Files.list(dir)) {
            s.forEach(p -> out.add(p.getFileName().toString() + (Files.isDirectory(p) ? "/" : "")));
        }
        return out;
    }

    /**
     * One row per bad destination: the arguments ({@code D} = a fresh folder), the set-up made in D
     * first, the exit code, the message, and what D holds afterwards.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            // --out         | set-up                | exit | message                                                    | D afterwards
            "D/o/            | dir o                 | 2    | the output prefix 'D/o/' names a folder                     | o/",
            "D/missing/p     | -                     | 1    | cannot write D/missing/p.*: folder D/missing does not exist  | ",
            "D/file/p        | file file             | 1    | cannot write D/file/p.*: D/file is a file, not a folder      | file",
            "/proc/dempano-x | -                     | 1    | cannot write /proc/dempano-x.*: cannot create files in /proc | ",
            "D/p             | dir p.json            | 1    | cannot write D/p.json: a folder of that name is in the way   | p.json/",
            "D/p             | dir p.png             | 1    | cannot write D/p.png: a folder of that name is in the way    | p.png/",
            "D/p             | dir p-distance.png    | 1    | cannot write D/p-distance.png: a folder of that name is in the way | p-distance.png/",
    })
    void badDestinationsFailBeforeRenderingAndWriteNothing(String out, String setUp, int exit, String message,
                                                           String left, @TempDir Path d) throws IOException {
        if (!setUp.equals("-")) {
            String[] s = setUp.split(" ");
            if (s[0].equals("dir")) {
                Files.createDirectory(d.resolve(s[1]));
            } else {
                Files.writeString(d.resolve(s[1]), "x");
            }
        }
        String[] r = MainTest.run(args("--out", out.replace("D/", d + "/")));
        assertEquals(Integer.toString(exit), r[0], r[1]);
        assertTrue(r[1].contains("dempano: " + message.replace("D/", d + "/")), r[1]);
        assertFalse(r[1].contains("sweeping"), "failed before rendering: " + r[1]);
        assertFalse(r[1].contains("\tat "), "no stack trace: " + r[1]);
        Set<String> expected = new TreeSet<>();
        if (left != null) {
            expected.add(left);
        }
        assertEquals(expected, names(d), "nothing of a new set, nothing hidden");
    }

    @Test
    void aMissingSummitListNamesTheFileAndTheReason(@TempDir Path d) throws IOException {
        String[] r = MainTest.run(args("--out", d + "/p", "--summits", d + "/none.txt"));
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano: cannot read the summit list " + d + "/none.txt: no such file or folder"), r[1]);
        assertEquals(Set.of(), names(d));
    }

    @Test
    void aRenderReplacesTheWholePreviousSetWithFilesOfTheUmasksMode(@TempDir Path d) throws IOException {
        Path summits = Files.writeString(d.resolve("peaks.csv"), "Demo summit,0.05,0.05,1500\n");
        Path out = Files.createDirectory(d.resolve("out"));
        String[] first = MainTest.run(args("--out", out + "/p", "--layers", "elevation", "--summits", summits.toString()));
        assertEquals("0", first[0], first[1]);
        assertEquals(Set.of("p.png", "p-distance.npy", "p-distance.png", "p-elevation.npy", "p-summits.json",
                "p-summits.csv", "p-labels.png", "p.json"), names(out));
        assertEquals(2 * 360, width(out), "the first set's grid");

        String[] second = MainTest.run("--renderer", "reference", "--ppd", "3", "--elevation-range", "-10:10",
                "--out", out + "/p");
        assertEquals("0", second[0], second[1]);
        assertEquals(Set.of("p.png", "p-distance.npy", "p-distance.png", "p.json"), names(out),
                "the old set's layer and summit files went with it");
        assertEquals(3 * 360, width(out));
        JsonObject json = JsonParser.parseString(Files.readString(out.resolve("p.json"))).getAsJsonObject();
        assertEquals(0, json.get("terrainTriangles").getAsLong(), "the CPU reference draws no triangles");
        assertEquals(0, json.get("lodErrorPx").getAsDouble(), "and intersects the full-resolution surface");
        assertTrue(json.get("nearMetres").isJsonNull(), "nor has a near plane: " + json);
        assertEquals(0, json.get("views").getAsInt(), "nor views");
        assertEquals(3 * 360, javax.imageio.ImageIO.read(out.resolve("p.png").toFile()).getWidth());

        Path reference = Files.createFile(d.resolve("made-by-any-program"));
        Set<PosixFilePermission> umaskMode = Files.getPosixFilePermissions(reference);
        for (String n : names(out)) {
            assertEquals(umaskMode, Files.getPosixFilePermissions(out.resolve(n)), n);
        }
    }

    static int width(Path out) throws IOException {
        JsonObject json = JsonParser.parseString(Files.readString(out.resolve("p.json"))).getAsJsonObject();
        return json.getAsJsonObject("grid").get("width").getAsInt();
    }

    @Test
    void aRequestTooLargeForTheHeapIsRefusedBeforeRenderingWithTheFigures(@TempDir Path d) throws IOException {
        String[] r = MainTest.run("--renderer", "reference", "--ppd", "200", "--out", d + "/p");
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("dempano: this panorama needs about "), r[1]);
        assertTrue(r[1].contains("GB of Java heap") && r[1].contains("--ppd") && r[1].contains("-Xmx"), r[1]);
        assertFalse(r[1].contains("sweeping"), "refused before rendering: " + r[1]);
        assertEquals(Set.of(), names(d));
    }
}
