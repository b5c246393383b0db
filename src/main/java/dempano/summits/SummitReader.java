package dempano.summits;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonParseException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads summit lists in three formats, chosen by the file name:
 * <ul>
 *   <li>{@code .txt}: de Ferranti's list, one summit a line:
 *       {@code lon(D:M:S) lat(D:M:S) elevation_m code code code NAME…} (west and south negative);</li>
 *   <li>{@code .csv}: {@code name,lat,lon,elevation} (decimal degrees, metres; a header line is
 *       recognised; names may be quoted with double quotes);</li>
 *   <li>{@code .geojson} / {@code .json}: a FeatureCollection of Points (OpenStreetMap
 *       {@code natural=peak} exports) with {@code name} and {@code ele} properties; {@code ele}
 *       may carry a unit suffix " m".</li>
 * </ul>
 * Strict by default: the first bad line is an error naming the file and line number. Lenient
 * reading skips bad lines and lists them in {@link SummitList#skipped()}.
 */
public final class SummitReader {
    private SummitReader() {
    }

    public static SummitList read(Path file, boolean lenient) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (java.nio.charset.MalformedInputException e) {
            text = Files.readString(file, StandardCharsets.ISO_8859_1);
        }
        String source = file.toString();
        if (name.endsWith(".csv")) {
            return csv(source, text, lenient);
        }
        if (name.endsWith(".geojson") || name.endsWith(".json")) {
            return geoJson(source, text, lenient);
        }
        if (name.endsWith(".txt")) {
            return ferranti(source, text, lenient);
        }
        throw new SummitFormatException(source + ": unknown summit list format (use .txt, .csv, .geojson or .json)");
    }

    /** de Ferranti's text format. */
    public static SummitList ferranti(String source, String text, boolean lenient) {
        return eachLine(source, text, lenient, (line, first) -> {
            String[] f = line.split("\\s+", 7);
            if (f.length < 7) {
                throw new IllegalArgumentException("expected 'lon lat elevation code code code NAME', got " + f.length + " fields");
            }
            double lon = dms(f[0], "longitude"), lat = dms(f[1], "latitude");
            double ele = number(f[2], "elevation");
            return new Summit(f[6].replaceAll("\\s+", " "), lat, lon, ele);
        });
    }

    /** CSV: name,lat,lon,elevation. */
    public static SummitList csv(String source, String text, boolean lenient) {
        return eachLine(source, text, lenient, (line, first) -> {
            List<String> f = csvFields(line);
            if (first && f.size() >= 3 && f.get(1).trim().equalsIgnoreCase("lat")) {
                return null; // header
            }
            if (f.size() != 4) {
                throw new IllegalArgumentException("expected 4 fields name,lat,lon,elevation, got " + f.size());
            }
            String ele = f.get(3).trim();
            return new Summit(f.get(0).trim(), number(f.get(1), "latitude"), number(f.get(2), "longitude"),
                    ele.isEmpty() ? Double.NaN : number(ele, "elevation"));
        });
    }

    /** Parses one non-blank, non-comment line; null skips it silently (a header). */
    private interface LineParser {
        Summit parse(String line, boolean firstContentLine);
    }

    /** The line loop of the text formats: blank lines and # comments skipped, bad lines reported by number. */
    private static SummitList eachLine(String source, String text, boolean lenient, LineParser parser) {
        List<Summit> out = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        boolean first = true;
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                Summit s = parser.parse(line, first);
                if (s != null) {
                    out.add(s);
                }
            } catch (IllegalArgumentException e) {
                fail(source, i + 1, e.getMessage(), lenient, skipped);
            }
            first = false;
        }
        return new SummitList(source, out, skipped);
    }

    /** GeoJSON FeatureCollection of Points; "line" in messages is the feature's index (1-based). */
    public static SummitList geoJson(String source, String text, boolean lenient) {
        JsonArray features;
        try {
            JsonObject root = JsonParser.parseString(text).getAsJsonObject();
            features = root.getAsJsonArray("features");
            if (features == null) {
                throw new SummitFormatException(source + ": not a GeoJSON FeatureCollection (no \"features\")");
            }
        } catch (JsonParseException | IllegalStateException | ClassCastException e) {
            throw new SummitFormatException(source + ": not valid GeoJSON: " + e.getMessage(), e);
        }
        List<Summit> out = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        for (int i = 0; i < features.size(); i++) {
            try {
                JsonObject f = features.get(i).getAsJsonObject();
                JsonObject geom = f.getAsJsonObject("geometry");
                if (geom == null || !"Point".equals(str(geom.get("type")))) {
                    throw new IllegalArgumentException("geometry is not a Point");
                }
                JsonArray c = geom.getAsJsonArray("coordinates");
                JsonObject props = f.getAsJsonObject("properties");
                String name = props == null ? null : str(props.get("name"));
                if (name == null || name.isBlank()) {
                    throw new IllegalArgumentException("no name property");
                }
                String ele = props.has("ele") ? str(props.get("ele")) : null;
                double elevation = ele == null || ele.isBlank() ? Double.NaN
                        : number(ele.replaceFirst("(?i)\\s*m$", "").replace(',', '.'), "ele");
                out.add(new Summit(name, c.get(1).getAsDouble(), c.get(0).getAsDouble(), elevation));
            } catch (RuntimeException e) {
                fail(source, i + 1, "feature: " + e.getMessage(), lenient, skipped);
            }
        }
        return new SummitList(source, out, skipped);
    }

    private static String str(JsonElement e) {
        return e == null || e.isJsonNull() ? null : e.getAsString();
    }

    private static void fail(String source, int line, String problem, boolean lenient, List<String> skipped) {
        String msg = "line " + line + ": " + problem;
        if (!lenient) {
            throw new SummitFormatException(source + ": " + msg + " (read leniently to skip bad lines)");
        }
        skipped.add(msg);
    }

    /** Degrees from D:M:S or D:M (a leading '-' applies to the whole angle). */
    static double dms(String s, String what) {
        String[] p = s.split(":");
        if (p.length < 2 || p.length > 3) {
            throw new IllegalArgumentException("bad " + what + " '" + s + "' (want D:M:S)");
        }
        boolean negative = p[0].startsWith("-");
        double d = Math.abs(number(p[0], what)), m = number(p[1], what), sec = p.length == 3 ? number(p[2], what) : 0;
        if (m < 0 || m >= 60 || sec < 0 || sec >= 60) {
            throw new IllegalArgumentException("bad " + what + " '" + s + "': minutes and seconds must be in 0…59");
        }
        double v = d + m / 60 + sec / 3600;
        return negative ? -v : v;
    }

    static double number(String s, String what) {
        try {
            double v = Double.parseDouble(s.trim());
            if (!Double.isFinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("bad " + what + " '" + s + "'");
        }
    }

    static List<String> csvFields(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char ch = line.charAt(i);
            if (quoted) {
                if (ch == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    cur.append('"');
                    i++;
                } else if (ch == '"') {
                    quoted = false;
                } else {
                    cur.append(ch);
                }
            } else if (ch == '"') {
                quoted = true;
            } else if (ch == ',') {
                out.add(cur.toString());
                cur.setLength(0);
            } else {
                cur.append(ch);
            }
        }
        if (quoted) {
            throw new IllegalArgumentException("unterminated quote");
        }
        out.add(cur.toString());
        return out;
    }
}
