package dempano.bench;

import dempano.dem.HgtReader;
import dempano.dem.HgtTile;
import dempano.dem.TileId;
import dempano.dem.VoidFill;
import dempano.summits.Summit;
import dempano.summits.SummitList;
import dempano.summits.SummitReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * Compares the void fills ({@link VoidFill}) against surveyed summits: for every SRTM tile of a
 * directory and every summit of a list that lies in it, the DEM's bilinear height at the summit's
 * position minus its surveyed height, once per fill. A summit is "in or next to a void" when a void
 * sample lies within one sample of the 2×2 cell holding it (the 4×4 samples around it), "on valid
 * data" otherwise. Fills use no summit (nothing is tuned on them), so every summit is held out.
 * Writes {@code void-fill.md}; {@code gradle voidFillReport}.
 *
 * <p>Arguments: {@code --dem DIR} (default {@code ../shared/dem}), {@code --summits FILE} (default
 * {@code ../shared/peaks/alps.txt}), {@code --out DIR} (default {@code docs}).
 */
public final class VoidFillReport {
    private VoidFillReport() {
    }

    /** Height errors of one fill on one class of summits, metres (DEM minus surveyed). */
    public record Errors(int count, double medianMetres, double meanMetres, double meanAbsMetres, double rmsMetres,
                  double worstMetres, double withinFiftyShare) {
        public static Errors of(double[] e) {
            if (e.length == 0) {
                return new Errors(0, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);
            }
            double median = dempano.util.Quantiles.median(e);
            double sum = 0, abs = 0, sq = 0, worst = 0;
            int within = 0;
            for (double x : e) {
                sum += x;
                abs += Math.abs(x);
                sq += x * x;
                if (Math.abs(x) > Math.abs(worst)) {
                    worst = x;
                }
                if (Math.abs(x) <= 50) {
                    within++;
                }
            }
            return new Errors(e.length, median, sum / e.length, abs / e.length, Math.sqrt(sq / e.length), worst,
                    (double) within / e.length);
        }
    }

    /**
     * One fill's errors on the summits in or next to SRTM's real voids.
     *
     * @param fill   the fill
     * @param errors DEM minus surveyed height, metres
     * @param fillSeconds the fill's time over all tiles, seconds (the faster of two runs per tile)
     */
    public record FillErrors(VoidFill fill, Errors errors, double fillSeconds) {
    }

    /**
     * What the comparison measured.
     *
     * @param fills      one entry per {@link VoidFill}, in declaration order
     * @param validData  the summits on valid data (no fill involved)
     * @param perTileRows the per-tile table's rows, markdown
     * @param tilesUsed  tiles with at least one summit
     */
    public record Measured(List<FillErrors> fills, Errors validData, String perTileRows, int tilesUsed) {
        /** The errors of {@code fill}. */
        public Errors of(VoidFill fill) {
            return fills.stream().filter(f -> f.fill() == fill).findFirst().orElseThrow().errors();
        }
    }

    public static void main(String[] args) {
        System.exit(ReportTool.run(new Command(), args));
    }

    /** The command line: {@code --dem DIR}, {@code --summits FILE}, {@code --out DIR}. */
    @picocli.CommandLine.Command(name = "voidFillReport", mixinStandardHelpOptions = true,
            description = "Compares the void fills against surveyed summits in voids; writes void-fill.md.")
    static final class Command implements java.util.concurrent.Callable<Integer> {
        @picocli.CommandLine.Mixin
        ReportTool.FillOptions o = new ReportTool.FillOptions();

        @Override
        public Integer call() throws IOException {
            Path folder = ReportTool.outputFolder(o.out);
            ReportTool.inputs(o.dem, o.summits);
            String md = report(o.dem, o.summits);
            System.out.print(md);
            dempano.io.AtomicFiles.write(folder.resolve("void-fill.md"), w -> w.write(md.getBytes(StandardCharsets.UTF_8)));
            System.out.println("wrote " + folder.resolve("void-fill.md"));
            return 0;
        }
    }

    static String report(Path demDir, Path summitFile) throws IOException {
        return markdown(measure(demDir, summitFile), demDir, summitFile);
    }

    /** Fills every tile of {@code demDir} that holds a summit of {@code summitFile} with every fill and scores them. */
    public static Measured measure(Path demDir, Path summitFile) throws IOException {
        SummitList list = SummitReader.read(summitFile, true);
        List<Path> tiles;
        try (Stream<Path> s = Files.list(demDir)) {
            tiles = s.filter(p -> p.getFileName().toString().matches("[NS]\\d\\d[EW]\\d\\d\\d\\.hgt")).sorted().toList();
        }
        VoidFill[] fills = VoidFill.values();
        List<List<Double>> voidErrors = new ArrayList<>();
        for (VoidFill f : fills) {
            voidErrors.add(new ArrayList<>());
        }
        List<Double> validErrors = new ArrayList<>();
        long[] fillNanos = new long[fills.length];
        StringBuilder perTile = new StringBuilder();
        int tilesUsed = 0;
        for (Path file : tiles) {
            TileId id = TileId.parseFileName(file.getFileName().toString());
            List<Summit> inside = list.summits().stream().filter(s -> s.latDeg() >= id.latSouthDeg()
                    && s.latDeg() < id.latSouthDeg() + 1 && s.lonDeg() >= id.lonWestDeg()
                    && s.lonDeg() < id.lonWestDeg() + 1).toList();
            if (inside.isEmpty()) {
                continue;
            }
            HgtTile tile = HgtReader.read(file, VoidFill.IDW);
            int n = tile.samplesPerSide();
            float[] raw = new float[n * n];
            for (int r = 0; r < n; r++) {
                for (int c = 0; c < n; c++) {
                    raw[r * n + c] = tile.isFilledVoid(r, c) ? Float.NaN : tile.heightMetres(r, c);
                }
            }
            float[][] filled = new float[fills.length][];
            long[] tileNanos = new long[fills.length];
            for (int k = 0; k < fills.length; k++) {
                tileNanos[k] = Long.MAX_VALUE;
                for (int run = 0; run < 2; run++) { // the faster of two runs: the first includes JIT compiling
                    filled[k] = raw.clone();
                    long t0 = System.nanoTime();
                    fills[k].fill(filled[k], n);
                    tileNanos[k] = Math.min(tileNanos[k], System.nanoTime() - t0);
                }
                fillNanos[k] += tileNanos[k];
            }
            int inVoid = 0;
            for (Summit s : inside) {
                double row = (id.latSouthDeg() + 1 - s.latDeg()) * (n - 1), col = (s.lonDeg() - id.lonWestDeg()) * (n - 1);
                if (nearVoid(tile, row, col)) {
                    inVoid++;
                    for (int k = 0; k < fills.length; k++) {
                        voidErrors.get(k).add(bilinear(filled[k], n, row, col) - s.elevationMetres());
                    }
                } else {
                    validErrors.add(bilinear(filled[0], n, row, col) - s.elevationMetres());
                }
            }
            tilesUsed++;
            perTile.append(String.format(Locale.ROOT, "| %s | %.1f %% | %d | %d | %d |", id.name(),
                    100.0 * tile.voids().voidCells() / (n * n), tile.voids().largestRegionSpanSamples(), inside.size(), inVoid));
            for (long t : tileNanos) {
                perTile.append(String.format(Locale.ROOT, " %.2f |", t / 1e9));
            }
            perTile.append('\n');
        }
        List<FillErrors> measured = new ArrayList<>();
        for (int k = 0; k < fills.length; k++) {
            measured.add(new FillErrors(fills[k], Errors.of(voidErrors.get(k).stream().mapToDouble(Double::doubleValue).toArray()),
                    fillNanos[k] / 1e9));
        }
        return new Measured(measured, Errors.of(validErrors.stream().mapToDouble(Double::doubleValue).toArray()),
                perTile.toString(), tilesUsed);
    }

    static String markdown(Measured m, Path demDir, Path summitFile) {
        StringBuilder b = new StringBuilder();
        b.append("# Void fills against surveyed summits\n\n");
        b.append("Generated by `gradle voidFillReport` (`dempano.bench.VoidFillReport`) from the SRTM tiles in `")
                .append(demDir).append("` and the summits in `").append(summitFile).append("`.\n\n");
        b.append("Error = the DEM's bilinear height at the summit's surveyed position minus its surveyed height, metres. ")
                .append("A summit is *in or next to a void* when a void sample lies among the 4×4 samples around it ")
                .append("(within one sample of the cell holding it). The fills use no summit, so every summit is held out. ")
                .append("SRTM3 averages each ~90 m cell, so even summits on valid data come out low.\n\n")
                .append("The fills (`--void-fill`, `dempano.dem.VoidFill`; all deterministic, valid samples untouched):\n\n")
                .append("- `idw`: inverse-distance weighting of the nearest valid sample along eight directions, as GDAL's ")
                .append("FillNodata; the default before this comparison.\n")
                .append("- `laplace`: harmonic (diffusion) fill, the smoothest membrane over the void; by the maximum principle ")
                .append("no filled sample rises above the void's rim.\n")
                .append("- `thin-plate` (default): minimum bending (squared discrete Laplacian) with slight tension ")
                .append("(10⁻³ × squared slope), so the slopes around a void carry on into it and a summit the rim rises ")
                .append("towards is rebuilt above the rim. Solved by conjugate gradients started from the same problem on ")
                .append("grids coarsened 2:1.\n\n")
                .append("Where a second, lower-priority DEM has data (`--dem-dir A --dem-dir B`) it fills A's voids before ")
                .append("any of these fills; the shared SRTM3 tiles have no second source, so that is not measured here; `docs/coarse-fill.md` (`gradle coarseFillReport`) measures a 30″ second source on held-out voids.\n\n");
        b.append("| fill | summits | median | mean | mean abs | RMS | worst | within ±50 m | fill time, all tiles |\n");
        b.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (FillErrors f : m.fills()) {
            row(b, "`" + f.fill().cliName() + "`" + (f.fill() == VoidFill.DEFAULT ? " (default)" : ""), f.errors(),
                    String.format(Locale.ROOT, "%.2f s", f.fillSeconds()));
        }
        row(b, "summits on valid data (no fill involved)", m.validData(), "");
        b.append("\nPer tile (").append(m.tilesUsed()).append(" tiles with summits; fill times in seconds, one thread, ")
                .append("the faster of two runs in one JVM):\n\n");
        b.append("| tile | voids | largest void span, samples | summits | in/next to voids |");
        for (FillErrors f : m.fills()) {
            b.append(' ').append(f.fill().cliName()).append(" s |");
        }
        b.append("\n|---|---:|---:|---:|---:|");
        for (FillErrors f : m.fills()) {
            b.append("---:|");
        }
        b.append('\n').append(m.perTileRows());
        return b.toString();
    }

    private static void row(StringBuilder b, String name, Errors e, String time) {
        b.append(String.format(Locale.ROOT, "| %s | %d | %+.0f m | %+.0f m | %.0f m | %.0f m | %+.0f m | %.0f %% | %s |%n",
                name, e.count(), e.medianMetres(), e.meanMetres(), e.meanAbsMetres(), e.rmsMetres(), e.worstMetres(),
                100 * e.withinFiftyShare(), time));
    }

    /** True if a void sample lies among the 4×4 samples around fractional (row, col). */
    static boolean nearVoid(HgtTile t, double row, double col) {
        int n = t.samplesPerSide();
        int r0 = (int) Math.floor(row), c0 = (int) Math.floor(col);
        for (int r = r0 - 1; r <= r0 + 2; r++) {
            for (int c = c0 - 1; c <= c0 + 2; c++) {
                if (r >= 0 && r < n && c >= 0 && c < n && t.isFilledVoid(r, c)) {
                    return true;
                }
            }
        }
        return false;
    }

    static double bilinear(float[] h, int n, double row, double col) {
        int r = Math.max(0, Math.min(n - 2, (int) Math.floor(row)));
        int c = Math.max(0, Math.min(n - 2, (int) Math.floor(col)));
        double fr = row - r, fc = col - c;
        return dempano.util.Bilinear.interpolate(h[r * n + c], h[r * n + c + 1], h[(r + 1) * n + c],
                h[(r + 1) * n + c + 1], fr, fc);
    }
}
