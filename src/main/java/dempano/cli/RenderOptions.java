package dempano.cli;

import dempano.PanoramaRequest;
import dempano.dem.DemFill;
import dempano.dem.MissingTilePolicy;
import dempano.dem.PriorityDem;
import dempano.dem.VoidFill;
import dempano.geo.Refraction;
import dempano.panorama.DepthMode;
import dempano.panorama.Layer;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import picocli.CommandLine.Option;

/**
 * The options that shape any rendered view, a panorama or a photograph's camera view, declared once as a
 * picocli mixin: range, refraction, supersampling, exact distances, layers, depth mode, near plane, level of
 * detail, missing tiles, renderer, void fill and DEM blend. {@link PanoramaOptions} holds these plus the panorama-only
 * ones (pixels per degree, elevation range, views, ...); {@code dempano photo} takes these alone, since its
 * pose and lens come from the photo or its own flags. Plain values: serializable (the Spark job ships them).
 */
public class RenderOptions implements Serializable {
    private static final long serialVersionUID = 1L;

    @Option(names = "--range-km", description = "Range of sight, km (default: 100; 60 for the panorama command's built-in demo scene).")
    public Double rangeKm;
    @Option(names = "--refraction", paramLabel = "K", description = "Refraction coefficient k: apparent lift k·d²/2R; 0 = off (default: ${DEFAULT-VALUE}).", defaultValue = "0.13")
    public double refraction = Refraction.STANDARD.coefficient();
    @Option(names = "--depth-mode", paramLabel = "MODE", description = "shader (exact float range, default), reversed32f (reversed-Z float depth), standard24 (the thesis's 24-bit linearization).", defaultValue = "shader")
    public String depthMode = "shader";
    @Option(names = "--layers", split = ",", paramLabel = "LAYER", description = "Extra per-pixel layers, comma-separated: elevation, latitude, longitude, ground-distance, incidence (degrees between ray and terrain), uncertainty (metres of distance error from SRTM's 10 m vertical error).")
    public List<String> layers = new ArrayList<>();
    @Option(names = "--near-m", description = "Near plane, metres: an upper bound, lowered where terrain comes nearer to the eye (P.json has the one used) (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    public double nearMetres = 1;
    @Option(names = "--supersampling", description = "View pixels per output pixel (panorama or photo pixel), linear (default: ${DEFAULT-VALUE}).", defaultValue = "1")
    public double supersampling = 1;
    @Option(names = "--lod-px", paramLabel = "PX", description = "Bound on the screen error of simplified distant terrain, output pixels; 0 = full resolution everywhere (default: ${DEFAULT-VALUE}).", defaultValue = "" + dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX)
    public double lodErrorPx = dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX;
    @Option(names = "--exact-distances", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "Measure every pixel's distance along its own centre ray (exact at grazing incidence and at silhouettes; default). --no-exact-distances interpolates the views' depth instead: faster, but tens of per cent off at grazing incidence.")
    public boolean exactDistances = true;
    @Option(names = "--missing-tiles", paramLabel = "auto|sea|error", description = "A needed tile that is absent: auto (default: sea level, 0 m, with a warning for tiles beside the data, as at coasts; an error when no needed tile is present, or the viewpoint's own tile is missing and --altitude-m is not given), sea (every missing tile is sea level, with a warning) or error (fail, listing every missing tile).", defaultValue = "auto")
    public String missingTiles = "auto";
    @Option(names = "--renderer", paramLabel = "opengl|reference", description = "opengl (default; GPU or Mesa llvmpipe) or reference (exact CPU horizon sweep, no OpenGL needed; slower).", defaultValue = "opengl")
    public String renderer = "opengl";
    @Option(names = "--void-fill", paramLabel = "thin-plate|laplace|idw", defaultValue = "thin-plate",
            description = "How DEM voids no --dem-dir fills are interpolated: thin-plate (default: carries the slopes around a void on into it, so a summit in a void is rebuilt above its rim), laplace (smoothest membrane, never above the rim) or idw (inverse-distance weighting along eight directions, as GDAL's FillNodata; the previous default). Compared on surveyed summits in docs/void-fill.md.")
    public String voidFill = "thin-plate";
    @Option(names = "--dem-blend", paramLabel = "delta-surface|as-is", defaultValue = "delta-surface",
            description = "How a later --dem-dir fills the voids of an earlier one: delta-surface (default: its heights plus the difference between the two at the void's rim, interpolated over the void, so a coarser or offset source meets the first without a step; where it holds the first's true heights they go in unchanged) or as-is (its heights, bilinear where its grid differs). Measured in docs/coarse-fill.md.")
    public String demBlend = "delta-surface";

    /**
     * The request these options make of {@code base}: its viewpoint, and whatever these options do not set,
     * are kept.
     *
     * @param defaultRangeMetres the range when {@code --range-km} is not given, metres
     * @throws IllegalArgumentException naming the option, for a bad value
     */
    public PanoramaRequest applyTo(PanoramaRequest base, double defaultRangeMetres) {
        return base.withRangeMetres(rangeKm != null ? rangeKm * 1000 : defaultRangeMetres)
                .withRefraction(new Refraction(refraction)).withDepthMode(DepthMode.fromOptionName(depthMode))
                .withLayers(layers()).withNearMetres(nearMetres).withSupersampling(supersampling)
                .withMissingTiles(missingTilePolicy()).withLodErrorPx(lodErrorPx).withExactDistances(exactDistances);
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
        return missingTilePolicy(missingTiles);
    }

    /** A {@code --missing-tiles} value (auto, sea, error). */
    static MissingTilePolicy missingTilePolicy(String missingTiles) {
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

    /** The values of {@code --void-fill} and {@code --dem-blend}: how the DEM's voids are filled. */
    public DemFill demFill() {
        return new DemFill(voidFillMethod(), PriorityDem.Blend.parse(demBlend));
    }

    /** Checks every option (a bad one is a bad argument before anything is read or rendered). */
    public void check() {
        applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
        referenceRenderer();
        demFill();
    }
}
