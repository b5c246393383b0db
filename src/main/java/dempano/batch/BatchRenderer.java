package dempano.batch;

import dempano.PanoramaRenderer;
import dempano.io.PanoramaWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * Renders many panoramas in one process: one {@link PanoramaRenderer} (its tiles, patch deviations
 * and meshes reused from row to row), each row's files written as one set under an output folder,
 * and {@code results.csv} there. For a Java caller:
 *
 * <pre>{@code
 * try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(Path.of("dem")))) {
 *     List<BatchRow> rows = ViewpointCsv.read(Path.of("viewpoints.csv"), PanoramaRequest.at(0, 0)).rows();
 *     BatchRun run = new BatchRenderer(r, Path.of("out"), PanoramaWriter.Options.DEFAULT).newRun(rows, listener);
 *     BatchSummary s = run.run();   // run.cancel() from another thread stops after the current row
 * }
 * }</pre>
 *
 * The renderer stays the caller's: the batch does not close it.
 */
public final class BatchRenderer {
    private final PanoramaRenderer renderer;
    private final Path outDir;
    private final PanoramaWriter.Options writing;

    /**
     * @param renderer the renderer every row uses (not closed by the batch)
     * @param outDir   an existing folder: row {@code id} writes {@code outDir/<id>.*}, the batch {@code outDir/results.csv}
     * @param writing  file options for every row (summits are not supported here: pass none)
     */
    public BatchRenderer(PanoramaRenderer renderer, Path outDir, PanoramaWriter.Options writing) {
        this.renderer = Objects.requireNonNull(renderer, "renderer");
        this.outDir = Objects.requireNonNull(outDir, "outDir");
        this.writing = Objects.requireNonNull(writing, "writing");
        if (writing.summits() != null) {
            throw new IllegalArgumentException("summit sightings are per panorama: a batch writes none");
        }
    }

    /** A run over these rows, not yet started: call {@link BatchRun#run()} on the thread that should do the work. */
    public BatchRun newRun(List<BatchRow> rows, BatchListener listener) {
        return new BatchRun(renderer, outDir, writing, rows, listener == null ? new BatchListener() { } : listener);
    }

    /** Runs the rows to the end on the calling thread; see {@link BatchRun#run()}. */
    public BatchSummary render(List<BatchRow> rows, BatchListener listener) throws java.io.IOException {
        return newRun(rows, listener).run();
    }

    /** The file with one line per row handled. */
    public static Path resultsFile(Path outDir) {
        return outDir.resolve("results.csv");
    }
}
