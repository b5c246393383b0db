package dempano.spark;

import dempano.PanoramaRequest;
import dempano.dem.MissingTilePolicy;
import dempano.geo.Refraction;
import dempano.io.PanoramaWriter;
import dempano.io.SummitWriter;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * What every executor needs to render a row: where the tiles and the outputs are, and the defaults
 * request (the options of {@code dempano batch}, each row's columns override them). Plain values,
 * so that Spark ships it to the executors by Java serialization; the request is rebuilt there.
 */
public final class JobSettings implements Serializable {
    private static final long serialVersionUID = 1L;

    /** DEM folders in priority order: local paths (the same on every node) or Hadoop URIs (copied to each node once). */
    public List<String> demDirs = new ArrayList<>();
    /** Output folder, any Hadoop-compatible URI or a local path. */
    public String outDir;
    /** Hadoop settings from the driver (spark.hadoop.*, core-site.xml), applied on the executors. */
    public Map<String, String> hadoop = new HashMap<>();

    public double ppd = 20;
    public double rangeKm = 100;
    public double offsetMetres = 0;
    public double eyeHeightMetres = 2;
    public double refraction = 0.13;
    public String elevationRange = "-30:30";
    public String depthMode = "shader";
    public List<String> layers = new ArrayList<>();
    public boolean pfm;
    public double nearMetres = 1;
    public double supersampling = 1;
    public int views = 8;
    public double lodErrorPx = dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX;
    public boolean exactDistances = true;
    public boolean colour = true;
    public boolean distance = true;
    public String missingTiles = "auto";
    /** opengl or reference (the CPU renderer). */
    public String renderer = "opengl";

    /** The request every row starts from; built as {@code dempano batch} builds it from the same options. */
    public PanoramaRequest defaults() {
        Set<Layer> wanted = EnumSet.noneOf(Layer.class);
        for (String s : layers) {
            wanted.add(Layer.fromName(s.trim()));
        }
        return PanoramaRequest.at(0, 0).withOffsetMetres(offsetMetres).withEyeHeightMetres(eyeHeightMetres)
                .withRangeMetres(rangeKm * 1000).withPixelsPerDegree(ppd).withElevationRange(ElevationRange.parse(elevationRange))
                .withRefraction(new Refraction(refraction)).withDepthMode(DepthMode.fromOptionName(depthMode))
                .withLayers(wanted).withNearMetres(nearMetres).withSupersampling(supersampling).withViews(views)
                .withMissingTiles(missingTilePolicy(missingTiles)).withLodErrorPx(lodErrorPx)
                .withExactDistances(exactDistances).withColour(colour).withDistance(distance);
    }

    /** File options, as {@code dempano batch} writes. */
    public PanoramaWriter.Options writing() {
        return new PanoramaWriter.Options(pfm, null, SummitWriter.LabelOptions.DEFAULT);
    }

    /** True for the CPU reference renderer. */
    public boolean reference() {
        return switch (renderer.toLowerCase(Locale.ROOT)) {
            case "opengl", "gl" -> false;
            case "reference", "cpu" -> true;
            default -> throw new IllegalArgumentException("--renderer must be opengl or reference, got " + renderer);
        };
    }

    /** The key under which an executor keeps its renderer: the DEM and the renderer kind. */
    String rendererKey() {
        return String.join("\u0000", demDirs) + "\u0000" + reference() + "\u0000" + hadoop.hashCode();
    }

    static MissingTilePolicy missingTilePolicy(String option) {
        return switch (option.toLowerCase(Locale.ROOT)) {
            case "auto" -> MissingTilePolicy.AUTO;
            case "sea", "sea-level" -> MissingTilePolicy.SEA_LEVEL;
            case "error" -> MissingTilePolicy.ERROR;
            default -> throw new IllegalArgumentException("--missing-tiles must be auto, sea or error, got " + option);
        };
    }

    /** Checks the settings on the driver (a bad option fails before any task starts). */
    public void check() {
        Objects.requireNonNull(outDir, "outDir");
        if (demDirs.isEmpty()) {
            throw new IllegalArgumentException("no DEM folder given");
        }
        defaults();
        reference();
    }
}
