package dempano.dem;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * GDAL's command-line tools (Debian's {@code gdal-bin}, installed by scripts/setup.sh) for tests that
 * make GeoTIFFs at run time. Where a tool is absent the test is skipped with the reason, but only
 * outside CI: with the environment variable {@code CI} set (as {@code .ci/run} runs) a missing tool
 * fails the test, so CI cannot pass without having run them.
 */
public final class Gdal {
    private Gdal() {
    }

    /** The tool's path on PATH; skips (locally) or fails (under CI) when it is not installed. */
    public static String require(String tool) {
        String path = System.getenv("PATH");
        if (path != null) {
            for (String d : path.split(File.pathSeparator)) {
                Path p = Path.of(d.isEmpty() ? "." : d, tool);
                if (Files.isExecutable(p)) {
                    return p.toString();
                }
            }
        }
        String reason = tool + " not found on PATH: install GDAL's tools (apt-get install gdal-bin, as scripts/setup.sh does)";
        String ci = System.getenv("CI");
        if (ci != null && !ci.isBlank() && !ci.equalsIgnoreCase("false")) {
            fail(reason + "; CI=" + ci + " requires them");
        }
        Assumptions.abort(reason + "; test skipped (it would fail under CI)");
        return null; // not reached
    }

    /**
     * Runs a GDAL tool with arguments; fails the test with its output if it exits with an error.
     *
     * @return the tool's standard output and error together
     */
    static String run(String tool, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(require(tool));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        byte[] out = p.getInputStream().readAllBytes();
        try {
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                fail(String.join(" ", cmd) + " did not finish within 120 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        String text = new String(out, StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            fail(String.join(" ", cmd) + " exited with " + p.exitValue() + ":\n" + text);
        }
        return text;
    }

    /** gdal_translate with -q, then the arguments (options, source, destination). */
    static Path translate(Path source, Path destination, String... options) throws IOException {
        List<String> a = new ArrayList<>(List.of("-q"));
        a.addAll(List.of(options));
        a.add(source.toString());
        a.add(destination.toString());
        run("gdal_translate", a.toArray(String[]::new));
        return destination;
    }

    /** gdalwarp -q (overwriting), then the arguments (options, source, destination). */
    static Path warp(Path source, Path destination, String... options) throws IOException {
        List<String> a = new ArrayList<>(List.of("-q", "-overwrite"));
        a.addAll(List.of(options));
        a.add(source.toString());
        a.add(destination.toString());
        run("gdalwarp", a.toArray(String[]::new));
        return destination;
    }
}
