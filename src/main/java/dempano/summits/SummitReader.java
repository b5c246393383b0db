package dempano.summits;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;
import com.google.gson.Strictness;
import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;
import java.io.IOException;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;

/**
 * Reads summit lists in three formats, chosen by the file name:
 * <ul>
 *   <li>{@code .txt}: de Ferranti's list, one summit a line:
 *       {@code lon(D:M:S) lat(D:M:S) elevation_m code code code NAME…} (west and south negative);</li>
 *   <li>{@code .csv}: decimal degrees and metres, read with Apache Commons CSV (fields may be quoted
 *       with double quotes, {@code ""} inside quotes is one quote). Either a header line naming the
 *       columns, in any order and any letter case: {@code name}; {@code lat} or {@code latitude};
 *       {@code lon}, {@code lng}, {@code long} or {@code longitude}; optionally {@code ele},
 *       {@code elevation}, {@code elev}, {@code height}, {@code alt} or {@code altitude} (other
 *       columns are ignored); or no header and four fields {@code name,lat,lon,elevation}. An empty
 *       elevation field means "not known" (NaN). The first line is a header when it has a known
 *       column name and no number;</li>
 *   <li>{@code .geojson} / {@code .json}: a FeatureCollection of Points (OpenStreetMap
 *       {@code natural=peak} exports) with {@code name} and {@code ele} properties; {@code ele}
 *       may carry a unit suffix " m".</li>
 * </ul>
 * In the text formats lines end with {@code \n}, {@code \r\n} or a lone {@code \r}; blank lines and
 * lines starting with {@code #} are skipped. Numbers are plain decimals only: optional sign, digits,
 * optional fraction, optional exponent ({@code 4049}, {@code -71.3}, {@code 4.049e3}); Java
 * literals such as {@code 0x2Bp0}, {@code 43.8f}, {@code 100D}, {@code NaN} or {@code Infinity}
 * are bad values. Latitude must lie in [−90, 90] and longitude in [−180, 180] degrees.
 *
 * <p>Strict by default: the first bad entry is an error naming the file and the line (GeoJSON: the
 * feature, counted from 1). Lenient reading skips bad entries and lists them in
 * {@link SummitList#skipped()}. A file that cannot be read at all (not JSON, an unclosed quote in a
 * CSV file, a CSV header without a latitude column…) is an error in both modes. A list with no
 * summits is not an error: {@link SummitList#warnings()} says so.
 */
public final class SummitReader {
    /** A plain decimal number: no hex, no type suffix, no NaN or Infinity. */
    /** Any line ending: {@code \r\n}, {@code \n} or a lone {@code \r}. */
    private static final Pattern LINE_BREAK = Pattern.compile("\r\n|\r|\n");
    private static final String HEADER_RULE = "name, lat/latitude, lon/lng/long/longitude and optionally"
            + " ele/elevation/elev/height/alt/altitude";

    private SummitReader() {
    }

    /**
     * Reads a list, the format chosen by the file name's ending ({@code .txt}, {@code .csv},
     * {@code .geojson}, {@code .json}). UTF-8, falling back to ISO-8859-1; a leading byte-order mark
     * is dropped.
     *
     * @throws SummitFormatException the format is unknown, or (strict) an entry is bad, or the file
     *                               cannot be read as its format at all
     */
    public static SummitList read(Path file, boolean lenient) throws IOException {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (java.nio.charset.MalformedInputException e) {
            text = Files.readString(file, StandardCharsets.ISO_8859_1);
        }
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1);
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
        List<Summit> out = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        String[] lines = LINE_BREAK.split(text, -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                String[] f = line.split("\\s+", 7);
                if (f.length < 7) {
                    throw new IllegalArgumentException("expected 'lon lat elevation code code code NAME', got "
                            + f.length + " fields");
                }
                double lon = dms(f[0], "longitude"), lat = dms(f[1], "latitude");
                double ele = number(f[2], "elevation");
                out.add(summit(f[6].replaceAll("\\s+", " "), lat, lon, ele));
            } catch (IllegalArgumentException e) {
                fail(source, "line " + (i + 1), e.getMessage(), lenient, skipped);
            }
        }
        return new SummitList(source, out, skipped);
    }

    private enum Column {
        NAME("name"), LAT("latitude"), LON("longitude"), ELE("elevation");

        final String word;

        Column(String word) {
            this.word = word;
        }

        static Column of(String header) {
            return switch (header.strip().toLowerCase(Locale.ROOT)) {
                case "name" -> NAME;
                case "lat", "latitude" -> LAT;
                case "lon", "lng", "long", "longitude" -> LON;
                case "ele", "elevation", "elev", "height", "alt", "altitude" -> ELE;
                default -> null;
            };
        }
    }

    /** CSV with a header naming the columns, or headerless {@code name,lat,lon,elevation}; see the class comment. */
    public static SummitList csv(String source, String text, boolean lenient) {
        CSVFormat format = CSVFormat.DEFAULT.builder()
                .setCommentMarker('#')
                .setIgnoreEmptyLines(true)
                .setIgnoreSurroundingSpaces(true)
                .setTrim(true)
                .get();
        // The line each record starts on: commons-csv counts line breaks read; blank and comment
        // lines before a record are skipped by it and by contentLines alike.
        boolean[] content = contentLines(text);
        List<Summit> out = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        Map<Column, Integer> columns = null; // null: headerless name,lat,lon,elevation
        int headerFields = 4;
        boolean first = true;
        try (CSVParser parser = CSVParser.parse(text, format)) {
            Iterator<CSVRecord> it = parser.iterator();
            long linesRead = 0;
            while (true) {
                CSVRecord r;
                try {
                    if (!it.hasNext()) {
                        break;
                    }
                    r = it.next();
                } catch (UncheckedIOException | IllegalStateException e) {
                    throw new SummitFormatException(source + ": " + csvProblem(e, nextContentLine(content, linesRead))
                            + " (the file cannot be read past it)", e);
                }
                int line = nextContentLine(content, linesRead);
                linesRead = parser.getCurrentLineNumber();
                List<String> f = r.toList();
                if (f.stream().allMatch(String::isEmpty) || f.get(0).startsWith("#")) {
                    continue; // a line of spaces, or an indented comment
                }
                if (first) {
                    first = false;
                    if (f.stream().noneMatch(SummitReader::isDecimal)) {
                        if (f.stream().anyMatch(h -> Column.of(h) != null)) {
                            columns = header(source, line, f);
                            headerFields = f.size();
                            continue;
                        }
                        fail(source, "line " + line, "looks like a header but names no known column (want "
                                + HEADER_RULE + ")", lenient, skipped);
                        continue;
                    }
                }
                try {
                    if (f.size() != headerFields) {
                        throw new IllegalArgumentException(columns == null
                                ? "expected 4 fields name,lat,lon,elevation, got " + f.size()
                                : "expected " + headerFields + " fields as in the header, got " + f.size());
                    }
                    String name = f.get(columns == null ? 0 : columns.get(Column.NAME)).replaceAll("\\s+", " ");
                    double lat = number(f.get(columns == null ? 1 : columns.get(Column.LAT)), "latitude");
                    double lon = number(f.get(columns == null ? 2 : columns.get(Column.LON)), "longitude");
                    Integer eleColumn = columns == null ? Integer.valueOf(3) : columns.get(Column.ELE);
                    String ele = eleColumn == null ? "" : f.get(eleColumn);
                    out.add(summit(name, lat, lon, ele.isEmpty() ? Double.NaN : number(ele, "elevation")));
                } catch (IllegalArgumentException e) {
                    fail(source, "line " + line, e.getMessage(), lenient, skipped);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e); // cannot happen: the text is in memory
        }
        return new SummitList(source, out, skipped);
    }

    /** The columns a header line names; an unusable header (no name, latitude or longitude column, or one twice) is always an error. */
    private static Map<Column, Integer> header(String source, int line, List<String> fields) {
        Map<Column, Integer> columns = new EnumMap<>(Column.class);
        for (int i = 0; i < fields.size(); i++) {
            Column c = Column.of(fields.get(i));
            if (c != null && columns.put(c, i) != null) {
                throw new SummitFormatException(source + ": line " + line + ": header has two " + c.word + " columns");
            }
        }
        for (Column c : List.of(Column.NAME, Column.LAT, Column.LON)) {
            if (!columns.containsKey(c)) {
                throw new SummitFormatException(source + ": line " + line + ": header " + fields + " has no " + c.word
                        + " column (want " + HEADER_RULE + ")");
            }
        }
        return columns;
    }

    /** For each line (index = line number − 1): whether it holds more than spaces or a # comment. */
    private static boolean[] contentLines(String text) {
        String[] lines = LINE_BREAK.split(text, -1);
        boolean[] content = new boolean[lines.length];
        for (int i = 0; i < lines.length; i++) {
            String s = lines[i].strip();
            content[i] = !s.isEmpty() && !s.startsWith("#");
        }
        return content;
    }

    /** The 1-based number of the first content line after {@code linesRead} whole lines. */
    private static int nextContentLine(boolean[] content, long linesRead) {
        int i = (int) linesRead;
        while (i < content.length && !content[i]) {
            i++;
        }
        return i + 1;
    }

    /** commons-csv's reason for giving up, in plain words with the line it started on. */
    private static String csvProblem(RuntimeException e, int line) {
        String msg = String.valueOf(e.getMessage());
        Matcher m = Pattern.compile("\\(startline (\\d+)\\)|at line: (\\d+)").matcher(msg);
        String where = "line " + (m.find() ? (m.group(1) != null ? m.group(1) : m.group(2)) : String.valueOf(line));
        String lower = msg.toLowerCase(Locale.ROOT);
        if (lower.contains("eof reached before encapsulated token finished")) {
            return where + ": a quoted field is not closed (a \" is missing)";
        }
        if (lower.contains("between encapsulated token and delimiter")) {
            return where + ": text after a closing quote (quote the whole field, and write \"\" for a \" inside it)";
        }
        return where + ": not readable as CSV";
    }

    /**
     * GeoJSON FeatureCollection of Points. Features are counted from 1 in messages ("feature 3: …");
     * coordinates must be JSON numbers, {@code [lon, lat]} or {@code [lon, lat, height]}.
     */
    public static SummitList geoJson(String source, String text, boolean lenient) {
        JsonArray features;
        try {
            JsonReader reader = new JsonReader(new StringReader(text));
            reader.setStrictness(Strictness.STRICT);
            JsonElement root = JsonParser.parseReader(reader);
            if (reader.peek() != JsonToken.END_DOCUMENT) {
                throw new SummitFormatException(source + ": not valid JSON: text after the end of the document");
            }
            if (!root.isJsonObject()) {
                throw new SummitFormatException(source + ": not a GeoJSON FeatureCollection (the file is not a JSON object)");
            }
            JsonElement fs = root.getAsJsonObject().get("features");
            if (fs == null || !fs.isJsonArray()) {
                throw new SummitFormatException(source + ": not a GeoJSON FeatureCollection (no \"features\" list)");
            }
            features = fs.getAsJsonArray();
        } catch (JsonParseException | IOException | IllegalStateException e) {
            throw new SummitFormatException(source + ": not valid JSON" + jsonWhere(e), e);
        }
        List<Summit> out = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        for (int i = 0; i < features.size(); i++) {
            try {
                out.add(feature(features.get(i)));
            } catch (IllegalArgumentException e) {
                fail(source, "feature " + (i + 1), e.getMessage(), lenient, skipped);
            }
        }
        return new SummitList(source, out, skipped);
    }

    private static Summit feature(JsonElement e) {
        if (!e.isJsonObject()) {
            throw new IllegalArgumentException("not a GeoJSON Feature (not an object)");
        }
        JsonObject f = e.getAsJsonObject();
        JsonElement geom = f.get("geometry");
        String type = geom != null && geom.isJsonObject() ? text(geom.getAsJsonObject().get("type")) : null;
        if (!"Point".equals(type)) {
            throw new IllegalArgumentException("geometry is not a Point" + (type == null ? "" : " (it is a " + type + ")"));
        }
        JsonElement c = geom.getAsJsonObject().get("coordinates");
        if (c == null || !c.isJsonArray() || c.getAsJsonArray().size() < 2 || !jsonNumber(c.getAsJsonArray().get(0))
                || !jsonNumber(c.getAsJsonArray().get(1))) {
            throw new IllegalArgumentException("no numeric coordinates (want [longitude, latitude])");
        }
        JsonArray xy = c.getAsJsonArray();
        double lon = number(xy.get(0).getAsString(), "longitude"), lat = number(xy.get(1).getAsString(), "latitude");
        JsonElement propsElement = f.get("properties");
        JsonObject props = propsElement != null && propsElement.isJsonObject() ? propsElement.getAsJsonObject() : null;
        String name = props == null ? null : text(props.get("name"));
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("no name property");
        }
        JsonElement eleElement = props.get("ele");
        double elevation = Double.NaN;
        if (eleElement != null && !eleElement.isJsonNull()) {
            String ele = text(eleElement);
            if (ele == null) {
                throw new IllegalArgumentException("ele is not a number or text");
            }
            if (!ele.isBlank()) {
                String plain = ele.strip().replaceFirst("(?i)\\s*m$", "").replace(',', '.');
                if (!isDecimal(plain)) {
                    throw new IllegalArgumentException("bad ele '" + ele + "' (want metres as a decimal number)");
                }
                elevation = number(plain, "ele");
            }
        }
        return summit(name.strip(), lat, lon, elevation);
    }

    private static boolean jsonNumber(JsonElement e) {
        return e.isJsonPrimitive() && e.getAsJsonPrimitive().isNumber();
    }

    /** A string or number property as text; null for anything else (absent, null, object, array, boolean). */
    private static String text(JsonElement e) {
        if (e == null || !e.isJsonPrimitive()) {
            return null;
        }
        JsonPrimitive p = e.getAsJsonPrimitive();
        return p.isString() || p.isNumber() ? p.getAsString() : null;
    }

    /** Where Gson's parser gave up, as " at line L, column C", without its internals. */
    private static String jsonWhere(Exception e) {
        Matcher m = Pattern.compile("line (\\d+) column (\\d+)").matcher(String.valueOf(e.getMessage()));
        return m.find() ? " (at line " + m.group(1) + ", column " + m.group(2) + ")" : "";
    }

    private static void fail(String source, String where, String problem, boolean lenient, List<String> skipped) {
        String msg = where + ": " + problem;
        if (!lenient) {
            throw new SummitFormatException(source + ": " + msg + " (read leniently to skip bad "
                    + (where.startsWith("feature") ? "features" : "lines") + ")");
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

    /** A summit, with coordinates outside [−90, 90] × [−180, 180] reported as a bad value. */
    private static Summit summit(String name, double lat, double lon, double elevation) {
        if (!(lat >= -90 && lat <= 90)) {
            throw new IllegalArgumentException("latitude " + lat + " out of range -90…90");
        }
        if (!(lon >= -180 && lon <= 180)) {
            throw new IllegalArgumentException("longitude " + lon + " out of range -180…180");
        }
        // Control characters (a GeoJSON name may hold line breaks and tabs) as spaces, as the text formats' lines have
        // them: a name is one line in P-summits.csv and on the labels.
        return new Summit(name == null ? null : name.replaceAll("\\p{Cntrl}", " ").trim(), lat, lon, elevation);
    }

    static boolean isDecimal(String s) {
        return dempano.util.Decimals.isPlain(s.strip());
    }

    /** A plain decimal number (see the class comment); anything else is a bad value named by {@code what}. */
    static double number(String s, String what) {
        String t = s.strip();
        if (!dempano.util.Decimals.isPlain(t)) {
            throw new IllegalArgumentException("bad " + what + " '" + s + "'" + (t.isEmpty() ? " (empty)" : " (want a decimal number)"));
        }
        double v = Double.parseDouble(t);
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("bad " + what + " '" + s + "' (too large)");
        }
        return v;
    }
}
