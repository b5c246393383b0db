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

/**
 * {@code results.csv} of a batch: header {@code id,status,files,seconds,error}, one line per row
 * handled, written and flushed as soon as the row is done, so that a batch killed mid-way leaves the
 * lines of the rows that finished. {@code files} is the row's file names (relative to the output
 * folder) separated by spaces, {@code seconds} has millisecond resolution, {@code error} is one line
 * (empty when OK). UTF-8, CRLF line ends (RFC 4180), fields quoted where needed.
 */
final class ResultsCsv implements AutoCloseable {
    static final String[] HEADER = {"id", "status", "files", "seconds", "error"};
    private final CSVPrinter printer;
    private final Path directory;

    private ResultsCsv(CSVPrinter printer, Path directory) {
        this.printer = printer;
        this.directory = directory;
    }

    /** Creates (or replaces) the file and writes the header. */
    static ResultsCsv create(Path file) throws IOException {
        BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        CSVPrinter p = new CSVPrinter(w, CSVFormat.DEFAULT.builder().setHeader(HEADER).get());
        p.flush();
        Path dir = file.toAbsolutePath().getParent();
        return new ResultsCsv(p, dir);
    }

    /** Appends a row's line and flushes it to the file. */
    synchronized void append(BatchResult r) throws IOException {
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
