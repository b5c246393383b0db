package dempano.io;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import dempano.panorama.Panorama;
import dempano.summits.SummitSighting;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/** Writes summit sightings: {@code P-summits.json}, {@code P-summits.csv} and the labelled {@code P-labels.png}. */
public final class SummitWriter {
    private SummitWriter() {
    }

    /** Which summits get a label, and how densely. */
    public enum LabelOrder {
        /** Highest summit first (the default: what people name first). */
        HEIGHT,
        /** Highest in the picture first (largest elevation angle: the most striking). */
        ANGLE,
        /** Nearest first. */
        DISTANCE;

        Comparator<SummitSighting> comparator() {
            return switch (this) {
                case HEIGHT -> Comparator.comparingDouble(s -> -s.summit().elevationMetres());
                case ANGLE -> Comparator.comparingDouble(s -> -s.elevationAngleDeg());
                case DISTANCE -> Comparator.comparingDouble(SummitSighting::slantMetres);
            };
        }
    }

    /**
     * Label density.
     *
     * @param maxLabels  at most this many labels (0 = no limit)
     * @param spacingPx  least horizontal distance between two labelled summits, pixels; NaN = one
     *                   text line (the least that keeps the vertical labels from overlapping)
     * @param order      which summits win where they compete for room
     */
    public record LabelOptions(int maxLabels, double spacingPx, LabelOrder order) {
        public static final LabelOptions DEFAULT = new LabelOptions(0, Double.NaN, LabelOrder.HEIGHT);

        public LabelOptions {
            if (maxLabels < 0) {
                throw new IllegalArgumentException("the number of labels must be 0 (no limit) or more, got " + maxLabels);
            }
            if (!Double.isNaN(spacingPx) && !(spacingPx >= 0 && spacingPx < 1e6)) {
                throw new IllegalArgumentException("label spacing must be a number of pixels in [0, 1e6), got " + spacingPx);
            }
        }
    }

    /** The suffixes of the files {@link #stage} writes. */
    static List<String> suffixes(boolean colour) {
        return colour ? List.of("-summits.json", "-summits.csv", "-labels.png") : List.of("-summits.json", "-summits.csv");
    }

    /**
     * Writes {@code P-summits.json}, {@code P-summits.csv} and (when the panorama has colour) the
     * labelled {@code P-labels.png} into an output set (see {@link PanoramaWriter#write(Panorama, String, PanoramaWriter.Options)}).
     *
     * @return the paths the files will have once the set is committed
     */
    public static List<Path> stage(OutputSet set, Panorama p, List<SummitSighting> sightings, LabelOptions options)
            throws IOException {
        String jsonText = json(sightings);
        Path json = set.write("-summits.json", out -> out.write(jsonText.getBytes(StandardCharsets.UTF_8)));
        String csvText = csv(sightings);
        Path csv = set.write("-summits.csv", out -> out.write(csvText.getBytes(StandardCharsets.UTF_8)));
        if (!p.hasColour()) {
            return List.of(json, csv);
        }
        BufferedImage labelled = labels(p, sightings, options);
        Path png = set.write("-labels.png", out -> Png.write(labelled, out));
        return List.of(json, csv, png);
    }

    /** What pixelX/pixelY mean in a panorama's summit files. */
    static final String PANORAMA_PIXELS = "pixelX, pixelY: panorama pixel coordinates, column c spanning [c, c + 1) (its"
            + " centre at c + 0.5), row 0's top edge at 0";
    /** What pixelX/pixelY mean in a camera image's summit files (as its P.json says). */
    static final String CAMERA_PIXELS = "pixelX, pixelY: OpenCV pixel coordinates, pixel (column i, row j) centred at"
            + " (i, j), as P.json's conventions say";

    static String json(List<SummitSighting> sightings) {
        return json(sightings, PANORAMA_PIXELS);
    }

    static String json(List<SummitSighting> sightings, String pixels) {
        JsonArray a = new JsonArray();
        for (SummitSighting s : sightings) {
            JsonObject o = new JsonObject();
            o.addProperty("name", s.summit().name());
            o.addProperty("lat", s.summit().latDeg());
            o.addProperty("lon", s.summit().lonDeg());
            o.addProperty("elevationMetres", s.summit().elevationMetres());
            o.addProperty("elevationFromDem", s.summit().elevationFromDem());
            o.addProperty("azimuthDeg", s.azimuthDeg());
            o.addProperty("elevationAngleDeg", s.elevationAngleDeg());
            o.addProperty("pixelX", s.pixelX());
            o.addProperty("pixelY", s.pixelY());
            o.addProperty("slantMetres", s.slantMetres());
            o.addProperty("groundMetres", s.groundMetres());
            number(o, "mapDistanceMetres", s.mapDistanceMetres());
            number(o, "seenDistanceMetres", s.seenDistanceMetres());
            o.addProperty("visible", s.visible());
            number(o, "demHeightMetres", s.demHeightMetres());
            o.addProperty("inFilledVoid", s.inFilledVoid());
            a.add(o);
        }
        JsonObject root = new JsonObject();
        root.addProperty("note", pixels + "; elevationFromDem: the list gave no height, elevationMetres is the DEM's there;"
                + " mapDistanceMetres: distance-map value at the summit's pixel (null: sky or outside);"
                + " seenDistanceMetres: terrain seen at the summit within the tolerance window (null: none);"
                + " demHeightMetres: the DEM's height at the summit's position (null: not looked up);"
                + " inFilledVoid: the DEM had a void there, its height is interpolated");
        root.add("summits", a);
        return new GsonBuilder().setPrettyPrinting().serializeNulls().create().toJson(root) + "\n";
    }

    private static void number(JsonObject o, String key, double v) {
        if (Double.isFinite(v)) {
            o.addProperty(key, v);
        } else {
            o.add(key, com.google.gson.JsonNull.INSTANCE); // JSON has no NaN or infinity
        }
    }

    static String csv(List<SummitSighting> sightings) {
        StringBuilder b = new StringBuilder("name,lat,lon,elevation_m,azimuth_deg,elevation_angle_deg,pixel_x,pixel_y,"
                + "slant_m,ground_m,map_distance_m,seen_distance_m,visible,dem_height_m,in_filled_void,elevation_from_dem\n");
        for (SummitSighting s : sightings) {
            String name = s.summit().name();
            if (name.contains(",") || name.contains("\"") || name.contains("\n") || name.contains("\r")) {
                name = "\"" + name.replace("\"", "\"\"") + "\"";
            }
            b.append(String.format(Locale.ROOT, "%s,%.6f,%.6f,%.0f,%.4f,%.4f,%.2f,%.2f,%.1f,%.1f,%s,%s,%s,%s,%s,%s%n", name,
                    s.summit().latDeg(), s.summit().lonDeg(), s.summit().elevationMetres(), s.azimuthDeg(),
                    s.elevationAngleDeg(), s.pixelX(), s.pixelY(), s.slantMetres(), s.groundMetres(),
                    csvNumber(s.mapDistanceMetres()), csvNumber(s.seenDistanceMetres()), s.visible(),
                    csvNumber(s.demHeightMetres()), s.inFilledVoid(), s.summit().elevationFromDem()));
        }
        return b.toString();
    }

    private static String csvNumber(double v) {
        return Double.isNaN(v) ? "" : Double.isInfinite(v) ? "inf" : String.format(Locale.ROOT, "%.1f", v);
    }

    /**
     * The panorama with a band above it for labels: visible summits in the options' order, each with
     * its own slot at least one text line wide (so labels never overlap; a summit too close to a
     * better one's slot is left unlabelled), a vertical label "NAME 2927 m · 12.3 km" and a leader
     * line from the label down to the summit's pixel.
     */
    public static BufferedImage labels(Panorama p, List<SummitSighting> sightings, LabelOptions options) {
        int w = p.widthPx(), h = p.heightPx();
        Font font = new Font(Font.SANS_SERIF, Font.PLAIN, 13);
        BufferedImage probe = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        FontMetrics fm = probe.createGraphics().getFontMetrics(font);
        int line = fm.getHeight() + 3;
        double spacing = Double.isNaN(options.spacingPx()) ? line : Math.max(line, options.spacingPx());
        List<SummitSighting> chosen = chooseLabels(sightings, w, h, spacing, options.maxLabels(), options.order());
        int longest = 0;
        for (SummitSighting s : chosen) {
            longest = Math.max(longest, fm.stringWidth(text(s)));
        }
        int band = longest + 16;
        BufferedImage img = new BufferedImage(w, h + band, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, band);
        g.drawImage(p.image(), 0, band, null);
        g.setFont(font);
        for (SummitSighting s : chosen) {
            int x = (int) Math.floor(s.pixelX());
            int y = band + (int) Math.floor(s.pixelY());
            g.setColor(new Color(40, 40, 40, 200));
            g.setStroke(new BasicStroke(1f));
            g.drawLine(x, band - 4, x, y - 3);
            g.setColor(new Color(200, 30, 30));
            g.fillOval(x - 2, y - 2, 5, 5);
            AffineTransform saved = g.getTransform();
            g.translate(x + fm.getAscent() / 2 - 1, band - 6);
            g.rotate(-Math.PI / 2);
            g.setColor(Color.BLACK);
            g.drawString(text(s), 0, 0);
            g.setTransform(saved);
        }
        g.dispose();
        return img;
    }

    /**
     * The visible summits inside the picture that get a label: taken in {@code order}, each kept if no
     * kept one lies within {@code spacingPx} columns (across the 0°/360° seam too), until
     * {@code maxLabels} are kept (0 = no limit).
     */
    static List<SummitSighting> chooseLabels(List<SummitSighting> sightings, int widthPx, int heightPx, double spacingPx,
                                             int maxLabels, LabelOrder order) {
        List<SummitSighting> candidates = new ArrayList<>();
        for (SummitSighting s : sightings) {
            if (s.visible() && s.pixelY() >= 0 && s.pixelY() < heightPx) {
                candidates.add(s);
            }
        }
        candidates.sort(order.comparator());
        List<SummitSighting> chosen = new ArrayList<>();
        for (SummitSighting s : candidates) {
            if (maxLabels > 0 && chosen.size() >= maxLabels) {
                break;
            }
            boolean free = true;
            for (SummitSighting c : chosen) {
                double dx = Math.abs(c.pixelX() - s.pixelX());
                if (Math.min(dx, widthPx - dx) < spacingPx) {
                    free = false;
                    break;
                }
            }
            if (free) {
                chosen.add(s);
            }
        }
        return chosen;
    }

    /** A label's text: "NAME 2927 m · 12.3 km", "NAME ~1912 m · …" where the height is the DEM's (no height in the list). */
    static String text(SummitSighting s) {
        return String.format(Locale.ROOT, "%s %s%.0f m · %.1f km", s.summit().name(), s.summit().elevationFromDem() ? "~" : "",
                s.summit().elevationMetres(), s.slantMetres() / 1000);
    }
}
