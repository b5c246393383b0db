package dempano.batch;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Collectors;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVPrinter;
import dempano.io.IoMessages;

/**
 * {@code results.csv} of a batch: header {@code id,status,files,seconds,error}, one line per row
 * handled, written and flushed as soon as the row is done, so that a batch killed mid-way leaves the
 * lines of the rows that finished. {@code files} is the row's file names (relative to the output
 * folder) separated by spaces, {@code seconds} has millisecond resolution, {@code error} is one line
 * (empty when OK). UTF-8, CRLF line ends (RFC 4180), fields quoted where needed.
 *
 * <p>The file is locked while a run writes it (an advisory lock, which every batch takes): a second batch into the
 * same folder, in this process or another, is refused ({@link BatchFolderInUseException}) instead of truncating the
 * file under the first and interleaving lines with it, which lost one run's lines.
 */
final class ResultsCsv implements AutoCloseable {
    static final String[] HEADER = {"id", "status", "files", "seconds", "error"};
    private final CSVPrinter printer;
    private final Path directory;
    private final Path file;
    /** The file's identity (device and inode where the file system has them) when created; null where it has none. */
    private final Object fileKey;

    private ResultsCsv(CSVPrinter printer, Path file, Object fileKey) {
        this.printer = printer;
        this.file = file;
        this.directory = file.toAbsolutePath().getParent();
        this.fileKey = fileKey;
    }

    /**
     * Creates (or replaces) the file, locked for this run, and writes the header.
     *
     * @throws BatchFolderInUseException when another batch holds the file
     */
    static ResultsCsv create(Path file) throws IOException {
        java.nio.channels.FileChannel channel = java.nio.channels.FileChannel.open(file,
                java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.WRITE);
        java.nio.channels.FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (java.nio.channels.OverlappingFileLockException e) {
            lock = null; // held by a run of this process
        } catch (IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
        if (lock == null) {
            channel.close();
            throw new BatchFolderInUseException(file);
        }
        channel.truncate(0); // only now: the other run's lines are not touched
        BufferedWriter w = new BufferedWriter(java.nio.channels.Channels.newWriter(channel, StandardCharsets.UTF_8));
        CSVPrinter p = new CSVPrinter(w, CSVFormat.DEFAULT.builder().setHeader(HEADER).get());
        p.flush();
        return new ResultsCsv(p, file, Files.readAttributes(file, java.nio.file.attribute.BasicFileAttributes.class).fileKey());
    }

    /**
     * Throws when the file written is no longer at its path: removed, or replaced (its folder deleted or renamed during
     * the run). Lines written after that would go to a file nobody can open, and the batch would end as if all were
     * well.
     */
    private void checkStillThere() throws IOException {
        Object now;
        try {
            now = Files.readAttributes(file, java.nio.file.attribute.BasicFileAttributes.class).fileKey();
        } catch (IOException e) {
            throw new IOException("it is gone (its folder deleted or renamed during the run?): " + IoMessages.reason(e), e);
        }
        if (fileKey != null && !fileKey.equals(now)) {
            throw new IOException("it was replaced by another file during the run");
        }
    }

    /**
     * Appends a row's line and flushes it to the file.
     *
     * @throws IOException also when the file is no longer at its path (removed or replaced during the run)
     */
    synchronized void append(BatchResult r) throws IOException {
        checkStillThere();
        String files = r.files().stream().map(f -> relative(f)).collect(Collectors.joining(" "));
        printer.printRecord(BatchIds.printable(r.id()), // control characters (a NUL in a refused id) as ?
                r.status().word(), files, String.format(Locale.ROOT, "%.3f", r.seconds()),
                r.error() == null ? "" : r.error());
        printer.flush();
    }

    private String relative(Path f) {
        Path abs = f.toAbsolutePath().normalize();
        return abs.startsWith(directory) ? directory.relativize(abs).toString() : f.toString();
    }

    @Override
    public synchronized void close() throws IOException {
        printer.close();
    }
}
