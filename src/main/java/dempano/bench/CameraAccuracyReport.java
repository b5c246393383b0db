package dempano.bench;

import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraPose;
import dempano.dem.DemDirectory;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * `gradle cameraAccuracyReport` (docs/camera-accuracy.md, docs/camera-accuracy.png): the OpenGL camera path
 * ({@code PanoramaRenderer.open(dem).render(CameraRequest)}, exact distances) against the CPU ray-cast reference
 * ({@code PanoramaRenderer.openReference(dem).render(CameraRequest)}: every pixel's own ray on the same triangulated
 * surface) on three real scenes × three lenses. Rendered pairs go to {@code build/camera-accuracy/}.
 */
@picocli.CommandLine.Command(name = "cameraAccuracyReport", mixinStandardHelpOptions = true,
        description = "Renders cameras on three real scenes with OpenGL and the CPU ray cast; writes camera-accuracy.md.")
public final class CameraAccuracyReport implements java.util.concurrent.Callable<Integer> {
    @picocli.CommandLine.Mixin
    ReportTool.SharedOptions io = new ReportTool.SharedOptions();
    @picocli.CommandLine.Option(names = "--size", paramLabel = "WxH", description = "Image size, pixels (default: ${DEFAULT-VALUE}).",
            defaultValue = "600x400")
    String size;

    private CameraAccuracyReport() { // run through main
    }

    /** Largest image side of the report, pixels: its reference casts every pixel's ray (about 10 s per 0.24 MP). */
    static final int MAX_SIDE_PX = 4000;

    /**
     * {@code WxH} (or {@code W×H}) as {width, height}.
     *
     * @throws IllegalArgumentException unless both are whole numbers in [16, {@link #MAX_SIDE_PX}]
     */
    static int[] size(String text) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\s*(\\d{1,6})\\s*[x×]\\s*(\\d{1,6})\\s*").matcher(text);
        int w = m.matches() ? Integer.parseInt(m.group(1)) : -1, h = m.matches() ? Integer.parseInt(m.group(2)) : -1;
        if (w < 16 || h < 16 || w > MAX_SIDE_PX || h > MAX_SIDE_PX) {
            throw new IllegalArgumentException("--size must be WIDTHxHEIGHT, each 16–" + MAX_SIDE_PX + " pixels, got '" + text + "'");
        }
        return new int[] {w, h};
    }

    /** A viewpoint on the shared tiles and where the cameras look (the 200 mm one at a distant skyline). */
    record Scene(String name, String description, double latDeg, double lonDeg, double rangeMetres,
                 CameraOrientation wide, CameraOrientation tele) {
    }

    static final List<Scene> SCENES = List.of(
            new Scene("eggishorn", "Eggishorn, Bernese Alps (N46E008), 80 km, looking east up the Rhône valley",
                    46.4314, 8.0942, 80_000, new CameraOrientation(75, -3, 0), new CameraOrientation(62, 0.5, 0)),
            new Scene("provence", "Cime du Cheiron, Alpes-Maritimes (N43E006/N43E007), 100 km, looking north-east to the"
                    + " Mercantour", 43.8167, 6.9667, 100_000, new CameraOrientation(40, -2, 0), new CameraOrientation(35, 0.8, 0)),
            new Scene("washington", "Mount Washington summit (N44W072), 100 km, looking north over the Northern"
                    + " Presidentials", 44.2706, -71.3033, 100_000, new CameraOrientation(350, -4, 0),
                    new CameraOrientation(330, -0.5, 0)));
    static final double[] LENSES_35MM = {24, 50, 200};

    /**
     * One comparison.
     *
     * @param relativeErrors |GL − reference| / reference per pixel both see as terrain, sorted
     * @param skyMismatch    pixels that one sees as sky and the other as terrain
     */
    record Row(String scene, double lensMm, int pixels, double[] relativeErrors, long skyMismatch,
               double glSeconds, double glCpuSeconds, double referenceSeconds, double referenceCpuSeconds) {
        double quantile(double q) {
            return dempano.util.Quantiles.ofSorted(relativeErrors, q);
        }

        double shareOver(double threshold) {
            int i = Arrays.binarySearch(relativeErrors, Math.nextUp(threshold));
            int firstOver = i >= 0 ? i : -i - 1;
            return relativeErrors.length == 0 ? Double.NaN : (relativeErrors.length - firstOver) / (double) relativeErrors.length;
        }
    }

    public static void main(String[] args) {
        System.exit(ReportTool.run(new CameraAccuracyReport(), args));
    }

    @Override
    public Integer call() throws IOException {
        int[] wh = size(size);
        int width = wh[0], height = wh[1];
        Path shared = io.shared, out = ReportTool.outputFolder(io.out), pictures = Path.of("build/camera-accuracy");
        Files.createDirectories(pictures);
        DemDirectory dem = new DemDirectory(shared.resolve("dem"));
        List<Row> rows = new ArrayList<>();
        try (PanoramaRenderer reference = PanoramaRenderer.openReference(dem); PanoramaRenderer gl = PanoramaRenderer.open(dem)) {
            for (Scene scene : SCENES) {
                for (double lens : LENSES_35MM) {
                    CameraOrientation o = lens >= 100 ? scene.tele() : scene.wide();
                    CameraRequest req = CameraRequest.of(CameraIntrinsics.fromFocal35mm(width, height, lens),
                            new CameraPose(scene.latDeg(), scene.lonDeg(), 0, Double.NaN, 2, o))
                            .withSettings(PanoramaRequest.at(scene.latDeg(), scene.lonDeg()).withRangeMetres(scene.rangeMetres())
                                    .withExactDistances(true));
                    double[] glClock = new double[2], refClock = new double[2];
                    CameraImage g = timed(() -> gl.render(req), glClock);
                    CameraImage r = timed(() -> reference.render(req), refClock);
                    String stem = scene.name() + "-" + (int) lens + "mm";
                    ImageIO.write(g.image(), "png", pictures.resolve(stem + "-gl.png").toFile());
                    ImageIO.write(r.image(), "png", pictures.resolve(stem + "-reference.png").toFile());
                    Row row = compare(scene.name(), lens, g.distanceArray(), r.distanceArray(), glClock, refClock);
                    rows.add(row);
                    System.out.println(line(row));
                }
            }
        }
        plot(rows, out.resolve("camera-accuracy.png"));
        String md = markdown(rows, width, height);
        dempano.io.AtomicFiles.write(out.resolve("camera-accuracy.md"), o -> o.write(md.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
        System.out.println("wrote " + out.resolve("camera-accuracy.md") + " and camera-accuracy.png; renders in " + pictures);
        return 0;
    }

    private interface Render {
        CameraImage get();
    }

    /** Runs a render; clock receives {wall seconds, process CPU seconds}. */
    private static CameraImage timed(Render render, double[] clock) {
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long cpu0 = os.getProcessCpuTime(), t0 = System.nanoTime();
        CameraImage img = render.get();
        clock[0] = (System.nanoTime() - t0) / 1e9;
        clock[1] = (os.getProcessCpuTime() - cpu0) / 1e9;
        return img;
    }

    static Row compare(String scene, double lensMm, float[] gl, float[] ref, double[] glClock, double[] refClock) {
        double[] rel = new double[gl.length];
        int n = 0;
        long skyMismatch = 0;
        for (int i = 0; i < gl.length; i++) {
            double a = gl[i], b = ref[i];
            if (Double.isNaN(a) || Double.isNaN(b)) {
                continue;
            }
            if (Double.isInfinite(a) || Double.isInfinite(b)) {
                skyMismatch += Double.isInfinite(a) != Double.isInfinite(b) ? 1 : 0;
                continue;
            }
            rel[n++] = Math.abs(a - b) / b;
        }
        double[] sorted = Arrays.copyOf(rel, n);
        Arrays.sort(sorted);
        return new Row(scene, lensMm, gl.length, sorted, skyMismatch, glClock[0], glClock[1], refClock[0], refClock[1]);
    }

    static String line(Row r) {
        return String.format(Locale.ROOT, "| %s | %.0f mm | %d | %.2f %% | %.2e | %.2e | %.3f %% | %.3f %% | %d (%.3f %%) | %.1f (%.1f) | %.1f (%.1f) |",
                r.scene(), r.lensMm(), r.relativeErrors().length, 100 * (1 - r.shareOver(0)), r.quantile(0.5), r.quantile(0.99),
                100 * r.shareOver(0.01), 100 * r.shareOver(0.05), r.skyMismatch(), 100.0 * r.skyMismatch() / r.pixels(),
                r.glSeconds(), r.glCpuSeconds(), r.referenceSeconds(), r.referenceCpuSeconds());
    }

    static String markdown(List<Row> rows, int width, int height) {
        StringBuilder s = new StringBuilder();
        s.append("# Camera view: OpenGL path against the ray-cast reference\n\n");
        s.append("Commit ").append(ReportTool.commit("**/camera-accuracy.md", "**/camera-accuracy.png")).append(". ");
        s.append(String.format(Locale.ROOT, """
                Generated by `gradle cameraAccuracyReport` (`dempano.bench.CameraAccuracyReport`; `-Psize=WxH` for another \
                image size; the rendered pairs go to `build/camera-accuracy/`).

                Each camera (%d × %d px, pinhole, 35 mm-equivalent focal lengths 24, 50 and 200 mm, eye 2 m above the DEM, \
                standard refraction 0.13, exact distances on) is rendered twice from the SRTM3 tiles in `../shared/dem`:
                by the OpenGL path (`PanoramaRenderer.open(dem).render(CameraRequest)`: perspective views around the \
                optical axis, resampled to the photo's pixels, each pixel's own ray intersected with the triangles seen \
                around it) and by the CPU reference (`PanoramaRenderer.openReference(dem).render(CameraRequest)`: every \
                pixel's own ray cast on the full-resolution triangulated surface, `dempano.reference.RayCastReference` with \
                `TerrainRayProbe`, double precision). The two share the surface, nothing else.

                Per pixel both see as terrain: relative distance error |GL − reference| / reference; "identical": the \
                share of those pixels whose float32 distances are equal (the GL path's exact distances intersect the \
                pixel's own ray with the triangle the views saw around it, in double precision, so where it found the \
                triangle the reference found the two agree to the last bit; the rest are pixels where the two found \
                different triangles). Sky disagreement: \
                pixels one sees as sky and the other as terrain (share of all pixels). Times: wall seconds (process CPU \
                seconds in brackets) on a 2-core machine shared with other work, so wall times are noisy; OpenGL is Mesa \
                llvmpipe (no GPU). Missing neighbouring tiles are sea level in both renders.

                Scenes:
                """, width, height));
        for (Scene sc : SCENES) {
            s.append(String.format(Locale.ROOT, "- **%s**: %s, %.4f°, %.4f°; 24 and 50 mm at heading %.0f°, pitch %.1f°; 200 mm at"
                            + " heading %.0f°, pitch %.1f°.\n", sc.name(), sc.description(), sc.latDeg(), sc.lonDeg(),
                    sc.wide().headingDeg(), sc.wide().pitchDeg(), sc.tele().headingDeg(), sc.tele().pitchDeg()));
        }
        s.append("\n| scene | lens | terrain pixels | identical | median | p99 | > 1 % | > 5 % | sky disagreement | GL s (CPU s) |"
                + " reference s (CPU s) |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (Row r : rows) {
            s.append(line(r)).append('\n');
        }
        s.append("\n![share of terrain pixels whose relative error exceeds x](camera-accuracy.png)\n");
        return s.toString();
    }

    /** The share of terrain pixels over each relative error, per case (log–log). */
    static void plot(List<Row> rows, Path png) throws IOException {
        XYChart chart = new XYChartBuilder().width(900).height(550).title("OpenGL camera vs ray-cast reference")
                .xAxisTitle("relative distance error").yAxisTitle("share of terrain pixels above").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        for (Row r : rows) {
            List<Double> x = new ArrayList<>(), y = new ArrayList<>();
            for (double e = 1e-7; e <= 1; e *= 1.5) {
                double share = r.shareOver(e);
                if (share > 0) {
                    x.add(e);
                    y.add(share);
                }
            }
            if (!x.isEmpty()) {
                chart.addSeries(r.scene() + " " + (int) r.lensMm() + " mm", x, y).setMarker(SeriesMarkers.NONE);
            }
        }
        BitmapEncoder.saveBitmap(chart, png.toString(), BitmapEncoder.BitmapFormat.PNG);
    }
}
