package dempano.cli;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.dem.DemDirectory;
import dempano.dem.DemSource;
import dempano.dem.DemoTerrain;
import dempano.panorama.DepthMode;
import dempano.panorama.DistanceComparison;
import dempano.panorama.Panorama;
import java.awt.Color;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The accuracy report: every scene rendered by the CPU reference (the etalon) and by the GL path
 * over a sweep of settings; per setting the render time and the distance and skyline errors against
 * the reference. Writes {@code accuracy.md} and {@code accuracy.png} into the output folder.
 *
 * <p>Run: {@code gradle accuracyReport} (or {@code java -cp … dempano.cli.AccuracyReport --shared ../shared --out docs}).
 */
public final class AccuracyReport {
    /** One scene: a viewpoint in a DEM. */
    record Scene(String name, String description, DemSource dem, double latDeg, double lonDeg, double rangeMetres) {
    }

    /** One GL setting. */
    record Setting(DepthMode mode, double supersampling, int views, double lodPx) {
        Setting(DepthMode mode, double supersampling, int views) {
            this(mode, supersampling, views, dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX);
        }

        String label() {
            return mode.optionName() + ", ss " + fmt(supersampling) + ", " + views + " views, LOD " + fmt(lodPx) + " px";
        }
    }

    /** A measured row. */
    record Row(Scene scene, Setting setting, double seconds, DistanceComparison error) {
    }

    static final List<Setting> SETTINGS = List.of(
            new Setting(DepthMode.STANDARD_24, 1, 8),
            new Setting(DepthMode.STANDARD_24, 2, 8),
            new Setting(DepthMode.REVERSED_32F, 1, 8),
            new Setting(DepthMode.REVERSED_32F, 2, 8),
            new Setting(DepthMode.SHADER_RANGE, 0.5, 8),
            new Setting(DepthMode.SHADER_RANGE, 1, 8),
            new Setting(DepthMode.SHADER_RANGE, 1, 12),
            new Setting(DepthMode.SHADER_RANGE, 2, 8),
            // The level-of-detail axis (default shader, ss 1, 8 views): full resolution to a coarse bound.
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 0),
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 0.25),
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 1),
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 2));

    private AccuracyReport() {
    }

    public static void main(String[] args) throws IOException {
        Path shared = Path.of("../shared"), out = Path.of("docs");
        for (int i = 0; i + 1 < args.length; i += 2) {
            switch (args[i]) {
                case "--shared" -> shared = Path.of(args[i + 1]);
                case "--out" -> out = Path.of(args[i + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        List<Scene> scenes = new ArrayList<>();
        double[] demo = DemoTerrain.viewpoint();
        scenes.add(new Scene("synthetic", "demo massifs (generated, analytic heights), 60 km",
                new DemDirectory(DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR)), demo[0], demo[1], 60_000));
        Path dem = shared.resolve("dem");
        if (Files.isDirectory(dem)) {
            DemDirectory real = new DemDirectory(dem);
            scenes.add(new Scene("provence", "Cime du Cheiron, Alpes-Maritimes (N43E006/N43E007), 100 km",
                    real, 43.8167, 6.9667, 100_000));
            scenes.add(new Scene("washington", "Mount Washington summit (N44W072), 100 km",
                    real, 44.2706, -71.3033, 100_000));
        } else {
            System.err.println("accuracyReport: " + dem + " absent: real scenes left out");
        }
        Files.createDirectories(out);
        List<Row> rows = new ArrayList<>();
        Map<Scene, Double> referenceSeconds = new LinkedHashMap<>();
        // Held open for the whole report: the shared GL context is then created once (re-creating it
        // after the last holder closed failed once on llvmpipe: see the issue notes).
        PanoramaRenderer keepAlive = PanoramaRenderer.open(scenes.get(0).dem());
        String glName = keepAlive.glRenderer();
        for (Scene scene : scenes) {
            PanoramaRequest base = PanoramaRequest.at(scene.latDeg(), scene.lonDeg()).withRangeMetres(scene.rangeMetres());
            Panorama ref;
            try (PanoramaRenderer cpu = PanoramaRenderer.openReference(scene.dem())) {
                cpu.render(base); // warm-up: tiles decoded, JIT
                long t = System.nanoTime();
                ref = cpu.render(base);
                referenceSeconds.put(scene, (System.nanoTime() - t) / 1e9);
            }
            try (PanoramaRenderer gl = PanoramaRenderer.open(scene.dem())) {
                gl.render(base); // warm-up
                for (Setting s : SETTINGS) {
                    PanoramaRequest req = base.withDepthMode(s.mode()).withSupersampling(s.supersampling()).withViews(s.views())
                            .withLodErrorPx(s.lodPx());
                    long t = System.nanoTime();
                    Panorama p = gl.render(req);
                    double seconds = (System.nanoTime() - t) / 1e9;
                    DistanceComparison c = DistanceComparison.of(p.distanceArray(), ref.distanceArray(), p.widthPx());
                    rows.add(new Row(scene, s, seconds, c));
                    System.err.printf(Locale.ROOT, "%-10s %-32s %6.2f s  median %.2e  p99 %.2e  skyline %.3f px%n",
                            scene.name(), s.label(), seconds, c.medianRelative(), c.p99Relative(), c.skylineMeanAbsPx());
                }
            }
        }
        String summitSection = "";
        Path alps = shared.resolve("peaks").resolve("alps.txt");
        if (Files.isDirectory(dem) && Files.isRegularFile(alps)) {
            dempano.summits.SummitList list = dempano.summits.SummitReader.read(alps, false);
            List<Scene> summitScenes = List.of(scenes.get(1),
                    new Scene("eggishorn", "Eggishorn, Bernese Alps (N46E008), 80 km", new DemDirectory(dem), 46.4314, 8.0942, 80_000));
            summitSection = summits(summitScenes, list);
        }
        Files.writeString(out.resolve("accuracy.md"), markdown(scenes, rows, referenceSeconds, glName) + summitSection,
                StandardCharsets.UTF_8);
        plot(scenes, rows, out.resolve("accuracy.png"));
        keepAlive.close();
        System.err.println("accuracyReport: wrote " + out.resolve("accuracy.md") + " and " + out.resolve("accuracy.png"));
    }

    static String markdown(List<Scene> scenes, List<Row> rows, Map<Scene, Double> refSeconds, String glName) {
        StringBuilder b = new StringBuilder();
        b.append("# Accuracy: error against run time\n\n");
        b.append("Generated by `gradle accuracyReport` (class `dempano.cli.AccuracyReport`); do not edit by hand.\n\n");
        b.append("- Machine: ").append(Runtime.getRuntime().availableProcessors()).append(" cores, OpenGL renderer `")
                .append(glName).append("`, Java ").append(System.getProperty("java.version")).append(".\n");
        b.append("- Every panorama: 360° at 20 px/°, elevation −30°…30° (7200 × 1200 px), refraction k = 0.13, eye 2 m above the DEM.\n");
        b.append("- Truth: the CPU reference renderer (`--renderer reference`): for every pixel centre, the exact distance to the\n"
                + "  first point of the same triangulated surface (double precision horizon sweep, no GL).\n");
        b.append("- Time: one warm `PanoramaRenderer.render` call (tiles cached, JIT warm), all stages included.\n");
        b.append("- Relative error |d − d_ref| / d_ref over pixels where both see terrain; \"> 5 %\" is the share of pixels where\n"
                + "  a different surface was seen; skyline: per column, |topmost terrain row − reference's|, pixels.\n\n");
        for (Scene scene : scenes) {
            b.append("## ").append(scene.name()).append(": ").append(scene.description()).append("\n\n");
            b.append(String.format(Locale.ROOT, "Reference (CPU) render time: %.2f s. Viewpoint %.4f, %.4f.%n%n",
                    refSeconds.get(scene), scene.latDeg(), scene.lonDeg()));
            b.append("| setting | time s | median | p95 | p99 | max | > 5 % | median > 20 km | p99 > 20 km | sky mismatch px | skyline mean px | skyline max px | columns off |\n");
            b.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            for (Row r : rows) {
                if (r.scene() != scene) {
                    continue;
                }
                DistanceComparison c = r.error();
                b.append(String.format(Locale.ROOT, "| %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %d | %.3f | %d | %s |%n",
                        r.setting().label(), r.seconds(), pct(c.medianRelative()), pct(c.p95Relative()), pct(c.p99Relative()),
                        pct(c.maxRelative()), pct(c.shareOver5Percent()), pct(c.farMedianRelative()), pct(c.farP99Relative()),
                        c.skyMismatchPixels(), c.skylineMeanAbsPx(),
                        c.skylineMaxAbsPx(), pct(c.skylineColumnsOff())));
            }
            b.append('\n');
        }
        b.append("![error against run time](accuracy.png)\n");
        return b.toString();
    }

    /** The thesis's metrics on surveyed summits, for the default GL setting. */
    static String summits(List<Scene> scenes, dempano.summits.SummitList list) {
        StringBuilder b = new StringBuilder("\n## Distances to surveyed summits (the thesis's metrics)\n\n");
        b.append("Summits of `peaks/alps.txt` within range that the panorama sees (`SummitProjector`'s tolerance), default\n"
                + "settings (shader depth, ss 1, 8 views). Estimate: the distance map where a person clicking on the peak reads it\n"
                + "(the first terrain pixel at or below the summit's pixel); truth: the straight-line distance to the surveyed\n"
                + "summit. Differences come from the DEM (SRTM3 summits flattened or void-filled, positions on a 90 m grid), not\n"
                + "from the renderer, whose own error is in the tables above. Summits whose estimate misses by more than\n"
                + "max(300 m, 2 %) count as hidden, so this sample is truncated there (the thesis had 13 % MAPE).\n\n");
        b.append("| scene | summits in range | visible | RMSE m | MAPE | RSE | R² |");
        for (double t : dempano.summits.DistanceMetrics.THRESHOLDS) {
            b.append(String.format(Locale.ROOT, " < %.0f %% |", t * 100));
        }
        b.append("\n|---|---:|---:|---:|---:|---:|---:|");
        b.append("---:|".repeat(dempano.summits.DistanceMetrics.THRESHOLDS.length)).append('\n');
        for (Scene scene : scenes) {
            try (PanoramaRenderer gl = PanoramaRenderer.open(scene.dem())) {
                Panorama p = gl.render(PanoramaRequest.at(scene.latDeg(), scene.lonDeg()).withRangeMetres(scene.rangeMetres()));
                var sightings = p.summits(list);
                List<Double> est = new ArrayList<>(), truth = new ArrayList<>();
                for (var s : sightings) {
                    if (s.visible()) {
                        est.add(s.seenDistanceMetres());
                        truth.add(s.slantMetres());
                    }
                }
                var m = dempano.summits.DistanceMetrics.of(est, truth);
                b.append(String.format(Locale.ROOT, "| %s | %d | %d | %.0f | %s | %.2e | %.6f |", scene.name(), sightings.size(),
                        m.count(), m.rmseMetres(), pct(m.mape()), m.rse(), m.r2()));
                for (double share : m.shareUnder()) {
                    b.append(String.format(Locale.ROOT, " %.0f %% |", share * 100));
                }
                b.append('\n');
            }
        }
        return b.toString();
    }

    static void plot(List<Scene> scenes, List<Row> rows, Path png) throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (String metric : List.of("median > 20 km", "p99")) {
            for (Scene scene : scenes) {
                XYChart chart = new XYChartBuilder().width(520).height(380)
                        .title(scene.name() + ": " + metric + " relative error").xAxisTitle("render time, s")
                        .yAxisTitle("relative error").build();
                chart.getStyler().setYAxisLogarithmic(true);
                chart.getStyler().setYAxisDecimalPattern("0.#E0");
                chart.getStyler().setChartBackgroundColor(Color.WHITE);
                chart.getStyler().setLegendVisible(true);
                for (DepthMode mode : new DepthMode[] {DepthMode.STANDARD_24, DepthMode.REVERSED_32F, DepthMode.SHADER_RANGE, null}) {
                    List<Double> x = new ArrayList<>(), y = new ArrayList<>();
                    double lodDefault = dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX;
                    // One curve per depth mode (supersampling varies), and one for the level of detail (null).
                    rows.stream().filter(r -> r.scene() == scene && r.setting().views() == 8 && (mode == null
                                    ? r.setting().mode() == DepthMode.SHADER_RANGE && r.setting().supersampling() == 1
                                    : r.setting().mode() == mode && r.setting().lodPx() == lodDefault))
                            .sorted((a, c) -> Double.compare(a.seconds(), c.seconds()))
                            .forEach(r -> {
                                x.add(r.seconds());
                                double v = metric.equals("p99") ? r.error().p99Relative() : r.error().farMedianRelative();
                                y.add(Math.max(v, 1e-9)); // log axis: exact zero drawn at 1e-9
                            });
                    if (!x.isEmpty()) {
                        chart.addSeries(mode == null ? "shader, LOD 0-2 px" : mode.optionName(), x, y)
                                .setMarker(SeriesMarkers.CIRCLE);
                    }
                }
                charts.add(chart);
            }
        }
        BitmapEncoder.saveBitmap(charts, 2, scenes.size(), png.toString().replaceFirst("\\.png$", ""), BitmapEncoder.BitmapFormat.PNG);
    }

    static String pct(double v) {
        if (Double.isNaN(v)) {
            return "–";
        }
        double p = v * 100;
        return p >= 0.1 ? String.format(Locale.ROOT, "%.2f %%", p) : String.format(Locale.ROOT, "%.1e %%", p);
    }

    static String fmt(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
