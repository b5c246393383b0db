package dempano.cli;

import dempano.dem.DemoTerrain;
import dempano.geo.Refraction;
import dempano.render.OnscreenRenderer;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code dempano fly}: the on-screen fly-through over a DEM (see {@link OnscreenRenderer#KEYS}). */
@Command(name = "fly", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Fly over the DEM in a window to look for anomalies (voids, spikes, seams, wrong altitudes).",
            "Keys: W/S forward/back, A/D left/right, Q/Z up/down, arrows or mouse drag turn; +/- speed;",
            "F1 wireframe, F2 debug colours (filled voids magenta, missing tiles red, tile seams yellow),",
            "F3 vertical exaggeration, F4 curvature/refraction, P panorama here, K screenshot, Esc quit.",
            "Needs a display (under Xvfb: DEMPANO_GL=x11 xvfb-run -a ...)."})
public final class FlyCommand implements Callable<Integer> {
    @Option(names = "--lat", description = "Start latitude, degrees north. Default: the demo scene's.")
    Double latDeg;
    @Option(names = "--lon", description = "Start longitude, degrees east. Default: the demo scene's.")
    Double lonDeg;
    @Option(names = "--dem-dir", paramLabel = "DIR", description = "Directory of DEM tiles (.hgt, GeoTIFF); repeatable, "
            + "in priority order, as for rendering. Default: the demo DEM.")
    java.util.List<Path> demDirs;
    @Option(names = "--above-ground-m", description = "Start height above the DEM, metres (default: ${DEFAULT-VALUE}).", defaultValue = "300")
    double aboveGroundMetres;
    @Option(names = "--range-km", description = "Terrain built within this distance of the start, km (default: ${DEFAULT-VALUE}).", defaultValue = "40")
    double rangeKm;
    @Option(names = "--heading-deg", description = "Start heading, degrees clockwise from north (default: ${DEFAULT-VALUE}).", defaultValue = "0")
    double headingDeg;
    @Option(names = "--pitch-deg", description = "Start pitch, degrees up (default: ${DEFAULT-VALUE}).", defaultValue = "-10")
    double pitchDeg;
    @Option(names = "--speed-mps", description = "Flight speed, metres per second (default: ${DEFAULT-VALUE}).", defaultValue = "200")
    double speed;
    @Option(names = "--frames", description = "Scripted: fly this many frames (1/30 s each) straight along the heading, write --screenshot and quit (default: interactive).", defaultValue = "0")
    int frames;
    @Option(names = "--screenshot", paramLabel = "FILE", description = "Scripted mode's screenshot (PNG).")
    Path screenshot;
    @Option(names = "--panorama-at-end", description = "Scripted: also render the 360° panorama (key P) at the end and wait for it.")
    boolean panoramaAtEnd;
    /** Accepted for old scripts: there is no settings dialog (the flags set the window). */
    @Option(names = "--no-dialog", hidden = true)
    boolean noDialog;
    @Option(names = "--wireframe", description = "Start in wireframe.")
    boolean wireframe;
    @Option(names = "--debug-colours", description = "Start with filled voids, missing tiles and tile seams highlighted.")
    boolean debugColours;
    @Option(names = "--exaggeration", description = "Vertical exaggeration (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    double exaggeration;
    @Option(names = "--refraction", paramLabel = "K", description = "Refraction coefficient; 1 = flat earth (default: ${DEFAULT-VALUE}).", defaultValue = "0.13")
    double refraction;
    @Option(names = "--width", description = "Window width, pixels (default: ${DEFAULT-VALUE}).", defaultValue = "1280")
    int width;
    @Option(names = "--height", description = "Window height, pixels (default: ${DEFAULT-VALUE}).", defaultValue = "720")
    int height;
    @Option(names = "--missing-tiles", paramLabel = "auto|sea|error", description = "A needed tile that is absent, as for "
            + "a panorama: auto (default: sea level with a warning; an error when no needed tile is present or the start's "
            + "own is missing), sea or error.", defaultValue = "auto")
    String missingTiles;
    @Option(names = "--out-dir", paramLabel = "DIR", description = "Where panoramas (P) and screenshots (K) go (default: ${DEFAULT-VALUE}).", defaultValue = "build/fly")
    Path outDir;

    @Override
    public Integer call() throws Exception {
        boolean noDem = demDirs == null || demDirs.isEmpty();
        boolean demo = latDeg == null && lonDeg == null && noDem;
        if (!demo && (latDeg == null || lonDeg == null || noDem)) {
            throw new IllegalArgumentException("give --lat, --lon and --dem-dir (or none of them, for the demo scene)");
        }
        if (frames < 0 || (frames > 0 && screenshot == null)) {
            throw new IllegalArgumentException("--frames needs --screenshot FILE (and a count ≥ 1)");
        }
        check(rangeKm > 0 && rangeKm <= 300, "--range-km", "in (0, 300]", rangeKm);
        check(exaggeration >= 0.1 && exaggeration <= 100, "--exaggeration", "in [0.1, 100]", exaggeration);
        check(speed > 0 && speed <= 100_000, "--speed-mps", "in (0, 100000]", speed);
        check(Double.isFinite(headingDeg), "--heading-deg", "a finite number of degrees", headingDeg);
        // Straight up or down leaves the view's roll undefined.
        check(pitchDeg >= -89 && pitchDeg <= 89, "--pitch-deg", "in [-89, 89]", pitchDeg);
        check(width >= 64 && width <= 16384, "--width", "in [64, 16384] pixels", width);
        check(height >= 64 && height <= 16384, "--height", "in [64, 16384] pixels", height);
        if (screenshot != null) {
            String name = screenshot.getFileName() == null ? "" : screenshot.getFileName().toString();
            if (!name.toLowerCase(java.util.Locale.ROOT).endsWith(".png") || name.length() == 4) {
                throw new IllegalArgumentException("--screenshot must name a .png file, got '" + screenshot + "'");
            }
            if (java.nio.file.Files.isDirectory(screenshot)) {
                throw new IllegalArgumentException("--screenshot " + screenshot + " is a folder; name a .png file in it");
            }
        }
        if (java.nio.file.Files.exists(outDir) && !java.nio.file.Files.isDirectory(outDir)) {
            throw new IllegalArgumentException("--out-dir " + outDir + " is a file, not a folder");
        }
        new Refraction(refraction); // validates
        dempano.dem.MissingTilePolicy missing = RenderOptions.missingTilePolicy(missingTiles);
        if (!demo) { // the arguments before the display, as every other command has them
            dempano.dem.TileSelection.checkCoordinates(latDeg, lonDeg);
            for (Path d : demDirs) {
                if (!java.nio.file.Files.isDirectory(d)) {
                    throw new dempano.dem.DemException(dempano.dem.DemDirectory.notAFolder(d));
                }
            }
        }
        OnscreenRenderer.checkDisplay(); // before the demo DEM is written or jME started
        java.util.List<Path> dirs = demo ? java.util.List.of(DemoTerrain.ensure(DemoTerrain.DEFAULT_DIR)) : demDirs;
        double lat = demo ? DemoTerrain.viewpoint()[0] : latDeg, lon = demo ? DemoTerrain.viewpoint()[1] : lonDeg;
        return OnscreenRenderer.fly(new OnscreenRenderer.Options(dirs, lat, lon, aboveGroundMetres, rangeKm * 1000, headingDeg,
                pitchDeg, speed, frames, screenshot, wireframe, debugColours, exaggeration, refraction, width, height,
                outDir, panoramaAtEnd, missing));
    }

    private static void check(boolean ok, String flag, String range, Object value) {
        if (!ok) {
            throw new IllegalArgumentException(flag + " must be " + range + ", got " + value);
        }
    }
}
