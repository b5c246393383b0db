package dempano.cli;

import java.nio.file.Path;
import java.util.List;

/**
 * Where a command runs: the working directory its relative paths are taken from, and where its renderer comes
 * from. {@link #HERE} for a command run by its own process; the resident process ({@link ResidentServer}) runs
 * each client's command in the client's working directory on the renderer it keeps.
 *
 * @param workingDir the client's working directory (absolute), or null for this process's own
 * @param renderers  where the renderer comes from
 */
record RunContext(Path workingDir, Main.Renderers renderers) {
    /** This process's working directory, a renderer opened for the run. */
    static final RunContext HERE = new RunContext(null, Main.Renderers.PER_RUN);

    /** A path option as the command means it (unchanged in this process's own directory; null stays null). */
    Path resolve(Path p) {
        return workingDir == null || p == null ? p : workingDir.resolve(p);
    }

    /** An output prefix as the command means it. */
    String resolve(String prefix) {
        return workingDir == null ? prefix : workingDir.resolve(prefix).toString();
    }

    /** Files written, named as the user named their prefix: relative to the working directory where it was. */
    List<Path> asGiven(List<Path> files, String prefixAsGiven) {
        if (workingDir == null || Path.of(prefixAsGiven).isAbsolute()) {
            return files;
        }
        return files.stream().map(f -> f.startsWith(workingDir) ? workingDir.relativize(f) : f).toList();
    }
}
