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

    static long maxHeap(String flags) throws IOException {
        Matcher m = Pattern.compile("MaxHeapSize\\s*=\\s*(\\d+)").matcher(flags);
        assertTrue(m.find(), flags);
        return Long.parseLong(m.group(1));
    }
}
