package dempano.cli;

import dempano.PanoramaRequest;
import dempano.dem.MissingTilePolicy;
import dempano.dem.VoidFill;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import picocli.CommandLine.Option;

/**
 * The options that shape a panorama, declared once for every command that renders panoramas
 * ({@code dempano}, {@code dempano batch}, the Spark job) as a picocli mixin, so that their names,
 * defaults, checks and messages cannot drift apart. Plain values: serializable, so that the Spark job
 * ships them to its executors and builds the request there.
 */
public class PanoramaOptions implements Serializable {
    private static final long serialVersionUID = 1L;

    @Option(names = "--ppd", description = "Pixels per degree (default: ${DEFAULT-VALUE}).", defaultValue = "20")
    public double ppd = 20;
    @Option(names = "--range-km", description = "Range of sight, km (default: 100; demo scene: 60).")
    public Double rangeKm;
    @Option(names = "--offset-m", description = "Signed altitude correction added to the DEM height at the viewpoint, metres (default: ${DEFAULT-VALUE}).", defaultValue = "0")
    public double offsetMetres;
    @Option(names = "--eye-height-m", description = "Eye above the standing altitude, metres (default: ${DEFAULT-VALUE}).", defaultValue = "2")
    public double eyeHeightMetres = 2;
    @Option(names = "--refraction", paramLabel = "K", description = "Refraction coefficient k: apparent lift k·d²/2R; 0 = off (default: ${DEFAULT-VALUE}).", defaultValue = "0.13")
    public double refraction = Refraction.STANDARD.coefficient();
    @Option(names = "--elevation-range", paramLabel = "BOTTOM:TOP|auto", description = "Elevation angles covered, degrees (default: ${DEFAULT-VALUE}); auto crops to the terrain.", defaultValue = "-30:30")
    public String elevationRange = "-30:30";
    @Option(names = "--depth-mode", paramLabel = "MODE", description = "shader (exact float range, default), reversed32f (reversed-Z float depth), standard24 (the thesis's 24-bit linearization).", defaultValue = "shader")
    public String depthMode = "shader";
    @Option(names = "--layers", split = ",", paramLabel = "LAYER", description = "Extra per-pixel layers, comma-separated: elevation, latitude, longitude, ground-distance, incidence (degrees between ray and terrain), uncertainty (metres of distance error from SRTM's 10 m vertical error).")
    public List<String> layers = new ArrayList<>();
    @Option(names = "--pfm", description = "Write distance maps as .pfm instead of .npy.")
    public boolean pfm;
    @Option(names = "--near-m", description = "Near plane, metres (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    public double nearMetres = 1;
    @Option(names = "--supersampling", description = "View pixels per panorama pixel, linear (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    public double supersampling = 1;
    @Option(names = "--views", description = "Number of perspective views (default: ${DEFAULT-VALUE}).", defaultValue = "8")
    public int views = 8;
    @Option(names = "--lod-px", paramLabel = "PX", description = "Bound on the screen error of simplified distant terrain, panorama pixels; 0 = full resolution everywhere (default: ${DEFAULT-VALUE}).", defaultValue = "" + dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX)
    public double lodErrorPx = dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX;
    @Option(names = "--exact-distances", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "Measure every pixel's distance along its own centre ray (exact at grazing incidence and at silhouettes; default). --no-exact-distances interpolates the views' depth instead: faster, but tens of per cent off at grazing incidence.")
    public boolean exactDistances = true;
    @Option(names = "--no-colour", description = "Distances only: skip shading and the colour image (P.png, P-labels.png).")
    public boolean noColour;
    @Option(names = "--no-distance", description = "Colour only: skip the distance map (P-distance.*); its silhouette lines come from the nearest view samples. Not with --layers or --summits.")
    public boolean noDistance;
    @Option(names = "--missing-tiles", paramLabel = "auto|sea|error", description = "A needed tile that is absent: auto (default: sea level, 0 m, with a warning for tiles beside the data, as at coasts; an error when no needed tile is present, or the viewpoint's own tile is missing and --altitude-m is not given), sea (every missing tile is sea level, with a warning) or error (fail, listing every missing tile).", defaultValue = "auto")
    public String missingTiles = "auto";
    @Option(names = "--renderer", paramLabel = "opengl|reference", description = "opengl (default; GPU or Mesa llvmpipe) or reference (exact CPU horizon sweep, no OpenGL needed; slower).", defaultValue = "opengl")
    public String renderer = "opengl";
    @Option(names = "--void-fill", paramLabel = "thin-plate|laplace|idw", defaultValue = "thin-plate",
            description = "How DEM voids no --dem-dir fills are interpolated: thin-plate (default: carries the slopes around a void on into it, so a summit in a void is rebuilt above its rim), laplace (smoothest membrane, never above the rim) or idw (inverse-distance weighting along eight directions, as GDAL's FillNodata; the previous default). Compared on surveyed summits in docs/void-fill.md.")
    public String voidFill = "thin-plate";
    @Option(names = "--dem-blend", paramLabel = "as-is|delta-surface", defaultValue = "as-is",
            description = "How a later --dem-dir fills the voids of an earlier one: as-is (default: its heights, bilinear where its grid differs) or delta-surface (its heights plus the difference between the two at the void's rim, interpolated over the void, so a coarser or offset source meets the first without a step). Measured in docs/coarse-fill.md.")
    public String demBlend = "as-is";

    /**
     * The request these options make of {@code base} (its viewpoint and whatever these options do not
     * set are kept).
     *
     * @param defaultRangeMetres the range when {@code --range-km} is not given
     * @throws IllegalArgumentException naming the option, for a bad value
     */
    public PanoramaRequest applyTo(PanoramaRequest base, double defaultRangeMetres) {
        return base.withOffsetMetres(offsetMetres).withEyeHeightMetres(eyeHeightMetres)
                .withRangeMetres(rangeKm != null ? rangeKm * 1000 : defaultRangeMetres).withPixelsPerDegree(ppd)
                .withElevationRange(ElevationRange.parse(elevationRange)).withRefraction(new Refraction(refraction))
                .withDepthMode(DepthMode.fromOptionName(depthMode)).withLayers(layers()).withNearMetres(nearMetres)
                .withSupersampling(supersampling).withViews(views).withMissingTiles(missingTilePolicy())
                .withLodErrorPx(lodErrorPx).withExactDistances(exactDistances).withColour(!noColour).withDistance(!noDistance);
    }

    /** The layers of {@code --layers}. */
    public Set<Layer> layers() {
        Set<Layer> wanted = EnumSet.noneOf(Layer.class);
        if (layers != null) {
            for (String s : layers) {
                wanted.add(Layer.fromName(s.trim()));
            }
        }
        return wanted;
    }

    /** The value of {@code --missing-tiles} (auto, sea, error). */
    public MissingTilePolicy missingTilePolicy() {
        return switch (missingTiles.toLowerCase(Locale.ROOT)) {
            case "auto" -> MissingTilePolicy.AUTO;
            case "sea", "sea-level" -> MissingTilePolicy.SEA_LEVEL;
            case "error" -> MissingTilePolicy.ERROR;
            default -> throw new IllegalArgumentException("--missing-tiles must be auto, sea or error, got " + missingTiles);
        };
    }

    /** True for {@code --renderer reference} (or cpu), false for opengl (or gl). */
    public boolean referenceRenderer() {
        return switch (renderer.toLowerCase(Locale.ROOT)) {
            case "opengl", "gl" -> false;
            case "reference", "cpu" -> true;
            default -> throw new IllegalArgumentException("--renderer must be opengl or reference, got " + renderer);
        };
    }

    /** The value of {@code --void-fill}. */
    public VoidFill voidFillMethod() {
        return VoidFill.parse(voidFill);
    }

    /** The value of {@code --dem-blend}. */
    public dempano.dem.PriorityDem.Blend demBlend() {
        return dempano.dem.PriorityDem.Blend.parse(demBlend);
    }

    /** Checks every option (a bad one is a bad argument before anything is read or rendered). */
    public void check() {
        applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
        referenceRenderer();
        voidFillMethod();
        demBlend();
    }
}
