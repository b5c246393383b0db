package dempano.io;

import com.google.gson.Gson;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.PanoramaMetadata;
import dempano.summits.SummitSighting;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes a panorama's files for a prefix P as one {@link OutputSet}: {@code P.png} (when it has
 * colour), {@code P-distance.npy} (or {@code .pfm}) and {@code P-distance.png} (when it has
 * distances), {@code P-<layer>.npy}, the summit files when summits are given, and {@code P.json}
 * (listing them). After any failure the previous set stays as it was; see {@link OutputSet}.
 */
public final class PanoramaWriter {
    private PanoramaWriter() {
    }

    /**
     * What is written besides the panorama's own files.
     *
     * @param pfm     distance map as {@code .pfm} instead of {@code .npy}
     * @param summits sightings for {@code P-summits.json/.csv} and {@code P-labels.png}; null for none
     * @param labels  label density of {@code P-labels.png}
     */
    public record Options(boolean pfm, List<SummitSighting> summits, SummitWriter.LabelOptions labels) {
        public static final Options DEFAULT = new Options(false, null, SummitWriter.LabelOptions.DEFAULT);
    }

    /** As {@link #write(Panorama, String, Options)} with no summits. */
    public static List<Path> write(Panorama p, String prefix, boolean pfm) throws IOException {
        return write(p, prefix, new Options(pfm, null, SummitWriter.LabelOptions.DEFAULT));
    }

    /**
     * Writes the files as one set.
     *
     * @return the files written, {@code P.json} last
     * @throws IllegalArgumentException for an empty prefix or one naming a folder
     * @throws IOException naming the file and the reason; no file of the new set is then in place
     */
    public static List<Path> write(Panorama p, String prefix, Options options) throws IOException {
        try (OutputSet set = OutputSet.open(prefix)) {
            List<Path> files = stage(set, p, options);
            set.commit();
            return files;
        }
    }

    /**
     * The suffixes of the files a request will produce (to check the destination before rendering).
     *
     * @param colour   the panorama has colour
     * @param distance the panorama has distances
     */
    public static List<String> suffixes(boolean colour, boolean distance, java.util.Set<Layer> layers, Options options) {
        List<String> out = new ArrayList<>();
        if (colour) {
            out.add(".png");
        }
        if (distance) {
            out.add("-distance." + (options.pfm() ? "pfm" : "npy"));
            out.add("-distance.png");
        }
        layers.forEach(l -> out.add("-" + l.fileName() + ".npy"));
        if (options.summits() != null) {
            out.addAll(SummitWriter.suffixes(colour));
        }
        out.add(".json");
        return out;
    }

    /**
     * Writes every file of the panorama into an open set, {@code P.json} last (the caller commits).
     * The distance picture is drawn and encoded on a second thread meanwhile (PNG encoding is
     * single-threaded and takes about as long as the colour picture's); this returns or throws only
     * after that thread has ended.
     *
     * @return the files' final paths
     */
    public static List<Path> stage(OutputSet set, Panorama p, Options options) throws IOException {
        List<Path> files = new ArrayList<>();
        Path[] distancePicture = new Path[1];
        Throwable[] pictureFailure = new Throwable[1];
        Thread picture = null;
        if (p.hasDistance()) {
            picture = new Thread(() -> {
                try {
                    distancePicture[0] = set.write("-distance.png", out -> Png.write(DistanceImage.render(
                            p.distanceBuffer(), p.widthPx(), p.heightPx(), p.metadata().rangeMetres()), out));
                } catch (Throwable t) {
                    pictureFailure[0] = t;
                }
            }, "dempano-distance-png");
            picture.setDaemon(true);
            picture.start();
        }
        Throwable failure = null;
        try {
            if (p.hasColour()) {
                files.add(set.write(".png", out -> Png.write(p.image(), out)));
            }
            if (p.hasDistance()) {
                files.add(set.write("-distance." + (options.pfm() ? "pfm" : "npy"), options.pfm()
                        ? FloatArrayWriter.pfm(p.distanceBuffer(), p.heightPx(), p.widthPx())
                        : FloatArrayWriter.npy(p.distanceBuffer(), p.heightPx(), p.widthPx())));
            }
        } catch (Throwable t) {
            failure = t;
        }
        if (picture != null) {
            // Never return (or throw) with the second thread still writing.
            dempano.util.Threads.joinUninterruptibly(picture);
            if (pictureFailure[0] != null) {
                if (failure == null) {
                    failure = pictureFailure[0];
                } else {
                    failure.addSuppressed(pictureFailure[0]);
                }
            } else {
                files.add(distancePicture[0]);
            }
        }
        if (failure instanceof IOException io) {
            throw io;
        } else if (failure instanceof RuntimeException re) {
            throw re;
        } else if (failure instanceof Error e) {
            throw e;
        }
        for (Layer l : p.layers()) {
            files.add(set.write("-" + l.fileName() + ".npy", FloatArrayWriter.npy(p.layerBuffer(l), p.heightPx(), p.widthPx())));
        }
        if (options.summits() != null) {
            files.addAll(SummitWriter.stage(set, p, options.summits(), options.labels()));
        }
        List<Path> listed = new ArrayList<>(files);
        listed.add(set.target(".json"));
        String text = metadataJson(p, listed);
        files.add(set.write(".json", out -> out.write(text.getBytes(StandardCharsets.UTF_8))));
        return files;
    }

    /** The metadata document (see README for the fields). */
    public static String metadataJson(Panorama p, List<Path> files) {
        PanoramaMetadata m = p.metadata();
        PanoramaGeometry g = p.geometry();
        Map<String, Object> doc = new LinkedHashMap<>();
        Map<String, Object> vp = new LinkedHashMap<>();
        vp.put("latDeg", m.latDeg());
        vp.put("lonDeg", m.lonDeg());
        vp.put("groundElevationMetres", m.groundElevationMetres());
        vp.put("offsetMetres", Double.isNaN(m.offsetMetres()) ? null : m.offsetMetres());
        vp.put("standingAltitudeMetres", m.standingAltitudeMetres());
        vp.put("eyeHeightMetres", m.eyeHeightMetres());
        vp.put("eyeAltitudeMetres", m.eyeAltitudeMetres());
        if (m.viewpointMove() != null) {
            vp.put("moved", movedJson(m.viewpointMove()));
        }
        doc.put("viewpoint", vp);
        Map<String, Object> grid = new LinkedHashMap<>();
        grid.put("pixelsPerDegree", g.pixelsPerDegree());
        grid.put("width", g.widthPx());
        grid.put("height", g.heightPx());
        grid.put("azimuthOfColumn0LeftEdgeDeg", PanoramaGeometry.LEFT_AZIMUTH_DEG);
        grid.put("elevationOfRow0TopEdgeDeg", g.topElevationDeg());
        grid.put("pixelCentre", "azimuth = (col + 0.5)/ppd clockwise from true north; elevation = top - (row + 0.5)/ppd");
        doc.put("grid", grid);
        doc.put("distanceUnits", p.hasDistance() ? "metres, float32, straight line from the eye; sky = +Infinity"
                : "not rendered (colour only)");
        putRendering(doc, m);
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        doc.put("files", names);
        Gson gson = Json.writer();
        return gson.toJson(doc) + "\n";
    }

    /** {@code viewpoint.moved} (a panorama's) or {@code eye.moved} (a camera's): where the corrections moved the eye. */
    static Map<String, Object> movedJson(dempano.geo.ViewpointMove mv) {
        Map<String, Object> moved = new LinkedHashMap<>();
        moved.put("fromLatDeg", mv.fromLatDeg());
        moved.put("fromLonDeg", mv.fromLonDeg());
        moved.put("fromEyeAltitudeMetres", mv.fromEyeAltitudeMetres());
        moved.put("toLatDeg", mv.toLatDeg());
        moved.put("toLonDeg", mv.toLonDeg());
        moved.put("toEyeAltitudeMetres", mv.toEyeAltitudeMetres());
        moved.put("horizontalShiftMetres", mv.shiftMetres());
        moved.put("liftMetres", mv.liftMetres());
        moved.put("reason", mv.reason());
        return moved;
    }

    /**
     * The fields a panorama's and a camera's {@code P.json} share, one writer for both (two had drifted apart: the
     * camera's lacked the DEM sources and the near and far planes, neither wrote the level of detail's bound): the
     * earth and the drawing, the tiles and the sources of their samples, warnings, timings and the GL renderer.
     */
    static void putRendering(Map<String, Object> doc, PanoramaMetadata m) {
        doc.put("earthModel", PanoramaMetadata.EARTH_MODEL);
        doc.put("refractionCoefficient", m.refractionCoefficient());
        doc.put("rangeMetres", m.rangeMetres());
        doc.put("depthMode", m.depthMode().optionName());
        doc.put("nearMetres", m.nearMetres());
        doc.put("farMetres", Double.isInfinite(m.farMetres()) ? "infinite" : m.farMetres());
        doc.put("views", m.views());
        doc.put("viewSizePx", List.of(m.viewWidthPx(), m.viewHeightPx()));
        doc.put("lodErrorPx", m.lodErrorPx());
        doc.put("terrainTriangles", m.terrainTriangles());
        doc.put("tilesUsed", m.tilesUsed());
        doc.put("tilesMissing", m.tilesMissing());
        List<Map<String, Object>> sources = new ArrayList<>();
        for (PanoramaMetadata.TileSource ts : m.demSources()) {
            Map<String, Object> one = new LinkedHashMap<>();
            one.put("tile", ts.tile());
            one.put("source", ts.source());
            one.put("verticalDatum", ts.verticalDatum());
            one.put("samples", ts.samples());
            sources.add(one);
        }
        doc.put("demSources", sources);
        doc.put("warnings", m.warnings());
        doc.put("timingsMillis", m.timingsMillis());
        doc.put("glRenderer", m.glRenderer());
    }
}
