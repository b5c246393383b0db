package dempano;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assumptions;

/** The real data in ../shared (never copied into the project). Tests needing it are skipped, with the reason, where it is absent. */
public final class SharedData {
    private SharedData() {
    }

    public static Path root() {
        String env = System.getenv("DEMPANO_SHARED");
        return env != null ? Path.of(env) : Path.of("..", "shared");
    }

    /** ../shared/dem, or a skipped test saying why. */
    public static Path demDir() {
        Path dir = root().resolve("dem");
        Assumptions.assumeTrue(Files.isDirectory(dir),
                "real SRTM tiles not found at " + dir.toAbsolutePath() + " (set DEMPANO_SHARED); test skipped");
        return dir;
    }

    public static Path demFile(String name) {
        Path p = demDir().resolve(name);
        Assumptions.assumeTrue(Files.isRegularFile(p), p.toAbsolutePath() + " not found; test skipped");
        return p;
    }

    /** A file under ../shared (e.g. "peaks/alps.txt"), or a skipped test saying why. */
    public static Path require(String relative) {
        Path p = root().resolve(relative);
        Assumptions.assumeTrue(Files.isRegularFile(p), p.toAbsolutePath() + " not found (set DEMPANO_SHARED); test skipped");
        return p;
    }
}
