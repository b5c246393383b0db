package dempano.bench;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import dempano.CameraImage;
import dempano.CameraRequest;
import dempano.PanoramaRenderer;
import dempano.PanoramaRequest;
import dempano.dem.DemDirectory;
import dempano.dem.HgtTile;
import dempano.io.CameraWriter;
import dempano.io.PanoramaWriter;
import dempano.panorama.DistanceComparison;
import dempano.panorama.Panorama;
import java.awt.Color;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.AnnotationText;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code gradle bench}: speed and memory per scene, each case in a fresh JVM so that "cold" is
 * honest (context, shaders, tile decoding, JIT all included) and peak memory is the process's own.
 * Writes {@code docs/performance.md} and prints its tables.
 */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Speed and memory benchmark; writes docs/performance.md.")
public final class Benchmark implements java.util.concurrent.Callable<Integer> {
    @Option(names = "--out", description = "Directory for performance.md (default: ${DEFAULT-VALUE}).", defaultValue = "docs")
    Path outDir;
    @Option(names = "--dem-cache", description = "Where generated tiles are kept (default: ${DEFAULT-VALUE}).", defaultValue = "build/bench-dem")
    Path demCache;
    @Option(names = "--shared", description = "The shared material folder with real tiles (default: ${DEFAULT-VALUE}).", defaultValue = "../shared")
    Path shared;
    @Option(names = "--cases", split = ",", description = "Only these cases (names as in the table).")
    List<String> only;
    @Option(names = "--child", hidden = true)
    String child;

    /** One measured configuration. */
    record Case(String name, String scene, String dem, double lat, double lon, double rangeKm, double ppd, double lodPx,
                boolean colour, boolean distance, String renderer, String heap, boolean compare, Camera camera) {
        /** A panorama case. */
        Case(String name, String scene, String dem, double lat, double lon, double rangeKm, double ppd, double lodPx,
             boolean colour, boolean distance, String renderer, String heap, boolean compare) {
            this(name, scene, dem, lat, lon, rangeKm, ppd, lodPx, colour, distance, renderer, heap, compare, null);
        }

        /** What the case renders: colour, distance or both. */
        String outputs() {
            return colour && distance ? "both" : colour ? "colour" : "distance";
        }
    }

    /**
     * A camera case's photo: size, lens and pose (the viewpoint is the case's).
     *
     * @param focal35mm 35 mm-equivalent focal length, millimetres
     */
    record Camera(int widthPx, int heightPx, double focal35mm, double headingDeg, double pitchDeg) {
        dempano.camera.CameraIntrinsics intrinsics() {
            return dempano.camera.CameraIntrinsics.fromFocal35mm(widthPx, heightPx, focal35mm);
        }

        /** Pixels per degree at the image centre (the lens's focal length in pixels, per radian, in degrees). */
        double pixelsPerDegree() {
            return intrinsics().fxPx() * Math.PI / 180;
        }
    }

    /** What a child reports. */
    record Result(String name, double coldMillis, Map<String, Double> coldStages, double warmMillis,
                  Map<String, Double> warmStages, double writeMillis, long peakRssBytes, long triangles, int tiles,
                  double referenceMillis, double medianRel, double p99Rel, double skylineMeanPx, double shareOver5,
                  String glRenderer, String error) {
    }

    public static void main(String[] args) {
        System.exit(ReportTool.run(new Benchmark(), args));
    }

    @Override
    public Integer call() throws Exception {
        if (child != null) {
            return runChild(new Gson().fromJson(child, Case.class));
        }
        ReportTool.outputFolder(outDir); // before an hour of cases, not after
        Path srtm3 = FractalRelief.ensure(demCache.resolve("srtm3"), 45, 7, 3, 3, HgtTile.SRTM3_SAMPLES);
        System.err.println("bench: generated 3×3 SRTM3 tiles in " + srtm3);
        List<Case> cases = new ArrayList<>();
        String s3 = srtm3.toString();
        double lat = 46.5, lon = 8.5;
        String scene3 = "3×3 SRTM3 (generated), 150 km";
        cases.add(new Case("srtm3-150km", scene3, s3, lat, lon, 150, 20, 0.5, true, true, "opengl", "6g", true));
        cases.add(new Case("srtm3-150km-full-res", scene3, s3, lat, lon, 150, 20, 0, true, true, "opengl", "6g", false));
        for (double lod : new double[] {0.25, 1, 2}) {
            cases.add(new Case("srtm3-150km-lod-" + lod, scene3, s3, lat, lon, 150, 20, lod, true, true, "opengl", "6g", true));
        }
        cases.add(new Case("srtm3-150km-distance-only", scene3, s3, lat, lon, 150, 20, 0.5, false, true, "opengl", "6g", false));
        cases.add(new Case("srtm3-150km-colour-only", scene3, s3, lat, lon, 150, 20, 0.5, true, false, "opengl", "6g", false));
        cases.add(new Case("srtm3-150km-reference", scene3, s3, lat, lon, 150, 20, 0, true, true, "reference", "6g", false));
        for (double r : new double[] {25, 50, 100, 200, 300}) {
            cases.add(new Case("range-" + (int) r + "km", "range curve (3×3 SRTM3 area, sea beyond)", s3, lat, lon, r, 20, 0.5,
                    true, true, "opengl", "6g", false));
        }
        for (double p : new double[] {10, 40}) {
            cases.add(new Case("ppd-" + (int) p, "ppd curve (3×3 SRTM3, 150 km)", s3, lat, lon, 150, p, 0.5, true, true, "opengl",
                    "6g", false));
        }
        Path real = shared.resolve("dem");
        if (Files.isRegularFile(real.resolve("N43E006.hgt")) && Files.isRegularFile(real.resolve("N43E007.hgt"))) {
            String sceneP = "Provence, real SRTM3 (N43E006/N43E007), 100 km";
            cases.add(new Case("provence-100km", sceneP, real.toString(), 43.8167, 6.9667, 100, 20, 0.5, true, true, "opengl", "6g", true));
            cases.add(new Case("provence-100km-reference", sceneP, real.toString(), 43.8167, 6.9667, 100, 20, 0, true, true,
                    "reference", "6g", false));
            // A 24 MP photo's own view (50 mm equivalent) and its 1/4 scale, on the same real tiles.
            for (int scale : new int[] {1, 4}) {
                Camera cam = new Camera(6000 / scale, 4000 / scale, 50, 40, -2);
                cases.add(new Case("camera-" + cam.widthPx() + "x" + cam.heightPx(), "Provence camera, " + cam.widthPx() + "×"
                        + cam.heightPx() + " px, 50 mm equiv., heading 40°, pitch −2°, 100 km", real.toString(), 43.8167, 6.9667,
                        100, Math.round(cam.pixelsPerDegree()), 0.5, true, true, "opengl", "6g", false, cam));
            }
        } else {
            System.err.println("bench: " + real + " lacks N43E006/N43E007: the real-tile scene is skipped");
        }
        Path srtm1 = demCache.resolve("srtm1"); // generated below, where a case of it is run (a minute of work)
        String scene1 = "5×5 SRTM1 (generated), 300 km (sea beyond the 5×5)";
        cases.add(new Case("srtm1-300km", scene1, srtm1.toString(), 46.5, 8.5, 300, 20, 0.5, true, true, "opengl", "6g", true));
        cases.add(new Case("srtm1-300km-reference", scene1, srtm1.toString(), 46.5, 8.5, 300, 20, 0, true, true, "reference",
                "6g", false));
        java.util.Set<String> wanted = ReportTool.subset(only, cases.stream().map(Case::name).toList(), "case");
        cases.removeIf(c -> !wanted.contains(c.name()));
        if (cases.stream().anyMatch(c -> c.dem().equals(srtm1.toString()))) {
            FractalRelief.ensure(srtm1, 44, 6, 5, 5, HgtTile.SRTM1_SAMPLES);
        }
        List<Result> results = new ArrayList<>();
        for (Case c : cases) {
            System.err.println("bench: " + c.name() + " …");
            Result r = spawn(c);
            results.add(r);
            System.err.println("bench: " + c.name() + (r.error() != null ? " FAILED: " + r.error()
                    : String.format(Locale.ROOT, " cold %.2f s, warm %.2f s, peak %.2f GB", r.coldMillis() / 1e3,
                            r.warmMillis() / 1e3, r.peakRssBytes() / 1e9)));
        }
        boolean plotted = plot(cases, results, outDir.resolve("performance.png"));
        String md = report(cases, results) + (plotted ? "\n![time against range, ppd and level of detail](performance.png)\n" : "");
        Files.writeString(outDir.resolve("performance.md"), md);
        System.out.println(md);
        return 0;
    }

    private Result spawn(Case c) throws IOException, InterruptedException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = List.of(java, "-Xmx" + c.heap(), "-cp", System.getProperty("java.class.path"),
                Benchmark.class.getName(), "--child", new Gson().toJson(c));
        Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String last = null;
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = in.readLine()) != null; ) {
                if (line.startsWith("RESULT ")) {
                    last = line.substring(7);
                }
            }
        }
        int rc = p.waitFor();
        if (last == null) {
            return new Result(c.name(), Double.NaN, Map.of(), Double.NaN, Map.of(), Double.NaN, 0, 0, 0, Double.NaN, Double.NaN,
                    Double.NaN, Double.NaN, Double.NaN, "", "child JVM exited with " + rc + " and no result (see its output)");
        }
        return new Gson().fromJson(last, Result.class);
    }

    /** In the fresh JVM: cold render at the viewpoint, then warm renders of viewpoints 2, 4 and 6 km away. */
    private static int runChild(Case c) {
        Result r;
        try {
            r = measure(c);
        } catch (Throwable e) {
            r = new Result(c.name(), Double.NaN, Map.of(), Double.NaN, Map.of(), Double.NaN, peakRss(), 0, 0, Double.NaN,
                    Double.NaN, Double.NaN, Double.NaN, Double.NaN, "", e.toString());
        }
        System.out.println("RESULT " + new GsonBuilder().serializeSpecialFloatingPointValues().create().toJson(r));
        return 0;
    }

    private static Result measure(Case c) throws IOException {
        if (c.camera() != null) {
            return measureCamera(c);
        }
        long t0 = System.nanoTime();
        DemDirectory dem = new DemDirectory(Path.of(c.dem()), 64);
        boolean reference = c.renderer().equals("reference");
        PanoramaRequest a = PanoramaRequest.at(c.lat(), c.lon()).withRangeMetres(c.rangeKm() * 1000)
                .withPixelsPerDegree(c.ppd()).withLodErrorPx(c.lodPx()).withColour(c.colour()).withDistance(c.distance());
        // Warm: other viewpoints in the same area, each 2 km north-east of the one before.
        PanoramaRequest[] warmAt = new PanoramaRequest[3];
        for (int i = 0; i < warmAt.length; i++) {
            warmAt[i] = PanoramaRequest.at(c.lat() + 0.0127 * (i + 1), c.lon() + 0.0185 * (i + 1))
                    .withRangeMetres(c.rangeKm() * 1000).withPixelsPerDegree(c.ppd()).withLodErrorPx(c.lodPx())
                    .withColour(c.colour()).withDistance(c.distance());
        }
        try (PanoramaRenderer r = reference ? PanoramaRenderer.openReference(dem) : PanoramaRenderer.open(dem)) {
            double openMillis = (System.nanoTime() - t0) / 1e6;
            Panorama cold = r.render(a);
            double coldMillis = (System.nanoTime() - t0) / 1e6;
            Map<String, Double> coldStages = new LinkedHashMap<>();
            coldStages.put("context", openMillis);
            coldStages.putAll(cold.metadata().timingsMillis());
            Path tmp = Files.createTempDirectory("dempano-bench");
            long w0 = System.nanoTime();
            List<Path> written = PanoramaWriter.write(cold, tmp.resolve("p").toString(), false);
            double writeMillis = (System.nanoTime() - w0) / 1e6;
            for (Path f : written) {
                Files.deleteIfExists(f);
            }
            Files.deleteIfExists(tmp);
            // Warm: three renders of three viewpoints, the median reported.
            double[] warm = new double[warmAt.length];
            Panorama last = null;
            List<Map<String, Double>> stages = new ArrayList<>();
            for (int i = 0; i < warm.length; i++) {
                long s = System.nanoTime();
                last = r.render(warmAt[i]);
                warm[i] = (System.nanoTime() - s) / 1e6;
                stages.add(last.metadata().timingsMillis());
            }
            int median = argMedian(warm);
            long peak = peakRss(); // before the reference comparison, which is not part of the case
            double refMillis = Double.NaN, med = Double.NaN, p99 = Double.NaN, sky = Double.NaN, over5 = Double.NaN;
            if (c.compare()) {
                try (PanoramaRenderer cpu = PanoramaRenderer.openReference(dem)) {
                    PanoramaRequest b = warmAt[warmAt.length - 1];
                    cpu.render(b); // warm its JIT too
                    long s = System.nanoTime();
                    Panorama ref = cpu.render(b);
                    refMillis = (System.nanoTime() - s) / 1e6;
                    DistanceComparison d = DistanceComparison.of(last.distanceArray(), ref.distanceArray(), ref.widthPx());
                    med = d.medianRelative();
                    p99 = d.p99Relative();
                    sky = d.skylineMeanAbsPx();
                    over5 = d.shareOver5Percent();
                }
            }
            return new Result(c.name(), coldMillis, coldStages, warm[median], stages.get(median), writeMillis, peak,
                    last.metadata().terrainTriangles(), last.metadata().tilesUsed().size(), refMillis, med, p99, sky, over5,
                    r.glRenderer(), null);
        }
    }

    /**
     * A camera case: cold render (with opening the renderer) and write of the photo's outputs, then the median of
     * warm renders of the same camera at the panorama cases' warm viewpoints (2, 4 and 6 km away).
     */
    private static Result measureCamera(Case c) throws IOException {
        long t0 = System.nanoTime();
        DemDirectory dem = new DemDirectory(Path.of(c.dem()), 64);
        Camera cam = c.camera();
        dempano.camera.CameraOrientation o = new dempano.camera.CameraOrientation(cam.headingDeg(), cam.pitchDeg(), 0);
        CameraRequest[] at = new CameraRequest[4];
        for (int i = 0; i < at.length; i++) {
            double lat = c.lat() + 0.0127 * i, lon = c.lon() + 0.0185 * i;
            at[i] = new CameraRequest(cam.intrinsics(), new dempano.camera.CameraPose(lat, lon, 0, Double.NaN, 2, o),
                    PanoramaRequest.at(lat, lon).withRangeMetres(c.rangeKm() * 1000).withLodErrorPx(c.lodPx())
                            .withColour(c.colour()).withDistance(c.distance()));
        }
        try (PanoramaRenderer r = c.renderer().equals("reference") ? PanoramaRenderer.openReference(dem) : PanoramaRenderer.open(dem)) {
            double openMillis = (System.nanoTime() - t0) / 1e6;
            CameraImage cold = r.render(at[0]);
            double coldMillis = (System.nanoTime() - t0) / 1e6;
            Map<String, Double> coldStages = new LinkedHashMap<>();
            coldStages.put("context", openMillis);
            coldStages.putAll(cold.metadata().timingsMillis());
            Path tmp = Files.createTempDirectory("dempano-bench");
            long w0 = System.nanoTime();
            List<Path> written = CameraWriter.write(cold, tmp.resolve("p").toString(), CameraWriter.Extras.NONE);
            double writeMillis = (System.nanoTime() - w0) / 1e6;
            for (Path f : written) {
                Files.deleteIfExists(f);
            }
            Files.deleteIfExists(tmp);
            cold = null;
            double[] warm = new double[at.length - 1];
            CameraImage last = null;
            List<Map<String, Double>> stages = new ArrayList<>();
            for (int i = 0; i < warm.length; i++) {
                last = null;
                long s = System.nanoTime();
                last = r.render(at[i + 1]);
                warm[i] = (System.nanoTime() - s) / 1e6;
                stages.add(last.metadata().timingsMillis());
            }
            int median = argMedian(warm);
            return new Result(c.name(), coldMillis, coldStages, warm[median], stages.get(median), writeMillis, peakRss(),
                    last.metadata().terrainTriangles(), last.metadata().tilesUsed().size(), Double.NaN, Double.NaN, Double.NaN,
                    Double.NaN, Double.NaN, r.glRenderer(), null);
        }
    }

    private static int argMedian(double[] v) {
        Integer[] idx = {0, 1, 2};
        Arrays.sort(idx, (i, j) -> Double.compare(v[i], v[j]));
        return idx[1];
    }

    /** Peak resident set of this process (Java heap, native buffers, the GL driver), bytes. */
    static long peakRss() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("VmHWM:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) * 1024;
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux: reported as 0
        }
        return 0;
    }

    private static String f(double v, String fmt) {
        return Double.isNaN(v) ? "–" : String.format(Locale.ROOT, fmt, v);
    }

    private static String stages(Map<String, Double> m) {
        StringBuilder sb = new StringBuilder();
        m.forEach((k, v) -> sb.append(sb.length() == 0 ? "" : ", ").append(k).append(' ').append(Math.round(v)));
        return sb.toString();
    }

    static String report(List<Case> cases, List<Result> results) throws IOException {
        StringBuilder md = new StringBuilder();
        String commit = ReportTool.commit("**/performance.md", "**/performance.png");
        String gl = results.stream().map(Result::glRenderer).filter(s -> s != null && !s.isEmpty() && !s.startsWith("dempano"))
                .findFirst().orElse("?");
        md.append("# Performance\n\nGenerated by `gradle bench` (class `dempano.bench.Benchmark`); do not edit by hand.\n\n");
        md.append(String.format(Locale.ROOT, "- Commit %s; %d cores, Java %s; OpenGL renderer `%s`.%n", commit,
                Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"), gl));
        md.append("- 360° panoramas, elevation −30°…30°, refraction 0.13, eye 2 m above the DEM. Each case runs in a fresh JVM:\n"
                + "  **cold** = opening the renderer (GL context, shaders) + the first render, tiles decoded from disk;\n"
                + "  **warm** = median of three renders in the same JVM of three other viewpoints, 2, 4 and 6 km away "
                + "(tiles, patch deviations and fine patches' geometry with its GL buffers cached; the error is that of the last one).\n"
                + "- Stages (ms): context, tiles (load + mosaic), mesh (level of detail, culling, placing what is not cached), upload (scene to GL,\n"
                + "  culling), draw (8 views, to glFinish), readback, triangles (the seen triangles resolved for exact distances),\n"
                + "  stitch; draw and readback overlap triangles and stitch (the views are stitched while the next are drawn);\n"
                + "  write = PNG + .npy + distance PNG + JSON.\n"
                + "- Outputs: both = colour image and distance map; distance = distances only (no shading, colour read-back or\n"
                + "  colour stitching); colour = colour only (no depth linearization or distance interpolation).\n"
                + "- Peak memory: the process's peak resident set (VmHWM: heap, native buffers and the GL driver).\n"
                + "- LOD: bound on the screen error of simplified terrain, panorama pixels (0 = full resolution).\n"
                + "- Error: the warm panorama against the CPU reference on the full-resolution surface (relative distance error).\n"
                + "- Generated relief: `dempano.bench.FractalRelief` (ridged fractal noise, rough at every scale), as .hgt files.\n\n");
        md.append("| case | scene | renderer | ppd | LOD px | outputs | cold s | warm s | warm stages ms | write ms | peak GB | triangles | median err | p99 err | skyline px | reference s |\n");
        md.append("|---|---|---|---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            Result r = results.get(i);
            if (r.error() != null) {
                md.append(String.format(Locale.ROOT, "| %s | %s | %s | %.0f | %s | %s | failed: %s |||||||||%n", c.name(), c.scene(),
                        c.renderer(), c.ppd(), f(c.lodPx(), "%.2g"), c.outputs(), r.error().replace('|', '/')));
                continue;
            }
            md.append(String.format(Locale.ROOT, "| %s | %s | %s | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |%n",
                    c.name(), c.scene(), c.renderer(), c.ppd(), c.renderer().equals("reference") ? "exact" : f(c.lodPx(), "%.2g"),
                    c.outputs(), f(r.coldMillis() / 1e3, "%.2f"), f(r.warmMillis() / 1e3, "%.2f"),
                    stages(r.warmStages()), f(r.writeMillis(), "%.0f"), f(r.peakRssBytes() / 1e9, "%.2f"),
                    r.triangles() == 0 ? "–" : String.format(Locale.ROOT, "%.2f M", r.triangles() / 1e6),
                    f(r.medianRel() * 100, "%.1e %%"), f(r.p99Rel() * 100, "%.1e %%"), f(r.skylineMeanPx(), "%.3f"),
                    f(r.referenceMillis() / 1e3, "%.2f")));
        }
        md.append("\nCold stages (ms) per case:\n\n| case | cold stages ms |\n|---|---|\n");
        for (int i = 0; i < cases.size(); i++) {
            if (results.get(i).error() == null) {
                md.append("| ").append(cases.get(i).name()).append(" | ").append(stages(results.get(i).coldStages())).append(" |\n");
            }
        }
        return md.toString();
    }

    /**
     * The curves as pictures: time against range and against ppd (cold and warm), and the level of
     * detail's error against warm time. Writes nothing (returns false) when a subset of cases leaves
     * no curve of two points or more.
     */
    static boolean plot(List<Case> cases, List<Result> results, Path png) throws IOException {
        Map<String, Case> byName = new LinkedHashMap<>();
        Map<String, Result> ok = new LinkedHashMap<>();
        for (int i = 0; i < cases.size(); i++) {
            if (results.get(i).error() == null) {
                byName.put(cases.get(i).name(), cases.get(i));
                ok.put(cases.get(i).name(), results.get(i));
            }
        }
        List<XYChart> charts = new ArrayList<>();
        // The default scene (srtm3-150km: 150 km, 20 ppd) is a point on both curves.
        List<String> range = ok.keySet().stream().filter(n -> n.startsWith("range-") || n.equals("srtm3-150km"))
                .sorted(Comparator.comparingDouble(n -> byName.get(n).rangeKm())).toList();
        List<String> ppd = ok.keySet().stream().filter(n -> n.startsWith("ppd-") || n.equals("srtm3-150km"))
                .sorted(Comparator.comparingDouble(n -> byName.get(n).ppd())).toList();
        if (range.size() >= 2) {
            charts.add(timeChart("time against range (3×3 SRTM3, 20 ppd)", "range, km", range, byName, ok, Case::rangeKm));
        }
        if (ppd.size() >= 2) {
            charts.add(timeChart("time against resolution (150 km)", "pixels per degree", ppd, byName, ok, Case::ppd));
        }
        List<String> lod = ok.keySet().stream().filter(n -> (n.startsWith("srtm3-150km-lod-") || n.equals("srtm3-150km"))
                && !Double.isNaN(ok.get(n).p99Rel())).sorted(Comparator.comparingDouble(n -> byName.get(n).lodPx())).toList();
        if (lod.size() >= 2) {
            XYChart chart = chart("level of detail: error against warm time (3×3, 150 km)", "warm render time, s",
                    "p99 relative distance error, %");
            chart.getStyler().setYAxisDecimalPattern("0.000");
            double[] xs = lod.stream().mapToDouble(n -> ok.get(n).warmMillis() / 1e3).toArray();
            double[] ys = lod.stream().mapToDouble(n -> ok.get(n).p99Rel() * 100).toArray();
            chart.addSeries("GPU path, each point's LOD bound in px", xs, ys).setMarker(SeriesMarkers.CIRCLE);
            // Room around the points (XChart fits the axes to the data's extremes).
            double x0 = Arrays.stream(xs).min().orElseThrow(), x1 = Arrays.stream(xs).max().orElseThrow();
            double y0 = Arrays.stream(ys).min().orElseThrow(), y1 = Arrays.stream(ys).max().orElseThrow();
            chart.getStyler().setXAxisMin(x0 - 0.15 * (x1 - x0) - 0.02).setXAxisMax(x1 + 0.15 * (x1 - x0) + 0.02);
            chart.getStyler().setYAxisMin(Math.max(0, y0 - 0.2 * (y1 - y0) - 0.01)).setYAxisMax(y1 + 0.2 * (y1 - y0) + 0.01);
            chart.getStyler().setXAxisDecimalPattern("0.00");
            for (int i = 0; i < xs.length; i++) {
                chart.addAnnotation(new AnnotationText(String.format(Locale.ROOT, "%.2g px",
                        byName.get(lod.get(i)).lodPx()), xs[i], ys[i] + 0.06 * (y1 - y0) + 0.003, false));
            }
            charts.add(chart);
        }
        if (charts.isEmpty()) {
            return false;
        }
        BitmapEncoder.saveBitmap(charts, 1, charts.size(), png.toString().replaceFirst("\\.png$", ""),
                BitmapEncoder.BitmapFormat.PNG);
        return true;
    }

    private static XYChart chart(String title, String x, String y) {
        XYChart chart = new XYChartBuilder().width(520).height(380).title(title).xAxisTitle(x).yAxisTitle(y).build();
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        return chart;
    }

    private static XYChart timeChart(String title, String x, List<String> names, Map<String, Case> cases,
                                     Map<String, Result> results, ToDoubleFunction<Case> axis) {
        XYChart chart = chart(title, x, "time, s");
        double[] xs = names.stream().mapToDouble(n -> axis.applyAsDouble(cases.get(n))).toArray();
        chart.addSeries("cold (fresh JVM)", xs, names.stream().mapToDouble(n -> results.get(n).coldMillis() / 1e3).toArray())
                .setMarker(SeriesMarkers.CIRCLE);
        chart.addSeries("warm", xs, names.stream().mapToDouble(n -> results.get(n).warmMillis() / 1e3).toArray())
                .setMarker(SeriesMarkers.CIRCLE);
        chart.addSeries("warm draw", xs, names.stream().mapToDouble(n -> results.get(n).warmStages()
                .getOrDefault("draw", Double.NaN) / 1e3).toArray()).setMarker(SeriesMarkers.DIAMOND);
        return chart;
    }
}
