package dempano.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;

/** Plain-words reasons for I/O failures, for messages that already name the file concerned. */
public final class IoMessages {
    private IoMessages() {
    }

    /**
     * An I/O failure for a message that does not name the file: the file the failure names and the {@link #reason}
     * ("…/afile: something of that name is in the way"); otherwise the exception's message (a bare path, for some).
     */
    public static String describe(IOException e) {
        return e instanceof FileSystemException fs && fs.getFile() != null ? fs.getFile() + ": " + reason(e) : e.getMessage();
    }

    /** Why an I/O operation failed, without the path (the caller names the final file). */
    public static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file or folder";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException) {
            return "something of that name is in the way";
        }
        if (e instanceof DirectoryNotEmptyException) {
            return "a folder of that name is in the way";
        }
        if (e instanceof NotDirectoryException) {
            return "a file stands where a folder is needed";
        }
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            return fs.getReason().toLowerCase(java.util.Locale.ROOT); // e.g. "no space left on device"
        }
        String m = e.getMessage();
        m = m == null || m.isBlank() ? e.getClass().getSimpleName() : m;
        // An encoder's own words ("I/O error writing PNG file!") hide the stream's: add the cause's reason.
        if (e.getCause() instanceof IOException cause && cause != e) {
            String why = reason(cause);
            if (!m.contains(why)) {
                m = m.replaceFirst("[!.]$", "") + ": " + why;
            }
        }
        return m;
    }
}
