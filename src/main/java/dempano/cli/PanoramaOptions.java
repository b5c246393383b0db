package dempano.cli;

import dempano.PanoramaRequest;
import dempano.dem.VoidFill;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import java.io.Serializable;
import java.util.Set;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The options that shape a panorama, declared once for every command that renders panoramas
 * ({@code dempano}, {@code dempano batch}, the Spark job) as a picocli mixin, so that their names,
 * defaults, checks and messages cannot drift apart. Those that shape camera views too are the nested
 * {@link RenderOptions} ({@link #view}), which {@code dempano photo} takes alone. Plain values: serializable, so that the Spark job
 * ships them to its executors and builds the request there.
 */
public class PanoramaOptions implements Serializable {
    private static final long serialVersionUID = 1L;

    @Option(names = "--ppd", description = "Pixels per degree (default: ${DEFAULT-VALUE}).", defaultValue = "20")
    public double ppd = 20;
    @Option(names = "--offset-m", description = "Signed altitude correction added to the DEM height at the viewpoint, metres (default: ${DEFAULT-VALUE}).", defaultValue = "0")
    public double offsetMetres;
    @Option(names = "--eye-height-m", description = "Eye above the standing altitude, metres (default: ${DEFAULT-VALUE}).", defaultValue = "2")
    public double eyeHeightMetres = 2;
    @Option(names = "--elevation-range", paramLabel = "BOTTOM:TOP|auto", description = "Elevation angles covered, degrees (default: ${DEFAULT-VALUE}); auto crops to the terrain.", defaultValue = "-30:30")
    public String elevationRange = "-30:30";
    @Option(names = "--pfm", description = "Write distance maps as .pfm instead of .npy.")
    public boolean pfm;
    @Option(names = "--views", description = "Number of perspective views (default: ${DEFAULT-VALUE}).", defaultValue = "8")
    public int views = 8;
    @Option(names = "--no-colour", description = "Distances only: skip shading and the colour image (P.png, P-labels.png).")
    public boolean noColour;
    @Option(names = "--no-distance", description = "Colour only: skip the distance map (P-distance.*); its silhouette lines come from the nearest view samples. Not with --layers or --summits.")
    public boolean noDistance;
    /** The options shared with camera views (range, refraction, supersampling, exact distances, layers, renderer, ...). */
    @Mixin
    public RenderOptions view = new RenderOptions();
    /**
     * The request these options make of {@code base} (its viewpoint and whatever these options do not
     * set are kept).
     *
     * @param defaultRangeMetres the range when {@code --range-km} is not given
     * @throws IllegalArgumentException naming the option, for a bad value
     */
    public PanoramaRequest applyTo(PanoramaRequest base, double defaultRangeMetres) {
        return view.applyTo(base, defaultRangeMetres).withOffsetMetres(offsetMetres).withEyeHeightMetres(eyeHeightMetres)
                .withPixelsPerDegree(ppd).withElevationRange(ElevationRange.parse(elevationRange)).withViews(views)
                .withColour(!noColour).withDistance(!noDistance);
    }

    /** The layers of {@code --layers}. */
    public Set<Layer> layers() {
        return view.layers();
    }

    /** True for {@code --renderer reference} (or cpu), false for opengl (or gl). */
    public boolean referenceRenderer() {
        return view.referenceRenderer();
    }

    /** The value of {@code --void-fill}. */
    public VoidFill voidFillMethod() {
        return view.voidFillMethod();
    }

    /** The values of {@code --void-fill} and {@code --dem-blend}. */
    public dempano.dem.DemFill demFill() {
        return view.demFill();
    }

    /** Checks every option (a bad one is a bad argument before anything is read or rendered). */
    public void check() {
        applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
        view.check();
    }
}
