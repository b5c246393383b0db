package dempano.cli;

import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.dem.DemDirectory;
import dempano.dem.DemSource;
import dempano.dem.DemoTerrain;
import dempano.dem.InMemoryDem;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.DistanceComparison;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.reference.ClosedFormSea;
import dempano.summits.Summit;
import dempano.summits.SummitList;
import dempano.summits.SummitSighting;
import java.awt.Color;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
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
 * the reference. Sea scenes (a DEM of zeros, no refraction) are measured against the closed form
 * instead ({@link ClosedFormSea}), the CPU reference included. Writes {@code accuracy.md} and
 * {@code accuracy.png} into the output folder.
 *
 * <p>Run: {@code gradle accuracyReport} (or {@code java -cp … dempano.cli.AccuracyReport --shared ../shared --out docs});
 * {@code --scenes sea-2m,provence,summits} (Gradle: {@code -Pscenes=…}) runs only the named scenes, "summits" for the
 * summit section, "terrain" for the void-fill section.
 */
@picocli.CommandLine.Command(name = "accuracyReport", mixinStandardHelpOptions = true,
        description = "Renders the accuracy scenes over a sweep of settings; writes accuracy.md and accuracy.png.")
public final class AccuracyReport implements java.util.concurrent.Callable<Integer> {
    @picocli.CommandLine.Mixin
    dempano.bench.ReportTool.SharedOptions io = new dempano.bench.ReportTool.SharedOptions();
    @picocli.CommandLine.Option(names = "--scenes", split = ",", description = "Only these scenes; \"summits\" and \"terrain\""
            + " for those sections.")
    List<String> scenesWanted;

    /**
     * One scene: a viewpoint in a DEM.
     *
     * @param request the default request of the scene (viewpoint, range, eye, refraction)
     * @param sea     true for a sea-only scene, whose truth is the closed form ({@link ClosedFormSea})
     */
    record Scene(String name, String description, DemSource dem, PanoramaRequest request, boolean sea) {
        Scene(String name, String description, DemSource dem, double latDeg, double lonDeg, double rangeMetres) {
            this(name, description, dem, PanoramaRequest.at(latDeg, lonDeg).withRangeMetres(rangeMetres), false);
        }

        /** Open sea at 43° N 7° E (an empty DEM: every tile is sea level), refraction off, eye at a height. */
        static Scene sea(double eyeHeightMetres, double rangeMetres) {
            String h = fmt(eyeHeightMetres);
            return new Scene("sea-" + h + "m", "open sea only (DEM of zeros), eye " + h + " m, refraction 0, "
                    + fmt(rangeMetres / 1000) + " km; truth: closed form", new InMemoryDem("sea", List.of()),
                    PanoramaRequest.at(43.0, 7.0).withAltitudeMetres(0).withEyeHeightMetres(eyeHeightMetres)
                            .withRefraction(Refraction.NONE).withMissingTiles(MissingTilePolicy.SEA_LEVEL)
                            .withRangeMetres(rangeMetres), true);
        }
    }

    /**
     * What a scene is measured against.
     *
     * @param distanceMetres truth per pixel, metres (+∞ sky): the CPU reference, or the closed form for the sea
     * @param incidenceDeg   incidence per pixel from the truth's side (reference layer or closed form), degrees
     * @param reference      the CPU reference panorama (for the sea, itself measured against the closed form)
     * @param referenceSeconds one warm CPU reference render, seconds
     */
    record Truth(float[] distanceMetres, float[] incidenceDeg, Panorama reference, double referenceSeconds) {
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

    /**
     * A measured row.
     *
     * @param setting    the GL setting, null for the CPU reference (sea scenes only)
     * @param seconds    one warm render, seconds
     * @param incidence  errors by incidence bin ({@link DistanceComparison#INCIDENCE_BIN_LOWER_DEG})
     * @param horizon    sea scenes: the first {@link #HORIZON_ROWS} rows under the horizon; empty otherwise
     * @param seaWithin  sea scenes: share of sea pixels within {@link #SEA_TOLERANCE}, horizon row excluded; NaN otherwise
     */
    record Row(Scene scene, Setting setting, double seconds, DistanceComparison error,
               List<DistanceComparison.IncidenceBin> incidence, List<DistanceComparison.HorizonRow> horizon,
               double seaWithin) {
        String label() {
            return setting == null ? "CPU reference" : setting.label();
        }
    }

    /** Rows under the horizon listed for the sea scenes. */
    static final int HORIZON_ROWS = 5;
    /** Relative tolerance of the sea scenes' "within" share: 0.1 %. */
    static final double SEA_TOLERANCE = 0.001;

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

    /**
     * The sea scenes' sweep, shorter (the reference and the far sea are costly at 2000 m): the axes that
     * change the sea's error, depth mode, supersampling, views and level of detail, one step each,
     * without the repeats (24-bit and 32f depth at ss 2; LOD 0.25 and 1 px).
     */
    static final List<Setting> SEA_SETTINGS = List.of(
            new Setting(DepthMode.STANDARD_24, 1, 8),
            new Setting(DepthMode.REVERSED_32F, 1, 8),
            new Setting(DepthMode.SHADER_RANGE, 0.5, 8),
            new Setting(DepthMode.SHADER_RANGE, 1, 8),
            new Setting(DepthMode.SHADER_RANGE, 1, 12),
            new Setting(DepthMode.SHADER_RANGE, 2, 8),
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 0),
            new Setting(DepthMode.SHADER_RANGE, 1, 8, 2));

    private AccuracyReport() { // run through main
    }

    public static void main(String[] args) {
        System.exit(dempano.bench.ReportTool.run(new AccuracyReport(), args));
    }

    @Override
    public Integer call() throws IOException {
        Path shared = io.shared, out = dempano.bench.ReportTool.outputFolder(io.out);
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
            // A steep summit cell: the drawn surface stands 1.1 m above the DEM's bilinear height under the eye,
            // which the near plane must respect (NearPlaneOnSteepSummitTest).
            scenes.add(new Scene("eggishorn-steep", "Eggishorn, a steep summit cell (N46E008), 80 km",
                    real, 46.4316, 8.0929, 80_000));
        } else {
            System.err.println("accuracyReport: " + dem + " absent: real scenes left out");
        }
        scenes.add(Scene.sea(2, 30_000));
        scenes.add(Scene.sea(100, 60_000));
        scenes.add(Scene.sea(2000, 170_000)); // horizon at 160 km
        Scene provence = scenes.stream().filter(sc -> sc.name().equals("provence")).findFirst().orElse(null);
        List<String> known = new ArrayList<>(scenes.stream().map(Scene::name).toList());
        known.addAll(List.of("summits", "terrain"));
        // --scenes a,b: only these scenes ("summits", "terrain" for those sections); null: all
        java.util.Set<String> only = scenesWanted == null ? null : dempano.bench.ReportTool.subset(scenesWanted, known, "scene");
        if (only != null) {
            scenes.removeIf(sc -> !only.contains(sc.name()));
        }
        long started = System.nanoTime();
        List<Row> rows = new ArrayList<>();
        Map<Scene, Truth> truths = new LinkedHashMap<>();
        // Held open for the whole report: the shared GL context is then created once (re-creating it
        // after the last holder closed failed once on llvmpipe: see the issue notes).
        PanoramaRenderer keepAlive = scenes.isEmpty() ? null : PanoramaRenderer.open(new InMemoryDem("none", List.of()));
        String glName = keepAlive == null ? "none (no scene rendered)" : keepAlive.glRenderer();
        for (Scene scene : scenes) {
            PanoramaRequest base = scene.request();
            Truth truth = truth(scene);
            truths.put(scene, truth);
            if (scene.sea()) {
                rows.add(measure(scene, null, truth.referenceSeconds(), truth.reference(), truth));
            }
            try (PanoramaRenderer gl = PanoramaRenderer.open(scene.dem())) {
                gl.render(base); // warm-up
                for (Setting s : scene.sea() ? SEA_SETTINGS : SETTINGS) {
                    PanoramaRequest req = base.withDepthMode(s.mode()).withSupersampling(s.supersampling()).withViews(s.views())
                            .withLodErrorPx(s.lodPx());
                    long t = System.nanoTime();
                    Panorama p = gl.render(req);
                    rows.add(measure(scene, s, (System.nanoTime() - t) / 1e9, p, truth));
                }
            }
        }
        String summitSection = "";
        Path alps = shared.resolve("peaks").resolve("alps.txt");
        if (provence != null && Files.isRegularFile(alps) && (only == null || only.contains("summits"))) {
            dempano.summits.SummitList list = dempano.summits.SummitReader.read(alps, false);
            List<Scene> summitScenes = List.of(provence,
                    new Scene("eggishorn", "Eggishorn, Bernese Alps (N46E008), 80 km", new DemDirectory(dem), 46.4314, 8.0942, 80_000));
            summitSection = summits(summitScenes, list, truths);
        }
        String terrainSection = only == null || only.contains("terrain") ? terrainSection(dem, alps) : "";
        if (!scenes.isEmpty()) {
            plot(scenes, rows, out.resolve("accuracy.png"));
            keepAlive.close();
        }
        double totalSeconds = (System.nanoTime() - started) / 1e9;
        String md = markdown(scenes, rows, truths, glName, totalSeconds) + summitSection + terrainSection;
        dempano.io.AtomicFiles.write(out.resolve("accuracy.md"), o -> o.write(md.getBytes(StandardCharsets.UTF_8)));
        System.err.println("accuracyReport: wrote " + out.resolve("accuracy.md") + (scenes.isEmpty() ? ""
                : " and " + out.resolve("accuracy.png")));
        return 0;
    }

    /**
     * The void-fill section ({@link dempano.bench.FillSummary}): the fills measured on the surveyed summits in the real
     * voids of the tiles in {@code dem} and on held-out voids of N46E008 with a 30″ second source (that part left out,
     * and said so, where GDAL's gdalwarp is absent). Empty, with a line on stderr, where the tiles or the summits are.
     */
    static String terrainSection(Path dem, Path summits) throws IOException {
        if (!Files.isDirectory(dem) || !Files.isRegularFile(summits)) {
            System.err.println("accuracyReport: " + dem + " or " + summits + " absent: void-fill section left out");
            return "";
        }
        dempano.bench.VoidFillReport.Measured real = dempano.bench.VoidFillReport.measure(dem, summits);
        dempano.bench.CoarseFillReport.Measured heldOut = null;
        Path n46e008 = dem.resolve("N46E008.hgt");
        if (Files.isRegularFile(n46e008)) {
            try {
                heldOut = dempano.bench.CoarseFillReport.measure(n46e008, summits);
            } catch (IOException e) {
                System.err.println("accuracyReport: held-out void fills not measured: " + e.getMessage());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted", e);
            }
        }
        return "\n" + dempano.bench.FillSummary.markdown(real, heldOut, "gradle accuracyReport");
    }

    /**
     * The truth of a scene: the CPU reference (one warm-up render that also gives the incidence layer,
     * then one timed render), or for the sea the closed form on the reference's pixel grid and eye.
     */
    static Truth truth(Scene scene) {
        PanoramaRequest base = scene.request();
        try (PanoramaRenderer cpu = PanoramaRenderer.openReference(scene.dem())) {
            // Warm-up (tiles decoded, JIT) that also computes the incidence layer; the timed render has no layers.
            Panorama withIncidence = cpu.render(base.withLayers(EnumSet.of(Layer.INCIDENCE)));
            long t = System.nanoTime();
            Panorama ref = cpu.render(base);
            double seconds = (System.nanoTime() - t) / 1e9;
            if (!scene.sea()) {
                return new Truth(ref.distanceArray(), withIncidence.layer(Layer.INCIDENCE), ref, seconds);
            }
            var m = ref.metadata();
            ClosedFormSea sea = ClosedFormSea.of(new LocalFrame(m.latDeg(), m.lonDeg(), m.eyeAltitudeMetres()), ref.geometry());
            return new Truth(sea.distanceMetres(), sea.incidenceDeg(), ref, seconds);
        }
    }

    /** Compares one rendered panorama with the scene's truth. */
    static Row measure(Scene scene, Setting s, double seconds, Panorama p, Truth truth) {
        float[] d = p.distanceArray(), ref = truth.distanceMetres();
        DistanceComparison c = DistanceComparison.of(d, ref, p.widthPx());
        var bins = DistanceComparison.byIncidence(d, ref, truth.incidenceDeg(), DistanceComparison.INCIDENCE_BIN_LOWER_DEG);
        List<DistanceComparison.HorizonRow> horizon = scene.sea()
                ? DistanceComparison.belowHorizon(d, ref, p.widthPx(), HORIZON_ROWS) : List.of();
        double within = scene.sea() ? DistanceComparison.shareWithin(d, ref, p.widthPx(), SEA_TOLERANCE, 1) : Double.NaN;
        Row row = new Row(scene, s, seconds, c, bins, horizon, within);
        System.err.printf(Locale.ROOT, "%-10s %-40s %6.2f s  median %s  p99 %s  far>1%% %s  skyline %.3f px%s%n",
                scene.name(), row.label(), seconds, pct(c.medianRelative()), pct(c.p99Relative()), pct(c.farShareOver1Percent()),
                c.skylineMeanAbsPx(), scene.sea() ? "  within 0.1 % " + pct(within) + "  horizon row " + horizonCell(horizon.get(0)) : "");
        return row;
    }

    static String markdown(List<Scene> scenes, List<Row> rows, Map<Scene, Truth> truths, String glName, double totalSeconds) {
        StringBuilder b = new StringBuilder();
        b.append("# Accuracy: error against run time\n\n");
        b.append("Generated by `gradle accuracyReport` (class `dempano.cli.AccuracyReport`); do not edit by hand.\n\n");
        b.append("- Commit ").append(dempano.bench.ReportTool.commit("**/accuracy.md", "**/accuracy.png")).append(".\n");
        b.append("- Machine: ").append(Runtime.getRuntime().availableProcessors()).append(" cores, OpenGL renderer `")
                .append(glName).append("`, Java ").append(System.getProperty("java.version")).append(".\n");
        b.append(String.format(Locale.ROOT, "- Whole report (every render, the reference's and the summits' included): %.0f s.%n",
                totalSeconds));
        b.append("- Every panorama: 360° at 20 px/°, elevation −30°…30° (7200 × 1200 px); land scenes: refraction k = 0.13,\n"
                + "  eye 2 m above the DEM.\n");
        b.append("- Truth on land: the CPU reference renderer (`--renderer reference`): for every pixel centre, the exact distance\n"
                + "  to the first point of the same triangulated surface (double precision horizon sweep, no GL).\n");
        b.append("- Truth at sea (scenes `sea-…`: only sea within range, an empty DEM read as sea level, refraction 0): the\n"
                + "  closed form, the distance along each pixel-centre ray to the WGS84 ellipsoid (a quadratic in ECEF, double\n"
                + "  precision; a ray that misses is sky). The CPU reference is measured against it too (first row).\n");
        b.append("- Time: one warm `PanoramaRenderer.render` call (tiles cached, JIT warm), all stages included.\n");
        b.append("- Relative error |d − d_true| / d_true over pixels where both see terrain; \"> 5 %\" is the share of pixels where\n"
                + "  a different surface was seen; \"far > 1 %\": share of the pixels farther than 20 km (truth) whose error exceeds\n"
                + "  1 %; skyline: per column, |topmost terrain row − truth's|, pixels.\n");
        b.append("- Incidence: the angle between the ray and the surface met, from the truth's side (the reference's incidence\n"
                + "  layer; at sea the ellipsoid's tangent plane), so the bins do not depend on the renderer tested. Per bin:\n"
                + "  median and 99th percentile of the relative error.\n\n");
        for (Scene scene : scenes) {
            Truth truth = truths.get(scene);
            List<Row> mine = rows.stream().filter(r -> r.scene() == scene).toList();
            b.append("## ").append(scene.name()).append(": ").append(scene.description()).append("\n\n");
            b.append(String.format(Locale.ROOT, "Reference (CPU) render time: %.2f s. Viewpoint %.4f, %.4f.%n%n",
                    truth.referenceSeconds(), scene.request().latDeg(), scene.request().lonDeg()));
            b.append("| setting | time s | median | p95 | p99 | max | > 5 % | median > 20 km | p99 > 20 km | far > 1 % | sky mismatch px | skyline mean px | skyline max px | columns off |\n");
            b.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            for (Row r : mine) {
                DistanceComparison c = r.error();
                b.append(String.format(Locale.ROOT, "| %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %s | %d | %.3f | %d | %s |%n",
                        r.label(), r.seconds(), pct(c.medianRelative()), pct(c.p95Relative()), pct(c.p99Relative()),
                        pct(c.maxRelative()), pct(c.shareOver5Percent()), pct(c.farMedianRelative()), pct(c.farP99Relative()),
                        pct(c.farShareOver1Percent()), c.skyMismatchPixels(), c.skylineMeanAbsPx(),
                        c.skylineMaxAbsPx(), pct(c.skylineColumnsOff())));
            }
            b.append('\n');
            b.append(incidenceTable(mine));
            if (scene.sea()) {
                b.append(horizonTable(mine));
            }
        }
        b.append("![error against run time](accuracy.png)\n");
        return b.toString();
    }

    /** Relative error by incidence bin: median / p99 per bin, pixel counts in the header. */
    static String incidenceTable(List<Row> rows) {
        StringBuilder b = new StringBuilder("Relative error by incidence angle (median / p99; pixels per bin in the header):\n\n| setting |");
        List<DistanceComparison.IncidenceBin> first = rows.get(0).incidence();
        for (DistanceComparison.IncidenceBin bin : first) {
            String range = Double.isInfinite(bin.toDeg()) ? "≥ " + fmt(bin.fromDeg()) + "°"
                    : bin.fromDeg() == 0 ? "< " + fmt(bin.toDeg()) + "°" : fmt(bin.fromDeg()) + "–" + fmt(bin.toDeg()) + "°";
            b.append(' ').append(range).append(" (").append(bin.pixels()).append(" px) |");
        }
        b.append("\n|---|").append("---:|".repeat(first.size())).append('\n');
        for (Row r : rows) {
            b.append("| ").append(r.label()).append(" |");
            for (DistanceComparison.IncidenceBin bin : r.incidence()) {
                b.append(' ').append(pct(bin.medianRelative())).append(" / ").append(pct(bin.p99Relative())).append(" |");
            }
            b.append('\n');
        }
        return b.append('\n').toString();
    }

    /** The sea's rows under the horizon: per row, median distance read (median signed error), and the share within 0.1 %. */
    static String horizonTable(List<Row> rows) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "Rows under the horizon (row 1 = each column's topmost"
                + " sea row in the truth): median distance read over the columns (median signed relative error; − = too"
                + " near; \"sky n\" = columns read as sky); \"within %s\": share of the sea pixels below row 1 within %s of"
                + " the closed form.%n%n", pct(SEA_TOLERANCE), pct(SEA_TOLERANCE)));
        b.append("| setting | within ").append(pct(SEA_TOLERANCE)).append(" |");
        for (int k = 1; k <= HORIZON_ROWS; k++) {
            b.append(" row ").append(k).append(" |");
        }
        b.append("\n|---|---:|").append("---:|".repeat(HORIZON_ROWS)).append('\n');
        b.append("| closed form (truth) | |");
        for (DistanceComparison.HorizonRow h : rows.get(0).horizon()) {
            b.append(String.format(Locale.ROOT, " %.0f m |", h.medianTruthMetres()));
        }
        b.append('\n');
        for (Row r : rows) {
            b.append("| ").append(r.label()).append(" | ").append(pct(r.seaWithin())).append(" |");
            for (DistanceComparison.HorizonRow h : r.horizon()) {
                b.append(' ').append(horizonCell(h)).append(" |");
            }
            b.append('\n');
        }
        return b.append('\n').toString();
    }

    static String horizonCell(DistanceComparison.HorizonRow h) {
        String cell = Double.isNaN(h.medianMetres()) ? "sky"
                : String.format(Locale.ROOT, "%.0f m (%s%s)", h.medianMetres(), h.medianSignedRelative() < 0 ? "−" : "+",
                        pct(Math.abs(h.medianSignedRelative())));
        return h.skyMismatchColumns() > 0 && !Double.isNaN(h.medianMetres()) ? cell + ", sky " + h.skyMismatchColumns() : cell;
    }

    /**
     * The thesis's metrics on surveyed summits for the default GL setting: truncated (summits the
     * panorama reads within the projector's distance tolerance) and untruncated (every summit the DEM
     * itself shows, whatever the panorama reads there).
     *
     * @param truths the scenes' truths already computed (the reference is rendered for a scene not among them)
     */
    static String summits(List<Scene> scenes, SummitList list, Map<Scene, Truth> truths) {
        StringBuilder b = new StringBuilder("\n## Distances to surveyed summits (the thesis's metrics)\n\n");
        b.append("Summits of `peaks/alps.txt` within range, default settings (shader depth, ss 1, 8 views). Estimate: the\n"
                + "distance map where a person clicking on the peak reads it (the first terrain pixel at or below the summit's\n"
                + "pixel, in the best-matching column of `SummitProjector`'s window); truth: the straight-line distance to the\n"
                + "surveyed summit. Differences come mostly from the DEM (SRTM3 summits flattened or void-filled, positions on a\n"
                + "90 m grid); the renderer's own error is in the tables above.\n\n");
        b.append("- Truncated (as before): only summits whose estimate lies within max(300 m, 2 %) of the truth count (\"visible\"),\n"
                + "  so large misses cannot enter (the thesis had 13 % MAPE).\n");
        b.append("- Untruncated: every summit the DEM itself shows, misses counted. \"DEM-visible\": the CPU reference panorama\n"
                + "  sees the DEM's own point at the summit's position (the surveyed position at the DEM's bilinear height,\n"
                + "  projected the same way; it is hidden when the reference reads nearer terrain there; summits on tiles the\n"
                + "  DEM lacks are left out). For each of those the GL estimate is compared with the truth whatever its error;\n"
                + "  \"no reading\" counts DEM-visible summits where the GL panorama shows no terrain in the window (left out of\n"
                + "  the metrics). The projector's window model applies to both: a summit seen against higher terrain behind\n"
                + "  it reads that terrain and counts as neither.\n\n");
        StringBuilder truncated = new StringBuilder("| scene | summits in range | visible | RMSE m | MAPE | RSE | R² |");
        StringBuilder untruncated = new StringBuilder("| scene | DEM-visible | no reading | compared | RMSE m | MAPE | median APE | RSE | R² |");
        for (double t : dempano.summits.DistanceMetrics.THRESHOLDS) {
            truncated.append(String.format(Locale.ROOT, " < %.0f %% |", t * 100));
            untruncated.append(String.format(Locale.ROOT, " < %.0f %% |", t * 100));
        }
        truncated.append("\n|---|---:|---:|---:|---:|---:|---:|")
                .append("---:|".repeat(dempano.summits.DistanceMetrics.THRESHOLDS.length)).append('\n');
        untruncated.append("\n|---|---:|---:|---:|---:|---:|---:|---:|---:|")
                .append("---:|".repeat(dempano.summits.DistanceMetrics.THRESHOLDS.length)).append('\n');
        for (Scene scene : scenes) {
            List<SummitSighting> sightings;
            try (PanoramaRenderer gl = PanoramaRenderer.open(scene.dem())) {
                sightings = gl.render(scene.request()).summits(list);
            }
            List<Double> est = new ArrayList<>(), truth = new ArrayList<>();
            for (SummitSighting s : sightings) {
                if (s.visible()) {
                    est.add(s.seenDistanceMetres());
                    truth.add(s.slantMetres());
                }
            }
            var m = dempano.summits.DistanceMetrics.of(est, truth);
            truncated.append(String.format(Locale.ROOT, "| %s | %d | %d | %.0f | %s | %.2e | %.6f |", scene.name(), sightings.size(),
                    m.count(), m.rmseMetres(), pct(m.mape()), m.rse(), m.r2()));
            for (double share : m.shareUnder()) {
                truncated.append(String.format(Locale.ROOT, " %.0f %% |", share * 100));
            }
            truncated.append('\n');

            Panorama reference = truths.containsKey(scene) ? truths.get(scene).reference() : null;
            if (reference == null) {
                try (PanoramaRenderer cpu = PanoramaRenderer.openReference(scene.dem())) {
                    reference = cpu.render(scene.request());
                }
            }
            java.util.Set<String> demVisible = demVisibleSummits(scene, list, reference);
            List<Double> estAll = new ArrayList<>(), truthAll = new ArrayList<>(), ape = new ArrayList<>();
            int noReading = 0, shown = 0;
            for (SummitSighting s : sightings) {
                if (!demVisible.contains(key(s.summit()))) {
                    continue;
                }
                shown++;
                if (Double.isNaN(s.seenDistanceMetres())) {
                    noReading++;
                    continue;
                }
                estAll.add(s.seenDistanceMetres());
                truthAll.add(s.slantMetres());
                ape.add(Math.abs(s.seenDistanceMetres() - s.slantMetres()) / s.slantMetres());
            }
            var u = dempano.summits.DistanceMetrics.of(estAll, truthAll);
            double medianApe = dempano.util.Quantiles.median(ape.stream().mapToDouble(Double::doubleValue).toArray());
            untruncated.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %.0f | %s | %s | %.2e | %.6f |", scene.name(), shown,
                    noReading, u.count(), u.rmseMetres(), pct(u.mape()), pct(medianApe), u.rse(), u.r2()));
            for (double share : u.shareUnder()) {
                untruncated.append(String.format(Locale.ROOT, " %.0f %% |", share * 100));
            }
            untruncated.append('\n');
        }
        b.append("Truncated at max(300 m, 2 %):\n\n").append(truncated).append("\nUntruncated (every DEM-visible summit):\n\n")
                .append(untruncated);
        return b.toString();
    }

    /**
     * Summits whose DEM point (surveyed position, the DEM's bilinear height there) the reference
     * panorama sees, by {@link #key}: the list re-projected with DEM heights into the reference.
     * Summits on tiles the DEM lacks (held as sea level) are never DEM-visible.
     */
    static java.util.Set<String> demVisibleSummits(Scene scene, SummitList list, Panorama reference) {
        PanoramaRequest r = scene.request();
        Mosaic mosaic = Mosaic.around(scene.dem(), r.latDeg(), r.lonDeg(), r.rangeMetres(), r.missingTiles());
        List<Summit> atDem = new ArrayList<>();
        for (Summit s : list.summits()) {
            double h = mosaic.heightAt(s.latDeg(), s.lonDeg());
            // A summit on a missing tile stands on the sea-level stand-in: the DEM has no summit there.
            boolean onData = !mosaic.tilesMissing().contains(dempano.dem.TileId.containing(s.latDeg(), s.lonDeg()));
            if (!Double.isNaN(s.elevationMetres()) && !Double.isNaN(h) && onData) {
                atDem.add(new Summit(s.name(), s.latDeg(), s.lonDeg(), h));
            }
        }
        java.util.Set<String> out = new java.util.HashSet<>();
        for (SummitSighting s : reference.summits(SummitList.of(list.source() + " at DEM heights", atDem))) {
            if (s.visible()) {
                out.add(key(s.summit()));
            }
        }
        return out;
    }

    /** Identifies a summit across lists that differ only in heights. */
    static String key(Summit s) {
        return s.name() + "@" + s.latDeg() + "," + s.lonDeg();
    }

    static void plot(List<Scene> scenes, List<Row> rows, Path png) throws IOException {
        List<XYChart> charts = new ArrayList<>();
        for (String metric : List.of("median > 20 km", "p99")) {
            for (Scene scene : scenes) {
                XYChart chart = new XYChartBuilder().width(520).height(380)
                        .title(scene.name() + ": " + metric + " relative error").xAxisTitle("render time, s")
                        .yAxisTitle("relative error (0 drawn at 1E-9)").build();
                chart.getStyler().setYAxisLogarithmic(true);
                chart.getStyler().setYAxisDecimalPattern("0.#E0");
                chart.getStyler().setChartBackgroundColor(Color.WHITE);
                chart.getStyler().setLegendVisible(true);
                for (DepthMode mode : new DepthMode[] {DepthMode.STANDARD_24, DepthMode.REVERSED_32F, DepthMode.SHADER_RANGE, null}) {
                    List<Double> x = new ArrayList<>(), y = new ArrayList<>();
                    double lodDefault = dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX;
                    // One curve per depth mode (supersampling varies), and one for the level of detail (null).
                    rows.stream().filter(r -> r.scene() == scene && r.setting() != null && r.setting().views() == 8 && (mode == null
                                    ? r.setting().mode() == DepthMode.SHADER_RANGE && r.setting().supersampling() == 1
                                    : r.setting().mode() == mode && r.setting().lodPx() == lodDefault))
                            .sorted((a, c) -> Double.compare(a.seconds(), c.seconds()))
                            .forEach(r -> {
                                double v = metric.equals("p99") ? r.error().p99Relative() : r.error().farMedianRelative();
                                if (!Double.isNaN(v)) { // NaN: no pixel farther than 20 km (the sea at 2 m)
                                    x.add(r.seconds());
                                    y.add(Math.max(v, 1e-9)); // log axis: exact zero drawn at 1e-9
                                }
                            });
                    if (!x.isEmpty()) {
                        chart.addSeries(mode == null ? "shader, LOD 0-2 px" : mode.optionName(), x, y)
                                .setMarker(SeriesMarkers.CIRCLE);
                    }
                }
                if (chart.getSeriesMap().isEmpty()) {
                    chart.setTitle(chart.getTitle() + " (no pixel)");
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
