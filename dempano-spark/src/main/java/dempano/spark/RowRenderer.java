package dempano.spark;

import dempano.PanoramaRenderer;
import dempano.batch.BatchRenderer;
import dempano.batch.BatchResult;
import dempano.batch.BatchRow;
import dempano.batch.BatchSummary;
import dempano.batch.ViewpointCsv;
import dempano.batch.ViewpointCsvException;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVPrinter;
import org.apache.hadoop.fs.FileSystem;

/**
 * Renders one row on an executor exactly as {@code dempano batch} does: the row's cells are read by
 * {@link ViewpointCsv} (same columns, checks and messages), rendered by a {@link BatchRenderer} on the
 * executor's shared renderer into a local temporary folder (the row's files complete or absent), and
 * the files copied to the output folder through Hadoop's FileSystem API, {@code <id>.json} last. Every
 * failure becomes the row's error; nothing is thrown.
 */
final class RowRenderer {
    private final JobSettings settings;
    private FileSystem fs;
    private org.apache.hadoop.fs.Path out;

    RowRenderer(JobSettings settings) {
        this.settings = settings;
    }

    /** What became of a row: as a line of {@code results.csv}. */
    record Outcome(String id, String status, String files, double seconds, String error) {
        static Outcome error(String id, String message, double seconds) {
            return new Outcome(id, "error", "", seconds, message);
        }
    }

    /**
     * @param id          the row's id cell (null read as empty)
     * @param cells       the viewpoint columns present in the table, name → cell text (null = empty)
     * @param duplicateOf where the id was first seen when this row repeats it, else null
     */
    Outcome render(String id, Map<String, String> cells, String duplicateOf) {
        long t0 = System.nanoTime();
        String shownId = id == null ? "" : id;
        BatchRow row;
        try {
            row = row(shownId, cells, duplicateOf);
        } catch (RuntimeException | ViewpointCsvException e) {
            return Outcome.error(shownId, "row '" + shownId + "': " + message(e), seconds(t0));
        }
        if (!row.valid()) {
            return Outcome.error(shownId, RowRenderer.ViewpointCsvOneLine.of(row.error()), seconds(t0));
        }
        Path tmp = null;
        try {
            tmp = Files.createTempDirectory("dempano-row-");
            row = localImage(row, cells.get(ViewpointCsv.IMAGE), tmp);
            PanoramaRenderer r = ExecutorRenderer.get(settings);
            BatchSummary s = new BatchRenderer(r, tmp, settings.writing()).render(List.of(row), null);
            BatchResult result = s.results().get(0);
            if (s.fatal() != null) {
                ExecutorRenderer.discard(settings, r);
            }
            if (!result.ok()) {
                return Outcome.error(shownId, result.error(), seconds(t0));
            }
            List<String> names = new ArrayList<>();
            for (Path f : result.files()) { // <id>.json last: a row with its json in place is complete
                names.add(f.getFileName().toString());
            }
            copy(result.files());
            return new Outcome(shownId, "ok", String.join(" ", names), seconds(t0), null);
        } catch (Throwable e) { // a failing row is recorded, never fails the job
            if (e instanceof VirtualMachineError && !(e instanceof OutOfMemoryError)) {
                throw (VirtualMachineError) e;
            }
            return Outcome.error(shownId, "row '" + shownId + "': " + message(e), seconds(t0));
        } finally {
            if (tmp != null) {
                deleteQuietly(tmp);
            }
        }
    }

    /**
     * The row as {@code dempano batch} reads it: the cells go through {@link ViewpointCsv} as a one-row file,
     * so that columns, defaults, checks and messages are the same; messages name the row by id.
     */
    BatchRow row(String id, Map<String, String> cells, String duplicateOf) throws ViewpointCsvException {
        String where = "row '" + id + "': ";
        if (duplicateOf != null && dempano.batch.BatchIds.problem(id) == null) {
            return BatchRow.invalid(0, id, where + "duplicate id '" + id + "' (first at " + duplicateOf + ")");
        }
        StringWriter text = new StringWriter();
        try (CSVPrinter p = new CSVPrinter(text, CSVFormat.DEFAULT)) {
            p.printRecord(cells.keySet());
            p.printRecord(cells.entrySet().stream().map(e -> e.getValue() == null ? ""
                    : e.getKey().equals(ViewpointCsv.IMAGE) ? fromTableFolder(e.getValue()) : e.getValue()).toList());
        } catch (IOException e) {
            throw new IllegalStateException(e); // in memory
        }
        List<BatchRow> rows = ViewpointCsv.parse("row '" + id + "'", text.toString(), settings.defaults()).rows();
        if (rows.size() != 1) {
            return BatchRow.invalid(0, id, where + "no values");
        }
        BatchRow r = rows.get(0);
        if (r.valid()) {
            return new BatchRow(0, r.id(), r.request(), r.photo(), null);
        }
        String e = r.error();
        return BatchRow.invalid(0, id, where + (e.startsWith("line 2: ") ? e.substring("line 2: ".length()) : e));
    }

    /**
     * An image cell as {@code dempano batch} reads it: a relative path is relative to the table's folder
     * ({@link JobSettings#tableDir}; it was the executor's working directory, where another photo of that name was
     * taken silently). Absolute paths and URIs as they are.
     */
    String fromTableFolder(String image) {
        String cell = image.strip();
        if (settings.tableDir == null || cell.isEmpty() || Hadoop.isUri(cell) || Path.of(cell).isAbsolute()) {
            return image;
        }
        return Hadoop.isUri(settings.tableDir)
                ? new org.apache.hadoop.fs.Path(new org.apache.hadoop.fs.Path(settings.tableDir), cell).toString()
                : Path.of(settings.tableDir).resolve(cell).toString();
    }

    /**
     * A photo row whose image is a Hadoop URI ({@code hdfs://…}, {@code s3a://…}, {@code file:/…}) with the image
     * copied into the row's local folder first; other rows as they are (a plain path is a local file of the node).
     */
    private BatchRow localImage(BatchRow row, String imageCell, Path tmp) throws IOException {
        if (row.photo() == null || imageCell == null || !Hadoop.isUri(imageCell)) {
            return row;
        }
        org.apache.hadoop.fs.Path remote = new org.apache.hadoop.fs.Path(imageCell.strip());
        Path local = tmp.resolve("image-" + remote.getName());
        FileSystem imageFs = remote.getFileSystem(Hadoop.configuration(settings.hadoop));
        try {
            imageFs.copyToLocalFile(false, remote, new org.apache.hadoop.fs.Path(local.toUri()), true);
        } catch (IOException e) {
            throw new IOException("cannot read the image " + imageCell.strip() + ": " + e.getMessage(), e);
        }
        return new BatchRow(row.lineNumber(), row.id(), row.request(),
                new dempano.batch.BatchPhoto(local, row.photo().overrides(), row.photo().ranges()), null);
    }

    private void copy(List<Path> files) throws IOException {
        if (fs == null) {
            out = new org.apache.hadoop.fs.Path(settings.outDir);
            fs = out.getFileSystem(Hadoop.configuration(settings.hadoop));
            if (fs instanceof org.apache.hadoop.fs.LocalFileSystem local) {
                fs = local.getRaw(); // no .crc file beside each output on a local or mounted disk
            }
        }
        // A folder in the way of a file: copying would put the file inside it, and the row would say "ok".
        for (Path f : files) {
            org.apache.hadoop.fs.Path target = new org.apache.hadoop.fs.Path(out, f.getFileName().toString());
            if (fs.exists(target) && fs.getFileStatus(target).isDirectory()) {
                throw new IOException("cannot write " + target + ": a folder of that name is in the way");
            }
        }
        // An earlier set's <id>.json goes first: until the new one is copied (last), the row's set is not claimed complete
        // (a failed copy left new files beside the old json).
        Path json = files.get(files.size() - 1);
        if (json.getFileName().toString().endsWith(".json")) {
            fs.delete(new org.apache.hadoop.fs.Path(out, json.getFileName().toString()), false);
        }
        for (Path f : files) {
            fs.copyFromLocalFile(false, true, new org.apache.hadoop.fs.Path(f.toUri()),
                    new org.apache.hadoop.fs.Path(out, f.getFileName().toString()));
        }
    }

    private static void deleteQuietly(Path dir) {
        try (Stream<Path> s = Files.walk(dir)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    // a temporary file left behind
                }
            });
        } catch (IOException e) {
            // a temporary folder left behind
        }
    }

    private static String message(Throwable e) {
        String m = e.getMessage() == null || e.getMessage().isBlank() ? e.toString() : e.getMessage();
        return ViewpointCsvOneLine.of(m);
    }

    private static double seconds(long since) {
        return (System.nanoTime() - since) / 1e9;
    }

    /** One line, as results.csv wants. */
    static final class ViewpointCsvOneLine {
        static String of(String s) {
            return s == null ? "" : s.replaceAll("\\s*\\R\\s*", " ").strip();
        }
    }
}
