package dempano.spark;

import dempano.PanoramaRequest;
import dempano.cli.PanoramaOptions;
import dempano.io.PanoramaWriter;
import dempano.io.SummitWriter;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

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
    /**
     * The folder relative image paths start from, as {@code dempano batch} takes them from the viewpoint file's folder:
     * a local path, or a Hadoop URI (the image then copied to the node); null = the executor's working directory.
     */
    public String tableDir;
    /** Hadoop settings from the driver (spark.hadoop.*, core-site.xml), applied on the executors. */
    public Map<String, String> hadoop = new HashMap<>();

    /** The panorama options, as {@code dempano batch} takes them. */
    public PanoramaOptions panorama = new PanoramaOptions();

    /** The request every row starts from; built as {@code dempano batch} builds it from the same options. */
    public PanoramaRequest defaults() {
        return panorama.applyTo(PanoramaRequest.at(0, 0), PanoramaRequest.DEFAULT_RANGE_METRES);
    }

    /** File options, as {@code dempano batch} writes. */
    public PanoramaWriter.Options writing() {
        return new PanoramaWriter.Options(panorama.pfm, null, SummitWriter.LabelOptions.DEFAULT);
    }

    /** True for the CPU reference renderer. */
    public boolean reference() {
        return panorama.referenceRenderer();
    }

    /** The key under which an executor keeps its renderer: the DEM and the renderer kind. */
    String rendererKey() {
        return String.join("\u0000", demDirs) + "\u0000" + reference() + "\u0000" + panorama.view.voidFill + "\u0000" + panorama.view.demBlend + "\u0000" + hadoop.hashCode();
    }

    /** Checks the settings on the driver (a bad option fails before any task starts). */
    public void check() {
        Objects.requireNonNull(outDir, "outDir");
        if (demDirs.isEmpty()) {
            throw new IllegalArgumentException("no DEM folder given");
        }
        panorama.check();
    }
}
