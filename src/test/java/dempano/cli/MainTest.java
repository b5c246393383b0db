package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MainTest {
    /** Runs the CLI capturing stderr+stdout. */
    static String[] run(String... args) {
        PrintStream oldErr = System.err, oldOut = System.out;
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        PrintStream ps = new PrintStream(buf, true, StandardCharsets.UTF_8);
        System.setErr(ps);
        System.setOut(ps);
        int code;
        try {
            code = Main.run(args);
        } finally {
            System.setErr(oldErr);
            System.setOut(oldOut);
        }
        return new String[] {Integer.toString(code), buf.toString(StandardCharsets.UTF_8)};
    }

    // Bad arguments: a clear message naming the problem, exit 2, never a stack trace.
    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "--lat 91 --lon 8 --dem-dir .|latitude must be in",
            "--lat NaN --lon 8 --dem-dir .|latitude must be in",
            "--lat 46 --lon 8 --dem-dir . --ppd -3|pixels per degree",
            "--lat 46 --lon 8 --dem-dir . --range-km 0|range must be",
            "--lat 46 --lon 8 --dem-dir . --depth-mode fast|unknown depth mode",
            "--lat 46 --lon 8 --dem-dir . --layers colour|unknown layer",
            "--lat 46 --lon 8 --dem-dir . --elevation-range 30:-30|elevation range",
            "--lat 46 --dem-dir .|give both --lat and --lon",
            "--lat 46 --lon 8|--dem-dir is needed",
            "--lat abc --lon 8 --dem-dir .|Invalid value",
            "--bogus|Unknown option",
            "--lat 46 --lon 8 --dem-dir . --missing-tiles maybe|--missing-tiles must be",
            "--lat 46 --lon 8 --dem-dir . --no-colour --no-distance|nothing to render",
            "--lat 46 --lon 8 --dem-dir . --no-distance --layers elevation|need the distance map",
            "--lat 46 --lon 8 --dem-dir . --no-distance --summits peaks.txt|--summits needs the distance map",
            "--lat 46 --lon 8 --dem-dir . --altitude-m NaN|--altitude-m must be a number, got NaN",
            "--lat 46 --lon 8 --dem-dir . --clear-view-m NaN|--clear-view-m must be a number, got NaN",
            "--lat 46 --lon 8 --dem-dir . --snap-to-summit-m NaN|--snap-to-summit-m must be a number, got NaN",
            "--lat 46 --lon 8 --dem-dir . --label-spacing-px NaN|--label-spacing-px must be a number, got NaN",
            "--lat 46 --lon 8 --dem-dir . --offset-m 1e300|offset must be a number of metres within ±1e6",
            "--lat 46 --lon 8 --dem-dir . --altitude-m 3000 --offset-m 50|--altitude-m and --offset-m both set the standing height",
            "photo --lat 46 --lon 8 --dem-dir . --width-px 10 --height-px 10 --altitude-m 3000 --offset-m 50|--altitude-m and --offset-m both set the standing height",
            "--lat 46 --lon 8 --dem-dir . --eye-height-m 1e9|eye height must be a number of metres in [0, 1e6)",
            "--lat 0x1p5 --lon 8 --dem-dir .|'0x1p5' is not a decimal number",
            "fly --lat 100 --lon 8 --dem-dir .|latitude must be in",
            "photo --lat 0x1p5 --lon 8 --dem-dir . --width-px 10 --height-px 10|'0x1p5' is not a decimal number",
            "--lat 46d --lon 8 --dem-dir .|'46d' is not a decimal number",
    })
    void badArgumentsExitTwoWithAMessage(String args, String expected) {
        String[] r = run(args.split(" "));
        assertEquals("2", r[0], r[1]);
        assertTrue(r[1].contains(expected), r[1]);
        assertFalse(r[1].contains("\tat "), "no stack trace: " + r[1]);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {"--lat 46 --lon 8 --dem-dir /nonexistent/dem|does not exist",
            "--out /nonexistent/out/p|cannot write /nonexistent/out/p.*: folder /nonexistent/out does not exist"})
    void inputProblemsExitOneBeforeAnyRendering(String args, String expected) {
        String[] r = run(args.split(" "));
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains(expected), r[1]);
        assertFalse(r[1].contains("rendering"), "failed before rendering: " + r[1]);
    }

    @org.junit.jupiter.api.Test
    void viewOptionsGivenToTheReferenceRendererAreSaidToBeUnused(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) {
        String[] r = run("--renderer", "reference", "--views", "4", "--near-m", "50", "--ppd", "1", "--range-km", "5",
                "--out", dir.resolve("p").toString());
        assertEquals("0", r[0], r[1]);
        assertTrue(r[1].contains("warning: --views, --near-m not used: --renderer reference draws no views"), r[1]);
    }

    @org.junit.jupiter.api.Test
    void anEmptyDemFolderNameIsAnErrorNotTheWorkingDirectory() {
        String[] r = run("--lat", "46", "--lon", "8", "--dem-dir", "");
        assertEquals("1", r[0], r[1]);
        assertTrue(r[1].contains("DEM directory is empty (\"\"): give a folder"), r[1]);
    }

    @ParameterizedTest
    @CsvSource({"--help"})
    void helpDocumentsEveryOptionWithUnits(String arg) {
        String[] r = run(arg);
        assertEquals("0", r[0]);
        for (String opt : new String[] {"--lat", "--lon", "--dem-dir", "--out", "--ppd", "--range-km", "--offset-m",
                "--altitude-m", "--eye-height-m", "--refraction", "--elevation-range", "--depth-mode", "--layers"}) {
            assertTrue(r[1].contains(opt), opt + " missing from help");
        }
        assertTrue(r[1].contains("metres") && r[1].contains("degrees") && r[1].contains("default"));
    }

    @Test
    void subcommandsAreBuiltWhenNamedOrForHelpOnly() {
        for (String[] args : new String[][] {{}, {"--help"}, {"-h"}, {"help"}, {"fly", "--help"}, {"batch", "x.csv"},
                {"--lat", "1", "photo"}, {"photo"}}) {
            assertTrue(Main.needsSubcommands(args), String.join(" ", args));
        }
        for (String[] args : new String[][] {{"--lat", "44.27", "--lon", "-71.3", "--dem-dir", "dem", "--out", "p"},
                {"--version"}, {"-V"}}) {
            assertFalse(Main.needsSubcommands(args), String.join(" ", args));
        }
        String[] help = run("--help");
        assertEquals("0", help[0]);
        for (String sub : Main.SUBCOMMANDS) {
            assertTrue(help[1].contains(sub), sub + " missing from help");
        }
        String[] flyHelp = run("fly", "--help");
        assertEquals("0", flyHelp[0], flyHelp[1]);
        assertTrue(flyHelp[1].contains("dempano fly"), flyHelp[1]);
    }
}
