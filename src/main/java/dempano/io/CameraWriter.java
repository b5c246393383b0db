package dempano.io;

import com.google.gson.Gson;
import dempano.CameraImage;
import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraPose;
import dempano.panorama.PanoramaMetadata;
import dempano.panorama.Silhouettes;
import dempano.summits.SummitSighting;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes a camera's rendered view on the photo's own pixel grid, all or nothing ({@link OutputSet}):
 * {@code P.png} (the rendered view with its silhouettes), {@code P-distance.npy} (float32, rows × columns, metres,
 * sky +∞), {@code P.json} (intrinsics, pose, conventions, eye, tiles, timings), {@code P-overlay.png} (the photo,
 * or the rendered view when there is none, with the rendered silhouettes in red and the summits in frame marked
 * and labelled) and, when summits are given, {@code P-summits.json} and {@code P-summits.csv} as the panorama
 * writes them ({@link SummitWriter}).
 */
public final class CameraWriter {
    private CameraWriter() {
    }

    /**
     * What goes with the view.
     *
     * @param photo      the photo as displayed (EXIF orientation applied), the same size as the view; null = overlay
     *                   on the rendered view
     * @param summits    the summits in frame ({@link dempano.summits.SummitProjector#project(CameraImage,
     *                   dempano.summits.SummitList)}); null = no summit files
     * @param provenance where each camera value came from (a line each), for the metadata
     * @param files      more files of the set ({@link ExtraFile}), in order
     */
    public record Extras(BufferedImage photo, List<SummitSighting> summits, List<String> provenance, List<ExtraFile> files) {
        public static final Extras NONE = new Extras(null, null, List.of(), List.of());

        public Extras {
            files = List.copyOf(files);
        }

        public Extras(BufferedImage photo, List<SummitSighting> summits, List<String> provenance) {
            this(photo, summits, provenance, List.of());
        }
    }

    /**
     * A file of the set besides the camera's own (the photo job's {@code P-orientation.png/json}): written before
     * {@code P.json} and listed in it, so that a later run of the prefix that does not make it removes it.
     *
     * @param suffix after the prefix, e.g. {@code "-orientation.json"}
     * @param bytes  the file's content
     */
    public record ExtraFile(String suffix, byte[] bytes) {
    }

    /** Writes every file for prefix P; returns their paths. */
    public static List<Path> write(CameraImage image, String prefix, Extras extras) throws IOException {
        try (OutputSet set = OutputSet.open(prefix)) {
            List<Path> files = stage(set, image, extras);
            set.commit();
            return files;
        }
    }

    /** The suffixes {@link #stage} writes (to check the destination before rendering). */
    public static List<String> suffixes(boolean summits) {
        List<String> suffixes = new ArrayList<>(List.of(".png", "-distance.npy", "-overlay.png", ".json"));
        if (summits) {
            suffixes.addAll(List.of("-summits.json", "-summits.csv"));
        }
        return suffixes;
    }

    /**
     * Writes every file for the set's prefix into the set, {@code P.json} last, without committing it (the
     * caller may add files of its own, then commits).
     *
     * @return the files' final paths, {@code P.json} last
     */
    public static List<Path> stage(OutputSet set, CameraImage image, Extras extras) throws IOException {
        List<String> targets = suffixes(extras.summits() != null);
        image.layers().forEach(l -> targets.add("-" + l.fileName() + ".npy"));
        extras.files().forEach(f -> targets.add(f.suffix()));
        set.checkTargets(targets);
        List<Path> files = new ArrayList<>();
        if (image.hasColour()) {
            BufferedImage rendered = image.image();
            files.add(set.write(".png", out -> Png.write(rendered, out)));
        }
        if (image.hasDistance()) {
            files.add(set.write("-distance.npy", FloatArrayWriter.npy(image.distanceBuffer(), image.heightPx(),
                    image.widthPx())));
            BufferedImage overlay = overlay(image, extras.photo(), extras.summits());
            files.add(set.write("-overlay.png", out -> Png.write(overlay, out)));
        }
        for (dempano.panorama.Layer l : image.layers()) {
            files.add(set.write("-" + l.fileName() + ".npy", FloatArrayWriter.npy(image.layerBuffer(l), image.heightPx(),
                    image.widthPx())));
        }
        if (extras.summits() != null) {
            String json = SummitWriter.json(extras.summits(), SummitWriter.CAMERA_PIXELS), csv = SummitWriter.csv(extras.summits());
            files.add(set.write("-summits.json", out -> out.write(json.getBytes(StandardCharsets.UTF_8))));
            files.add(set.write("-summits.csv", out -> out.write(csv.getBytes(StandardCharsets.UTF_8))));
        }
        for (ExtraFile f : extras.files()) {
            files.add(set.write(f.suffix(), out -> out.write(f.bytes())));
        }
        List<Path> all = new ArrayList<>(files);
        all.add(set.target(".json"));
        String meta = metadataJson(image, extras.provenance(), all);
        files.add(set.write(".json", out -> out.write(meta.getBytes(StandardCharsets.UTF_8))));
        return files;
    }

    /**
     * The photo (or the rendered view) with the rendered silhouettes (skylines and depth edges,
     * {@link Silhouettes#isEdge}) in red, and each summit in frame as a ring at its pixel: yellow and labelled
     * "NAME 1234 m · 12.3 km" when visible, grey when hidden.
     */
    public static BufferedImage overlay(CameraImage image, BufferedImage photo, List<SummitSighting> summits) {
        int w = image.widthPx(), h = image.heightPx();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        if (photo != null) {
            if (photo.getWidth() != w || photo.getHeight() != h) {
                throw new IllegalArgumentException("the photo is " + photo.getWidth() + "×" + photo.getHeight()
                        + " pixels as displayed, the camera's image " + w + "×" + h);
            }
            g.drawImage(photo, 0, 0, null);
        } else if (image.hasColour()) {
            g.drawImage(image.image(), 0, 0, null);
        }
        float[] distance = image.distanceArray();
        int red = 0xffff2020;
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                if (Silhouettes.isEdge(distance, w, h, col, row)) {
                    out.setRGB(col, row, red);
                }
            }
        }
        if (summits != null) {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, Math.max(11, Math.min(40, h / 40))));
            g.setStroke(new BasicStroke(2f));
            for (boolean visible : new boolean[] {false, true}) { // the visible rings on top
                for (SummitSighting s : summits) {
                    if (s.visible() == visible) {
                        g.setColor(visible ? Color.YELLOW : Color.LIGHT_GRAY);
                        g.drawOval((int) Math.round(s.pixelX()) - 6, (int) Math.round(s.pixelY()) - 6, 12, 12);
                    }
                }
            }
            java.awt.FontMetrics fm = g.getFontMetrics();
            for (Label l : labels(summits, fm::stringWidth, fm.getAscent(), fm.getDescent(), w, h)) {
                g.setColor(Color.BLACK); // a shadow: legible over sky and snow alike
                g.drawString(l.text(), l.x() + 1, l.baseline() + 1);
                g.setColor(Color.YELLOW);
                g.drawString(l.text(), l.x(), l.baseline());
            }
        }
        g.dispose();
        return out;
    }

    /** A summit label placed on the overlay: its text, left edge and baseline, pixels. */
    record Label(String text, int x, int baseline) {
    }

    /**
     * The labels of the visible summits that fit without overlapping, highest summit first (as the panorama's labels
     * are chosen): each up and to the right of its ring, or to the left where it would leave the image, and left out
     * where its box would overlap a label already placed (they were all drawn, piled on one another along a
     * skyline full of summits, none legible).
     *
     * @param width   a text's width, pixels
     * @param ascent  the font's ascent, pixels
     * @param descent the font's descent, pixels
     */
    static List<Label> labels(List<SummitSighting> summits, java.util.function.ToIntFunction<String> width, int ascent,
                              int descent, int imageWidth, int imageHeight) {
        List<SummitSighting> visible = summits.stream().filter(SummitSighting::visible)
                .sorted(SummitWriter.LabelOrder.HEIGHT.comparator()).toList();
        List<java.awt.Rectangle> taken = new java.util.ArrayList<>();
        List<Label> out = new java.util.ArrayList<>();
        for (SummitSighting s : visible) {
            String text = SummitWriter.text(s);
            int tw = width.applyAsInt(text), x = (int) Math.round(s.pixelX()), y = (int) Math.round(s.pixelY());
            int left = x + 9 + tw <= imageWidth ? x + 9 : x - 9 - tw;
            int baseline = Math.max(ascent, y - 9);
            java.awt.Rectangle box = new java.awt.Rectangle(left - 2, baseline - ascent - 2, tw + 4, ascent + descent + 4);
            if (left < 0 || taken.stream().anyMatch(box::intersects)) {
                continue;
            }
            taken.add(box);
            out.add(new Label(text, left, baseline));
        }
        return out;
    }

    /**
     * A photo as displayed: the stored pixels turned as its EXIF orientation says (1 as stored, 3 turned 180°,
     * 6 turned 90° clockwise, 8 turned 90° anticlockwise; mirrored orientations 2, 4, 5, 7 are mirrored too).
     */
    public static BufferedImage displayed(BufferedImage stored, int exifOrientation) {
        int w = stored.getWidth(), h = stored.getHeight();
        boolean swap = exifOrientation >= 5 && exifOrientation <= 8;
        AffineTransform t = new AffineTransform();
        switch (exifOrientation) {
            case 2 -> t.setTransform(-1, 0, 0, 1, w, 0);
            case 3 -> t.setTransform(-1, 0, 0, -1, w, h);
            case 4 -> t.setTransform(1, 0, 0, -1, 0, h);
            case 5 -> t.setTransform(0, 1, 1, 0, 0, 0);
            case 6 -> t.setTransform(0, 1, -1, 0, h, 0);
            case 7 -> t.setTransform(0, -1, -1, 0, h, w);
            case 8 -> t.setTransform(0, -1, 1, 0, 0, w);
            default -> {
                return stored;
            }
        }
        BufferedImage out = new BufferedImage(swap ? h : w, swap ? w : h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.drawImage(stored, t, null);
        g.dispose();
        return out;
    }

    /** The metadata document of a camera view. */
    public static String metadataJson(CameraImage image, List<String> provenance, List<Path> files) {
        PanoramaMetadata m = image.metadata();
        CameraIntrinsics k = image.view().intrinsics();
        CameraPose pose = image.pose();
        Map<String, Object> doc = new LinkedHashMap<>();
        Map<String, Object> in = new LinkedHashMap<>();
        in.put("width", k.widthPx());
        in.put("height", k.heightPx());
        in.put("fxPx", k.fxPx());
        in.put("fyPx", k.fyPx());
        in.put("cxPx", k.cxPx());
        in.put("cyPx", k.cyPx());
        // In OpenCV's order, always: Map.of's iteration order changes from one JVM run to the next.
        Map<String, Object> distortion = new LinkedHashMap<>();
        distortion.put("k1", k.distortion().k1());
        distortion.put("k2", k.distortion().k2());
        distortion.put("p1", k.distortion().p1());
        distortion.put("p2", k.distortion().p2());
        distortion.put("k3", k.distortion().k3());
        in.put("distortion", distortion);
        in.put("horizontalFovDeg", k.horizontalFovDeg());
        in.put("verticalFovDeg", k.verticalFovDeg());
        doc.put("intrinsics", in);
        Map<String, Object> p = new LinkedHashMap<>();
        p.put("latDeg", pose.latDeg());
        p.put("lonDeg", pose.lonDeg());
        p.put("altitudeMetres", pose.absoluteAltitude() ? pose.altitudeMetres() : null);
        p.put("offsetMetres", pose.absoluteAltitude() ? null : pose.offsetMetres());
        p.put("cameraHeightMetres", pose.cameraHeightMetres());
        p.put("headingDeg", pose.orientation().headingDeg());
        p.put("pitchDeg", pose.orientation().pitchDeg());
        p.put("rollDeg", pose.orientation().rollDeg());
        doc.put("pose", p);
        Map<String, Object> eye = new LinkedHashMap<>();
        eye.put("latDeg", m.latDeg());
        eye.put("lonDeg", m.lonDeg());
        eye.put("groundElevationMetres", m.groundElevationMetres());
        eye.put("standingAltitudeMetres", m.standingAltitudeMetres());
        eye.put("eyeHeightMetres", m.eyeHeightMetres());
        eye.put("eyeAltitudeMetres", m.eyeAltitudeMetres());
        if (m.viewpointMove() != null) {
            eye.put("moved", PanoramaWriter.movedJson(m.viewpointMove()));
        }
        doc.put("eye", eye);
        Map<String, String> conventions = new LinkedHashMap<>();
        conventions.put("pixels", "OpenCV: pixel (column i, row j) has its centre at (i, j); row 0 at the top; the photo"
                + " as displayed (EXIF orientation applied)");
        conventions.put("camera", "x right, y down, z forward (OpenCV); distortion Brown-Conrady k1 k2 p1 p2 k3 on"
                + " normalized coordinates");
        conventions.put("heading", "azimuth of the optical axis, degrees clockwise from true north");
        conventions.put("pitch", "optical axis above the eye's local horizontal, degrees, positive up");
        conventions.put("roll", "about the optical axis, degrees, positive turns the image clockwise as seen by the"
                + " photographer (heading, then pitch, then roll)");
        conventions.put("frame", "directions in the eye's local east-north-up frame on WGS84");
        conventions.put("distance", "metres, float32, straight line from the eye to the terrain seen through the"
                + " pixel centre; sky = +Infinity; NaN where the lens model has no ray");
        doc.put("conventions", conventions);
        PanoramaWriter.putRendering(doc, m);
        doc.put("provenance", provenance);
        List<String> names = new ArrayList<>();
        files.forEach(f -> names.add(f.getFileName().toString()));
        doc.put("files", names);
        Gson gson = Json.writer();
        return gson.toJson(doc) + "\n";
    }
}
