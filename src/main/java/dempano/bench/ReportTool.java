package dempano.bench;

import dempano.io.IoMessages;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine;

/**
 * What the report and benchmark tools ({@code gradle accuracyReport}, {@code bench}, {@code orientationReport}, …)
 * share: their command line through picocli, with a bad value or a problem found before the work (an unknown
 * scene, an output folder that is a file) said in one line, exit status 2, instead of a stack trace; and their output
 * folder checked before an hour of work, not after.
 */
public final class ReportTool {
    private ReportTool() {
    }

    /** {@code --shared DIR} and {@code --out DIR}, as the reports over the shared material take them (a picocli mixin). */
    public static final class SharedOptions {
        @picocli.CommandLine.Option(names = "--shared", description = "The shared material folder (default: ${DEFAULT-VALUE}).",
                defaultValue = "../shared")
        public Path shared;
        @picocli.CommandLine.Option(names = "--out", description = "Folder for the report's files (default: ${DEFAULT-VALUE}).",
                defaultValue = "docs")
        public Path out;
    }

    /** {@code --dem DIR}, {@code --summits FILE} and {@code --out DIR} of the void-fill reports (a picocli mixin). */
    public static final class FillOptions {
        @picocli.CommandLine.Option(names = "--dem", description = "SRTM tiles (default: ${DEFAULT-VALUE}).",
                defaultValue = "../shared/dem")
        public Path dem;
        @picocli.CommandLine.Option(names = "--summits", description = "Surveyed summits (default: ${DEFAULT-VALUE}).",
                defaultValue = "../shared/peaks/alps.txt")
        public Path summits;
        @picocli.CommandLine.Option(names = "--out", description = "Folder for the report (default: ${DEFAULT-VALUE}).",
                defaultValue = "docs")
        public Path out;
    }

    /**
     * Runs a picocli command: its own messages for unknown options and unparsable values, and an
     * {@link IllegalArgumentException} or {@link IOException} from the command as one line, "NAME: message", exit 2
     * (other exceptions as picocli reports them: a bug).
     *
     * @return the exit status
     */
    public static int run(Object command, String[] args) {
        CommandLine cl = new CommandLine(command);
        cl.setExecutionExceptionHandler((e, line, parsed) -> {
            if (e instanceof IllegalArgumentException) {
                line.getErr().println(line.getCommandName() + ": " + e.getMessage());
                return 2;
            }
            if (e instanceof IOException io) {
                line.getErr().println(line.getCommandName() + ": " + IoMessages.describe(io));
                return 2;
            }
            throw e;
        });
        return cl.execute(args);
    }

    /**
     * The output folder, made if it is missing; checked now so that a long run does not end in an error.
     *
     * @throws IllegalArgumentException when it is a file, or cannot be made or written
     */
    public static Path outputFolder(Path out) {
        if (Files.exists(out) && !Files.isDirectory(out)) {
            throw new IllegalArgumentException("the output folder " + out + " is a file, not a folder");
        }
        try {
            Files.createDirectories(out);
            Files.delete(Files.createTempFile(out, ".write-check", ".tmp"));
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot write to the output folder " + out + ": " + IoMessages.reason(e));
        }
        return out;
    }

    /**
     * The subset of {@code known} names asked for; all of them for an empty request.
     *
     * @param what the names' kind for the message ("scene", "case")
     * @throws IllegalArgumentException naming the unknown names and the known ones
     */
    public static java.util.Set<String> subset(java.util.Collection<String> requested, java.util.Collection<String> known,
                                               String what) {
        if (requested == null || requested.isEmpty()) {
            return new java.util.LinkedHashSet<>(known);
        }
        java.util.List<String> unknown = requested.stream().filter(n -> !known.contains(n)).toList();
        if (!unknown.isEmpty()) {
            throw new IllegalArgumentException("unknown " + what + (unknown.size() > 1 ? "s " : " ") + String.join(", ", unknown)
                    + "; the " + what + "s are " + String.join(", ", known));
        }
        return new java.util.LinkedHashSet<>(requested);
    }

    /**
     * Checks that the report's inputs exist (a folder or a file each).
     *
     * @throws IllegalArgumentException naming the first that does not
     */
    public static void inputs(Path... paths) {
        for (Path p : paths) {
            if (!Files.exists(p)) {
                throw new IllegalArgumentException(p + " does not exist");
            }
        }
    }

    /**
     * The commit the report is made at, as {@code `abc1234`}, with " (with uncommitted changes)" where tracked files
     * other than the report's own outputs differ from it; {@code `?`} outside a git checkout.
     *
     * @param outputGlobs the report's own files (git pathspec globs, e.g. {@code **}{@code /accuracy.md}): what the run
     *                    writes does not make the measured code dirty
     */
    public static String commit(String... outputGlobs) {
        String commit = git("rev-parse", "--short", "HEAD");
        java.util.List<String> status = new java.util.ArrayList<>(java.util.List.of("status", "--porcelain",
                "--untracked-files=no", "--", "."));
        for (String glob : outputGlobs) {
            status.add(":(exclude,glob)" + glob);
        }
        String dirty = git(status.toArray(String[]::new));
        return "`" + commit + "`" + (dirty.isEmpty() ? "" : " (with uncommitted changes)");
    }

    private static String git(String... args) {
        try {
            java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of("git"));
            cmd.addAll(java.util.List.of(args));
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).trim();
            return p.waitFor() == 0 ? out : "?";
        } catch (IOException e) {
            return "?";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "?";
        }
    }
}
