package dempano.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The installed start script ({@code gradle installDist}, which the test task runs first): prints
 * nothing it was not asked for, sizes the heap from the machine, and keeps DEMPANO_OPTS working.
 */
class StartScriptTest {
    static final Path SCRIPT = Path.of("build", "install", "dempano", "bin", "dempano");

    /** Runs the script; returns exit code, stdout, stderr. */
    static String[] run(Map<String, String> env, String... args) throws Exception {
        assertTrue(Files.isExecutable(SCRIPT), SCRIPT + " is built by installDist before the tests");
        ProcessBuilder pb = new ProcessBuilder(new java.util.ArrayList<>(List.of(SCRIPT.toString())));
        pb.command().addAll(List.of(args));
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("DEMPANO_OPTS");
        pb.environment().putAll(env);
        Path err = Files.createTempFile("dempano-err", ".txt");
        try {
            pb.redirectError(err.toFile());
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(60, TimeUnit.SECONDS));
            return new String[] {Integer.toString(p.exitValue()), out, Files.readString(err)};
        } finally {
            Files.deleteIfExists(err);
        }
    }

    @Test
    void helpPrintsTheUsageAndNothingOnStandardError() throws Exception {
        String[] r = run(Map.of(), "--help");
        assertEquals("0", r[0]);
        assertTrue(r[1].startsWith("Usage: dempano"), r[1]);
        assertEquals("", r[2], "no java -version banner or anything else on stderr");
    }

    @Test
    void theHeapIsSeventyPerCentOfTheMachineUnlessDempanoOptsSaysOtherwise() throws Exception {
        long machine = ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getTotalMemorySize();
        long byDefault = maxHeap(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version")[1]);
        assertEquals(0.70, byDefault / (double) machine, 0.02, "default heap " + byDefault + " of " + machine);
        long given = maxHeap(run(Map.of("DEMPANO_OPTS", "-Xmx1g -XX:+PrintFlagsFinal"), "--version")[1]);
        assertEquals(1L << 30, given);
    }

    /**
     * A panorama or a batch runs on the client compiler alone (a third less time from the shell on two cores); a photo
     * and the fly-through keep both compilers; JAVA_OPTS overrides.
     */
    @Test
    void panoramasAndBatchesRunOnTheClientCompilerAloneUnlessJavaOptsSaysOtherwise() throws Exception {
        assertEquals(1, tieredStopAtLevel(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version")[1]));
        assertEquals(1, tieredStopAtLevel(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "batch", "--help")[1]));
        assertEquals(4, tieredStopAtLevel(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "photo", "--help")[1]));
        assertEquals(4, tieredStopAtLevel(run(Map.of("JAVA_OPTS", "-XX:TieredStopAtLevel=4 -XX:+PrintFlagsFinal"), "--version")[1]));
    }

    /**
     * The same commands get a bounded young generation (memory, docs/cold-start.md): 128 MB for a panorama, 256 MB
     * for a batch; a later -Xmn wins.
     */
    @Test
    void panoramasAndBatchesKeepTheYoungGenerationBoundedUnlessJavaOptsSaysOtherwise() throws Exception {
        long mb = 1L << 20;
        assertEquals(128 * mb, flag(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version")[1], "MaxNewSize"));
        assertEquals(256 * mb, flag(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "batch", "--help")[1], "MaxNewSize"));
        long photo = flag(run(Map.of("JAVA_OPTS", "-XX:+PrintFlagsFinal"), "photo", "--help")[1], "MaxNewSize");
        assertTrue(photo != 128 * mb && photo != 256 * mb, "photo keeps the JVM's own: " + photo);
        assertEquals(64 * mb, flag(run(Map.of("JAVA_OPTS", "-Xmn64m -XX:+PrintFlagsFinal"), "--version")[1], "MaxNewSize"));
        assertEquals(64 * mb, flag(run(Map.of("JAVA_OPTS", "-Xmn64m -XX:+PrintFlagsFinal"), "batch", "--help")[1], "MaxNewSize"));
    }

    private static int tieredStopAtLevel(String flagsFinal) {
        return (int) flag(flagsFinal, "TieredStopAtLevel");
    }

    private static long flag(String flagsFinal, String name) {
        Matcher m = Pattern.compile("\\b" + name + "\\s+=\\s+(\\d+)").matcher(flagsFinal);
        assertTrue(m.find(), name + " among the flags");
        return Long.parseLong(m.group(1));
    }

    static final Path ARCHIVE = Path.of("build", "install", "dempano", "lib", "dempano.jsa");
    static final String SHARED = "source: shared objects file";

    /**
     * installDist's class-data sharing archive holds dempano's classes and is used. A rebuilt jar (newer than the
     * archive) makes the script leave it out, so the JVM keeps its own; a jar changed in a way the script cannot see
     * (an older time) makes the JVM refuse it. Either way nothing is printed and the script runs.
     */
    @Test
    void theClassDataArchiveIsUsedAndAChangedJarMakesItBeIgnoredSilently() throws Exception {
        assertTrue(Files.isRegularFile(ARCHIVE), ARCHIVE + " is made by installDist (a training run on the demo scene)");
        String[] fresh = run(Map.of("DEMPANO_OPTS", "-Xlog:class+load"), "--version");
        assertEquals("0", fresh[0], fresh[2]);
        assertEquals("", fresh[2]);
        assertTrue(fresh[1].contains("dempano.cli.Main " + SHARED), "dempano's own classes come from the archive");

        Path jar = ARCHIVE.resolveSibling("dempano-0.1.0.jar");
        java.nio.file.attribute.FileTime was = Files.getLastModifiedTime(jar);
        try {
            for (long shiftMillis : new long[] {60_000, -60_000}) {
                Files.setLastModifiedTime(jar, java.nio.file.attribute.FileTime.fromMillis(was.toMillis() + shiftMillis));
                String[] stale = run(Map.of("DEMPANO_OPTS", "-Xlog:class+load"), "--version");
                assertEquals("0", stale[0], stale[2]);
                assertEquals("", stale[2], "no warning about the stale archive");
                assertTrue(stale[1].contains("dempano 0.1.0"), stale[1]);
                assertTrue(stale[1].contains("dempano.cli.Main source: file:"), "a stale archive must not be used");
                if (shiftMillis > 0) {
                    assertTrue(stale[1].contains("java.lang.Object " + SHARED), "the JVM's own archive is still used");
                }
            }
        } finally {
            Files.setLastModifiedTime(jar, was);
        }
    }

    /** Without the archive (removed, or never made) the script names none: the JVM keeps its own, and says nothing. */
    @Test
    void withoutTheArchiveTheScriptRunsSilentlyOnTheJvmsOwnArchive(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path home = dir.resolve("dempano");
        copyInstallation(home, false);
        ProcessBuilder pb = new ProcessBuilder(home.resolve("bin/dempano").toString(), "--version");
        pb.environment().remove("JAVA_OPTS");
        pb.environment().put("DEMPANO_OPTS", "-Xlog:class+load");
        Path err = dir.resolve("err.txt");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue());
        assertEquals("", Files.readString(err));
        assertTrue(out.contains("dempano 0.1.0"), out);
        assertTrue(out.contains("dempano.cli.Main source: file:"), out);
        assertTrue(out.contains("java.lang.Object " + SHARED), "a missing archive named to the JVM would switch its own off");
    }

    /**
     * An installation whose path holds the shell's special characters runs: Gradle 4.x's template passed the class
     * path's value through eval, which expanded a {@code $}, {@code `} or {@code "} in it again (the JVM found no
     * class). Spaces worked before.
     */
    @Test
    void anInstallationPathWithTheShellsSpecialCharactersRuns(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path home = dir.resolve("odd $HOME \"q\" `false` 'a' \\b").resolve("dempano");
        copyInstallation(home, true);
        ProcessBuilder pb = new ProcessBuilder(home.resolve("bin/dempano").toString(), "--version");
        pb.environment().remove("JAVA_OPTS");
        Path err = dir.resolve("err.txt");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals("", Files.readString(err));
        assertEquals(0, p.exitValue());
        assertTrue(out.contains("dempano 0.1.0"), out);
    }

    /** Copies the installation (times kept) to {@code home}, with or without the class-data archive. */
    static void copyInstallation(Path home, boolean withArchive) throws IOException {
        Path installed = SCRIPT.getParent().getParent();
        try (var files = Files.walk(installed)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path to = home.resolve(installed.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(to);
                } else if (withArchive || !f.getFileName().toString().equals("dempano.jsa")) {
                    Files.copy(f, to, java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
                }
            }
        }
    }

    static long maxHeap(String flags) throws IOException {
        Matcher m = Pattern.compile("MaxHeapSize\\s*=\\s*(\\d+)").matcher(flags);
        assertTrue(m.find(), flags);
        return Long.parseLong(m.group(1));
    }
}
