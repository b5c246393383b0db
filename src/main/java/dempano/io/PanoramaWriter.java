package dempano.io;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.PanoramaMetadata;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import javax.imageio.ImageIO;

/**
 * Writes a panorama's files for a prefix P: {@code P.png} (when it has colour), {@code P-distance.npy} (or {@code .pfm})
 * and {@code P-distance.png} (when it has distances), {@code P-<layer>.npy} and {@code P.json}. Each file is written atomically.
 */
public final class PanoramaWriter {
    private PanoramaWriter() {
    }

    /**
     * Writes the files; the distance picture is drawn and encoded on a second thread meanwhile (PNG
     * encoding is single-threaded and takes about as long as the colour picture's).
     *
     * @return the files written
     */
    public static List<Path> write(Panorama p, String prefix, boolean pfm) throws IOException {
        List<Path> files = new ArrayList<>();
        FutureTask<Path> distancePicture = null;
        if (p.hasDistance()) {
            Path distPng = Path.of(prefix + "-distance.png");
            distancePicture = new FutureTask<>(() -> {
                AtomicFiles.write(distPng, out -> ImageIO.write(
                        DistanceImage.render(p.distanceBuffer(), p.widthPx(), p.heightPx(), p.metadata().rangeMetres()), "png", out));
                return distPng;
            });
            Thread t = new Thread(distancePicture, "dempano-distance-png");
            t.setDaemon(true);
            t.start();
        }
        Throwable failure = null;
        try {
            if (p.hasColour()) {
                Path png = Path.of(prefix + ".png");
                AtomicFiles.write(png, out -> {
                    if (!ImageIO.write(p.image(), "png", out)) {
                        throw new IOException("no PNG writer");
                    }
                });
                files.add(png);
            }
            if (p.hasDistance()) {
                Path dist = Path.of(prefix + "-distance." + (pfm ? "pfm" : "npy"));
                if (pfm) {
                    FloatArrayWriter.writePfm(dist, p.distanceBuffer(), p.heightPx(), p.widthPx());
                } else {
                    FloatArrayWriter.writeNpy(dist, p.distanceBuffer(), p.heightPx(), p.widthPx());
                }
                files.add(dist);
            }
        } catch (IOException | RuntimeException e) {
            failure = e;
        }
        if (distancePicture != null) {
            // Never return (or throw) with the second thread still writing.
            try {
                files.add(await(distancePicture));
            } catch (IOException | RuntimeException e) {
                if (failure == null) {
                    failure = e;
                } else {
                    failure.addSuppressed(e);
                }
            }
        }
        if (failure instanceof IOException io) {
            throw io;
        } else if (failure instanceof RuntimeException re) {
            throw re;
        }
        for (Layer l : p.layers()) {
            Path f = Path.of(prefix + "-" + l.fileName() + ".npy");
            FloatArrayWriter.writeNpy(f, p.layerBuffer(l), p.heightPx(), p.widthPx());
            files.add(f);
        }
        Path json = Path.of(prefix + ".json");
        String text = metadataJson(p, files);
        AtomicFiles.write(json, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
        files.add(json);
        return files;
    }

    private static Path await(FutureTask<Path> task) throws IOException {
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    return task.get();
                } catch (InterruptedException e) {
                    interrupted = true; // the file is being written: finish waiting, then restore the flag
                }
            }
        } catch (ExecutionException e) {
            if (e.getCause() instanceof IOException io) {
                throw io;
            }
            if (e.getCause() instanceof RuntimeException re) {
                throw re;
            }
            throw new IOException("writing the distance picture failed", e.getCause());
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
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
        doc.put("viewpoint", vp);
        Map<String, Object> grid = new LinkedHashMap<>();
        grid.put("pixelsPerDegree", g.pixelsPerDegree());
        grid.put("width", g.widthPx());
        grid.put("height", g.heightPx());
        grid.put("azimuthOfColumn0LeftEdgeDeg", PanoramaGeometry.LEFT_AZIMUTH_DEG);
        grid.put("elevationOfRow0TopEdgeDeg", g.topElevationDeg());
        grid.put("pixelCentre", "azimuth = (col + 0.5)/ppd clockwise from true north; elevation = top - (row + 0.5)/ppd");
        doc.put("grid", grid);
        doc.put("earthModel", PanoramaMetadata.EARTH_MODEL);
        doc.put("refractionCoefficient", m.refractionCoefficient());
        doc.put("rangeMetres", m.rangeMetres());
        doc.put("depthMode", m.depthMode().optionName());
        doc.put("nearMetres", m.nearMetres());
        doc.put("farMetres", Double.isInfinite(m.farMetres()) ? "infinite" : m.farMetres());
        doc.put("views", m.views());
        doc.put("viewSizePx", List.of(m.viewWidthPx(), m.viewHeightPx()));
        doc.put("distanceUnits", p.hasDistance() ? "metres, float32, straight line from the eye; sky = +Infinity"
                : "not rendered (colour only)");
        doc.put("tilesUsed", m.tilesUsed());
        doc.put("tilesMissing", m.tilesMissing());
        doc.put("warnings", m.warnings());
        doc.put("timingsMillis", m.timingsMillis());
        doc.put("glRenderer", m.glRenderer());
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        doc.put("files", names);
        Gson gson = new GsonBuilder().setPrettyPrinting().serializeNulls().serializeSpecialFloatingPointValues().create();
        return gson.toJson(doc) + "\n";
    }
}
