package dempano.batch;

import java.io.IOException;
import java.nio.file.Path;

/** Another batch, in this process or another, is writing into the same output folder (its {@code results.csv} is locked). */
public final class BatchFolderInUseException extends IOException {
    public BatchFolderInUseException(Path resultsFile) {
        super("another batch is writing into " + resultsFile.toAbsolutePath().getParent() + " (its " + resultsFile.getFileName()
                + " is in use): wait for it to end or choose another output folder");
    }
}
