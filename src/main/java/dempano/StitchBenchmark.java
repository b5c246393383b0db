package dempano;

import dempano.dem.DemDirectory;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The stitch alone, timed: renders a panorama once (GL), keeps what its stitch passes were given, and runs
 * {@link dempano.panorama.Stitcher#stitch} again on them (all passes, one after the other) several times. Reports the process's CPU time
 * per stitch (all threads: robust to other processes on the machine, unlike wall time) and wall
 * time, minimum, median and maximum, and a checksum of the distance map (equal checksums: the same
 * map, bit for bit). {@code gradle stitchBench -Pruns=N} (Mount Washington, 100 km, 20 px/°; the options
 * below choose another scene when run directly).
 */
@Command(name = "stitch-bench", mixinStandardHelpOptions = true, description = "Times the stitch alone on one render.")
public final class StitchBenchmark implements Callable<Integer> {
    @Option(names = "--dem", description = "DEM folder (default: ${DEFAULT-VALUE}).", defaultValue = "../shared/dem")
    Path dem;
    @Option(names = "--lat", description = "Viewpoint, degrees north (default: ${DEFAULT-VALUE}, Mount Washington).", defaultValue = "44.2706")
    double lat;
    @Option(names = "--lon", description = "Viewpoint, degrees east (default: ${DEFAULT-VALUE}).", defaultValue = "-71.3033")
    double lon;
    @Option(names = "--range-km", description = "Range of sight, km (default: ${DEFAULT-VALUE}).", defaultValue = "100")
    double rangeKm;
    @Option(names = "--ppd", description = "Pixels per degree (default: ${DEFAULT-VALUE}).", defaultValue = "20")
    double ppd;
    @Option(names = "--elevation-range", paramLabel = "BOTTOM:TOP", description = "Elevation range, degrees (default: ${DEFAULT-VALUE}).", defaultValue = "-30:30")
    String elevationRange;
    @Option(names = "--runs", description = "Timed stitches after one warm-up (default: ${DEFAULT-VALUE}).", defaultValue = "7")
    int runs;

    public static void main(String[] args) {
        System.exit(dempano.bench.ReportTool.run(new StitchBenchmark(), args));
    }

    @Override
    public Integer call() throws Exception {
        if (runs < 1) {
            throw new IllegalArgumentException("--runs must be at least 1, got " + runs);
        }
        List<PanoramaRenderer.StitchInputs> kept = java.util.Collections.synchronizedList(new ArrayList<>());
        PanoramaRenderer.stitchTap = kept::add;
        PanoramaRequest req = PanoramaRequest.at(lat, lon).withRangeMetres(rangeKm * 1000).withPixelsPerDegree(ppd)
                .withElevationRange(dempano.panorama.ElevationRange.parse(elevationRange));
        try (PanoramaRenderer r = PanoramaRenderer.open(new DemDirectory(dem, 64))) {
            r.render(req);
        } finally {
            PanoramaRenderer.stitchTap = null;
        }
        PanoramaRenderer.StitchInputs in = kept.get(0); // the passes share target, layout and outputs
        int pixels = in.target().widthPx() * in.target().heightPx();
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        List<double[]> times = new ArrayList<>();
        String checksum = null;
        dempano.panorama.Stitcher.Result result = null;
        for (int i = 0; i < runs + 1; i++) { // the first run warms the JIT and is not counted
            int[] argb = in.colour() ? new int[pixels] : null;
            float[] distance = new float[pixels];
            long c0 = os.getProcessCpuTime(), w0 = System.nanoTime();
            long exactPixels = 0, probed = 0, fallback = 0;
            for (PanoramaRenderer.StitchInputs pass : kept) {
                var r = dempano.panorama.Stitcher.stitch(pass.target(), pass.layout(), pass.captures(), pass.inverseEyeDepth(),
                        pass.exact(), argb, distance);
                exactPixels += r.exactPixels();
                probed += r.probedPixels();
                fallback += r.fallbackPixels();
            }
            result = new dempano.panorama.Stitcher.Result(exactPixels, probed, fallback);
            long c1 = os.getProcessCpuTime(), w1 = System.nanoTime();
            if (i > 0) {
                times.add(new double[] {(c1 - c0) / 1e6, (w1 - w0) / 1e6});
            }
            String sum = Integer.toHexString(Arrays.hashCode(distance)) + (argb == null ? "" : "/" + Integer.toHexString(Arrays.hashCode(argb)));
            if (checksum != null && !checksum.equals(sum)) {
                throw new IllegalStateException("the stitch is not deterministic: " + checksum + " then " + sum);
            }
            checksum = sum;
        }
        double[] cpu = times.stream().mapToDouble(t -> t[0]).sorted().toArray();
        double[] wall = times.stream().mapToDouble(t -> t[1]).sorted().toArray();
        System.out.printf(Locale.ROOT, "%d×%d px, %d runs after one warm-up; %s%n", in.target().widthPx(), in.target().heightPx(),
                runs, result);
        System.out.println("| stitch | min ms | median ms | max ms |");
        System.out.println("|---|---:|---:|---:|");
        System.out.printf(Locale.ROOT, "| CPU (process, all threads) | %.0f | %.0f | %.0f |%n", cpu[0], cpu[cpu.length / 2], cpu[cpu.length - 1]);
        System.out.printf(Locale.ROOT, "| wall | %.0f | %.0f | %.0f |%n", wall[0], wall[wall.length / 2], wall[wall.length - 1]);
        System.out.println("checksum (distance/colour): " + checksum);
        return 0;
    }
}
