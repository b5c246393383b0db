package dempano.bench;

import dempano.dem.DemSource;
import dempano.dem.GeoTiffReader;
import dempano.dem.HgtReader;
import dempano.dem.HgtTile;
import dempano.dem.InMemoryDem;
import dempano.dem.PriorityDem;
import dempano.dem.TileId;
import dempano.dem.VoidFill;
import dempano.summits.Summit;
import dempano.summits.SummitReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Filling voids from a coarser second source, measured where the truth is known. The shared SRTM3
 * tile N46E008 has no void-free version, so its real voids cannot be scored against true heights;
 * instead its own void mask is shifted by 300 samples (~9 km / ~6.4 km) in each of four directions onto
 * valid data, those samples are held out (made voids), and each fill is scored against the held-out
 * SRTM3 samples and against the surveyed summits that lie in the shifted voids (all of whose 4×4
 * surrounding samples are valid SRTM3 data). The coarse source B is the tile averaged by GDAL
 * ({@code gdalwarp -r average}) onto a 30″ grid (10 × 10 SRTM3 samples a cell, voids ignored): an honest
 * 30″ source, but a kind one, since it is made from the very heights it must restore (a real coarse DEM,
 * e.g. GMTED2010, has its own errors and offsets). Needs gdalwarp on PATH.
 *
 * <p>Arguments: {@code --dem DIR}, {@code --summits FILE}, {@code --out DIR}; writes {@code coarse-fill.md}.
 */
public final class CoarseFillReport {
    private static final int[][] SHIFTS = {{0, 300}, {0, -300}, {300, 0}, {-300, 0}};

    private CoarseFillReport() {
    }

    public static void main(String[] args) {
        System.exit(ReportTool.run(new Command(), args));
    }

    /** The command line: {@code --dem DIR} (its N46E008.hgt), {@code --summits FILE}, {@code --out DIR}. */
    @picocli.CommandLine.Command(name = "coarseFillReport", mixinStandardHelpOptions = true,
            description = "Fills held-out voids of N46E008 from a 30\u2033 average of it; writes coarse-fill.md.")
    static final class Command implements java.util.concurrent.Callable<Integer> {
        @picocli.CommandLine.Mixin
        ReportTool.FillOptions o = new ReportTool.FillOptions();

        @Override
        public Integer call() throws Exception {
            Path folder = ReportTool.outputFolder(o.out);
            ReportTool.inputs(o.dem.resolve("N46E008.hgt"), o.summits);
            String md = report(o.dem.resolve("N46E008.hgt"), o.summits);
            dempano.io.AtomicFiles.write(folder.resolve("coarse-fill.md"), w -> w.write(md.getBytes(StandardCharsets.UTF_8)));
            System.out.print(md);
            return 0;
        }
    }

    /** The fills compared: name, and the second source's blend (null: no second source). */
    public record Method(String name, PriorityDem.Blend blend) {
    }

    /**
     * One fill's errors on the held-out voids.
     *
     * @param samples errors on the held-out samples, fill minus SRTM3, metres
     * @param summits errors on the surveyed summits in the held-out voids, DEM minus surveyed, metres
     */
    public record MethodErrors(Method method, VoidFillReport.Errors samples, VoidFillReport.Errors summits) {
    }

    /**
     * What the comparison measured.
     *
     * @param methods        thin-plate alone, B as is, B with the delta surface
     * @param heldOutSrtm    the held-out SRTM3 samples themselves against the summits (no void)
     * @param heldOutSamples samples held out, all shifts together
     */
    public record Measured(List<MethodErrors> methods, VoidFillReport.Errors heldOutSrtm, long heldOutSamples) {
        /** The errors with a second source blended as {@code blend} (null: no second source). */
        public MethodErrors of(PriorityDem.Blend blend) {
            return methods.stream().filter(m -> m.method().blend() == blend).findFirst().orElseThrow();
        }
    }

    static String report(Path hgt, Path summitFile) throws IOException, InterruptedException {
        return markdown(measure(hgt, summitFile), hgt, summitFile);
    }

    /** Holds out the shifted voids of {@code hgt}, fills them with each method and scores the fills. */
    public static Measured measure(Path hgt, Path summitFile) throws IOException, InterruptedException {
        TileId id = TileId.parseFileName(hgt.getFileName().toString());
        Path tmp = Files.createTempDirectory("coarse-fill");
        Path bFile = tmp.resolve(id.name() + ".tif");
        double half = 1.0 / 240;
        Process p = new ProcessBuilder("gdalwarp", "-q", "-overwrite", "-r", "average", "-tr", "" + 1.0 / 120, "" + 1.0 / 120,
                "-te", "" + (id.lonWestDeg() - half), "" + (id.latSouthDeg() - half), "" + (id.lonWestDeg() + 1 + half),
                "" + (id.latSouthDeg() + 1 + half), "-srcnodata", "-32768", "-dstnodata", "-32768", "-ot", "Float32",
                hgt.toString(), bFile.toString()).inheritIO().start();
        if (p.waitFor() != 0) {
            throw new IOException("gdalwarp failed");
        }
        HgtTile b = GeoTiffReader.read(bFile);
        HgtTile srtm = HgtReader.read(hgt);
        int n = srtm.samplesPerSide();
        float[] raw = new float[n * n];
        boolean[] voidAt = new boolean[n * n];
        for (int i = 0; i < n * n; i++) {
            voidAt[i] = srtm.isFilledVoid(i / n, i % n);
            raw[i] = voidAt[i] ? Float.NaN : srtm.heightMetres(i / n, i % n);
        }
        List<Summit> inside = SummitReader.read(summitFile, true).summits().stream()
                .filter(s -> s.latDeg() >= id.latSouthDeg() && s.latDeg() < id.latSouthDeg() + 1
                        && s.lonDeg() >= id.lonWestDeg() && s.lonDeg() < id.lonWestDeg() + 1).toList();
        List<Method> methods = List.of(new Method("thin-plate, no second source (the default with one source)", null),
                new Method("30″ source as is (bilinear, `--dem-blend as-is`)", PriorityDem.Blend.AS_IS),
                new Method("30″ source + delta surface (`--dem-blend delta-surface`, the default)", PriorityDem.Blend.DELTA_SURFACE));
        List<List<Double>> summitErr = new ArrayList<>(), sampleErr = new ArrayList<>();
        for (int k = 0; k < methods.size(); k++) {
            summitErr.add(new ArrayList<>());
            sampleErr.add(new ArrayList<>());
        }
        List<Double> srtmErr = new ArrayList<>();
        long heldOut = 0;
        for (int[] shift : SHIFTS) {
            boolean[] held = new boolean[n * n];
            float[] a = raw.clone();
            for (int r = 0; r < n; r++) {
                for (int c = 0; c < n; c++) {
                    int sr = r - shift[0], sc = c - shift[1];
                    if (sr >= 0 && sr < n && sc >= 0 && sc < n && voidAt[sr * n + sc] && !voidAt[r * n + c]) {
                        held[r * n + c] = true;
                        a[r * n + c] = Float.NaN;
                        heldOut++;
                    }
                }
            }
            HgtTile primary = HgtTile.of(id, n, a, "SRTM3 with held-out voids");
            DemSource aSource = new InMemoryDem("A", List.of(primary)), bSource = new InMemoryDem("B", List.of(b));
            float[][] filled = new float[methods.size()][];
            for (int k = 0; k < methods.size(); k++) {
                Method m = methods.get(k);
                HgtTile t = m.blend() == null ? primary
                        : new PriorityDem(List.of(aSource, bSource), VoidFill.DEFAULT, m.blend()).tile(id).orElseThrow();
                filled[k] = new float[n * n];
                for (int i = 0; i < n * n; i++) {
                    filled[k][i] = t.heightMetres(i / n, i % n);
                    if (held[i]) {
                        sampleErr.get(k).add((double) filled[k][i] - raw[i]);
                    }
                }
            }
            for (Summit s : inside) {
                double row = (id.latSouthDeg() + 1 - s.latDeg()) * (n - 1), col = (s.lonDeg() - id.lonWestDeg()) * (n - 1);
                int r0 = (int) Math.floor(row), c0 = (int) Math.floor(col);
                boolean anyHeld = false, anyVoid = false;
                for (int r = r0 - 1; r <= r0 + 2; r++) {
                    for (int c = c0 - 1; c <= c0 + 2; c++) {
                        if (r >= 0 && r < n && c >= 0 && c < n) {
                            anyHeld |= held[r * n + c];
                            anyVoid |= voidAt[r * n + c];
                        }
                    }
                }
                if (anyHeld && !anyVoid) {
                    srtmErr.add(VoidFillReport.bilinear(raw, n, row, col) - s.elevationMetres());
                    for (int k = 0; k < methods.size(); k++) {
                        summitErr.get(k).add(VoidFillReport.bilinear(filled[k], n, row, col) - s.elevationMetres());
                    }
                }
            }
        }
        List<MethodErrors> measured = new ArrayList<>();
        for (int k = 0; k < methods.size(); k++) {
            measured.add(new MethodErrors(methods.get(k),
                    VoidFillReport.Errors.of(sampleErr.get(k).stream().mapToDouble(Double::doubleValue).toArray()),
                    VoidFillReport.Errors.of(summitErr.get(k).stream().mapToDouble(Double::doubleValue).toArray())));
        }
        deleteQuietly(bFile);
        deleteQuietly(tmp);
        return new Measured(measured, VoidFillReport.Errors.of(srtmErr.stream().mapToDouble(Double::doubleValue).toArray()), heldOut);
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException e) {
            // a temporary file left behind is harmless
        }
    }

    static String markdown(Measured m, Path hgt, Path summitFile) {
        long heldOut = m.heldOutSamples();
        StringBuilder md = new StringBuilder();
        md.append("# Filling voids from a coarser second source\n\n");
        md.append("Generated by `gradle coarseFillReport` (`dempano.bench.CoarseFillReport`; needs GDAL's `gdalwarp`) from `")
                .append(hgt.getFileName()).append("` and `").append(summitFile.getFileName()).append("`.\n\n");
        md.append("There is no void-free version of the shared SRTM3 tiles, so the real voids cannot be scored against true heights. "
                + "Instead N46E008's own void mask is shifted by 300 samples in each of four directions onto valid data; those "
                + String.format(Locale.ROOT, "%,d", heldOut) + " samples (all four shifts together) are held out as voids and "
                + "filled, and each fill is scored against the held-out SRTM3 heights and against the surveyed summits in the "
                + "shifted voids (those whose 4×4 surrounding samples are all valid SRTM3 data; a summit can count once per shift). "
                + "The second source B is the tile averaged by `gdalwarp -r average` onto a 30″ grid: honest 30″ data, but kind, as it "
                + "is made from the very heights it must restore; a real coarse DEM (e.g. GMTED2010) has its own errors and offsets, "
                + "which the delta surface removes at each void's rim but not inside it. What this cannot show: how any fill does on "
                + "SRTM's real voids, which lie on the steepest, highest terrain (radar shadow), where a 30″ average flattens summits "
                + "most.\n\n"
                + "Fills: thin-plate alone (B unused); B's heights as they are (`--dem-blend as-is`, bilinear from its 30″ grid); "
                + "B's heights plus the difference A − B on the samples around the void, interpolated over the void by the "
                + "thin-plate fill (`--dem-blend delta-surface`). Errors in metres: fill minus held-out SRTM3 sample; bilinear "
                + "height at the summit's surveyed position minus its surveyed height.\n\n");
        md.append("| fill | held-out samples: mean | RMS | summits | median | mean | mean abs | RMS | worst | within ±50 m |\n");
        md.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (MethodErrors e : m.methods()) {
            VoidFillReport.Errors s = e.summits(), x = e.samples();
            md.append(String.format(Locale.ROOT, "| %s | %+.1f m | %.1f m | %d | %+.0f m | %+.0f m | %.0f m | %.0f m | %+.0f m | %.0f %% |%n",
                    e.method().name(), x.meanMetres(), x.rmsMetres(), s.count(), s.medianMetres(), s.meanMetres(),
                    s.meanAbsMetres(), s.rmsMetres(), s.worstMetres(), 100 * s.withinFiftyShare()));
        }
        VoidFillReport.Errors o = m.heldOutSrtm();
        md.append(String.format(Locale.ROOT, "| the held-out SRTM3 itself (no void) | 0 | 0 | %d | %+.0f m | %+.0f m | %.0f m | %.0f m | %+.0f m | %.0f %% |%n",
                o.count(), o.medianMetres(), o.meanMetres(), o.meanAbsMetres(), o.rmsMetres(), o.worstMetres(), 100 * o.withinFiftyShare()));
        return md.toString();
    }
}
