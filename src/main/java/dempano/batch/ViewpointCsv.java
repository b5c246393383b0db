package dempano.batch;

import dempano.PanoramaRequest;
import dempano.camera.PhotoOverrides;
import dempano.io.IoMessages;
import dempano.orient.SearchRanges;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;

/**
 * Reads a batch's viewpoint file: CSV (RFC 4180 quoting, comma separated, UTF-8 with or without a
 * byte-order mark, LF or CRLF line ends) whose first line names the columns. Column names are
 * matched without regard to case or surrounding spaces, in any order:
 *
 * <ul>
 *   <li>{@code id} (required): the output id, files {@code D/<id>.png} etc.; see {@link BatchIds}</li>
 *   <li>{@code lat}, {@code lon} (required): viewpoint, decimal degrees north [-90, 90] and east [-180, 180]</li>
 *   <li>{@code altitude_m}: absolute standing altitude, metres above sea level, instead of the DEM height</li>
 *   <li>{@code offset_m}: signed correction added to the DEM height, metres</li>
 *   <li>{@code eye_height_m}: eye above the standing altitude, metres (≥ 0)</li>
 *   <li>{@code range_km}: range of sight, km</li>
 *   <li>{@code ppd}: pixels per degree (360·ppd a whole number)</li>
 *   <li>{@code image}: a photograph (JPEG, PNG, ...; a relative path is relative to the viewpoint file's folder).
 *       A row with an image is a <em>photo row</em>, rendered on the photo's own pixel grid as {@code dempano photo}
 *       renders it ({@link dempano.photo.PhotoJob}): its camera comes from the photo's EXIF/XMP, and the row's
 *       {@code lat}, {@code lon} (both or neither), {@code altitude_m}, {@code offset_m}, {@code eye_height_m} and
 *       the photo columns override it: {@code heading_deg} (true, clockwise from north), {@code pitch_deg} (up
 *       positive), {@code roll_deg} (clockwise positive), {@code hfov_deg} or {@code focal35_mm}. What neither
 *       gives, the row's error names. Where the estimate searches: {@code heading_range_deg} (± around a heading
 *       given), {@code hfov_min_deg} with {@code hfov_max_deg}, or {@code focal35_min_mm} with
 *       {@code focal35_max_mm} (a zoom lens), as {@code dempano photo}'s range flags. {@code ppd} is for panoramas. With an {@code image} column, {@code lat} and
 *       {@code lon} may be left out of the header; a row with an empty image cell is a viewpoint</li>
 * </ul>
 *
 * An empty optional cell, or a missing optional column, takes the value of the defaults request
 * (the command line's options). Other columns (names, notes) are ignored and reported by
 * {@link Parsed#ignoredColumns()}. Blank lines, and lines starting with {@code #} (comments: no id starts so), are skipped.
 *
 * <p>A bad row (a number that is not plain decimal, NaN, a coordinate or setting out of range, a
 * wrong number of fields, an unsafe or repeated id) becomes an invalid {@link BatchRow} with a
 * one-line reason that starts with its line number; the other rows are unaffected. A file that
 * cannot be read, has no header line, lacks a required column or names a column twice throws
 * {@link ViewpointCsvException}. Stateless.
 */
public final class ViewpointCsv {
    public static final String ID = "id", LAT = "lat", LON = "lon", ALTITUDE_M = "altitude_m", OFFSET_M = "offset_m",
            EYE_HEIGHT_M = "eye_height_m", RANGE_KM = "range_km", PPD = "ppd";
    /** Photo rows: the photograph, and its camera's values where the photo's metadata lacks them or is wrong. */
    public static final String IMAGE = "image", HEADING_DEG = "heading_deg", PITCH_DEG = "pitch_deg", ROLL_DEG = "roll_deg",
            HFOV_DEG = "hfov_deg", FOCAL35_MM = "focal35_mm";
    /**
     * Photo rows: where the estimate searches ({@link SearchRanges}, as {@code dempano photo}'s
     * {@code --heading-range-deg}, {@code --hfov-range-deg}, {@code --focal35-range-mm}); a range's two ends in two
     * columns.
     */
    public static final String HEADING_RANGE_DEG = "heading_range_deg", HFOV_MIN_DEG = "hfov_min_deg",
            HFOV_MAX_DEG = "hfov_max_deg", FOCAL35_MIN_MM = "focal35_min_mm", FOCAL35_MAX_MM = "focal35_max_mm";
    /** The columns that only a photo row (one with an image) may fill. */
    public static final List<String> PHOTO_COLUMNS = List.of(HEADING_DEG, PITCH_DEG, ROLL_DEG, HFOV_DEG, FOCAL35_MM,
            HEADING_RANGE_DEG, HFOV_MIN_DEG, HFOV_MAX_DEG, FOCAL35_MIN_MM, FOCAL35_MAX_MM);
    /** The columns read, required first. */
    public static final List<String> COLUMNS = List.of(ID, LAT, LON, ALTITUDE_M, OFFSET_M, EYE_HEIGHT_M, RANGE_KM, PPD,
            IMAGE, HEADING_DEG, PITCH_DEG, ROLL_DEG, HFOV_DEG, FOCAL35_MM, HEADING_RANGE_DEG, HFOV_MIN_DEG, HFOV_MAX_DEG,
            FOCAL35_MIN_MM, FOCAL35_MAX_MM);

    /** A photo row's optional column: what it is called in messages, and the override it makes. */
    /** A photo row's override column; {@code limit}: largest magnitude accepted (an angle's), +∞ for none. */
    private record PhotoColumn(String column, String what,
                               java.util.function.BiFunction<PhotoOverrides, Double, PhotoOverrides> override, double limit) {
        PhotoColumn(String column, String what, java.util.function.BiFunction<PhotoOverrides, Double, PhotoOverrides> override) {
            this(column, what, override, Double.POSITIVE_INFINITY);
        }
    }

    /** The columns a photo row may override its photo's metadata with, in the order they are applied. */
    private static final List<PhotoColumn> PHOTO_OVERRIDES = List.of(
            new PhotoColumn(ALTITUDE_M, "altitude", PhotoOverrides::withAltitudeMetres),
            new PhotoColumn(OFFSET_M, "offset", PhotoOverrides::withOffsetMetres),
            new PhotoColumn(EYE_HEIGHT_M, "eye height", PhotoOverrides::withCameraHeightMetres),
            new PhotoColumn(HEADING_DEG, "heading", PhotoOverrides::withHeadingDeg, PhotoOverrides.HEADING_LIMIT_DEG),
            new PhotoColumn(PITCH_DEG, "pitch", PhotoOverrides::withPitchDeg, PhotoOverrides.PITCH_LIMIT_DEG),
            new PhotoColumn(ROLL_DEG, "roll", PhotoOverrides::withRollDeg, PhotoOverrides.ROLL_LIMIT_DEG),
            new PhotoColumn(HFOV_DEG, "horizontal field of view", PhotoOverrides::withHorizontalFovDeg),
            new PhotoColumn(FOCAL35_MM, "35 mm-equivalent focal length", PhotoOverrides::withFocal35mmMm));

    private static final List<String> REQUIRED = List.of(ID, LAT, LON);

    private ViewpointCsv() {
    }

    /**
     * The rows of a viewpoint file, in file order.
     *
     * @param rows           one per data line, valid or not
     * @param ignoredColumns header names not read (neither required nor optional columns)
     */
    public record Parsed(List<BatchRow> rows, List<String> ignoredColumns) {
        public Parsed {
            rows = List.copyOf(rows);
            ignoredColumns = List.copyOf(ignoredColumns);
        }

        /** The rows that can be rendered. */
        public long validCount() {
            return rows.stream().filter(BatchRow::valid).count();
        }
    }

    /** The file name that reads the rows from standard input. */
    public static final String STANDARD_INPUT = "-";

    /**
     * Reads a viewpoint file (UTF-8; a byte-order mark is skipped); {@value #STANDARD_INPUT}: standard input.
     *
     * @param defaults the request each row starts from (its latitude and longitude are replaced)
     * @throws ViewpointCsvException when the file cannot be read or used at all; the message names the file
     */
    public static Parsed read(Path file, PanoramaRequest defaults) throws ViewpointCsvException {
        boolean stdin = file.toString().equals(STANDARD_INPUT);
        String source = stdin ? "standard input" : file.toString();
        // Photos named relative to the file's folder; from standard input, to the working directory.
        Path parent = stdin ? Path.of("").toAbsolutePath() : file.toAbsolutePath().getParent();
        Decoded d;
        try {
            d = decode(stdin ? System.in.readAllBytes() : Files.readAllBytes(file));
        } catch (IOException e) {
            throw new ViewpointCsvException("cannot read the viewpoint file " + (stdin ? "from " : "") + source + ": "
                    + IoMessages.reason(e), e);
        }
        return parse(source, d.text(), defaults, parent, d.malformed());
    }

    /** A row's error for cells holding bytes that are no UTF-8 (the row is spoilt, not the file). */
    public static final String NOT_UTF8 = "not UTF-8 text (bytes no UTF-8 character is made of; save the file as UTF-8)";

    /**
     * A viewpoint file's text.
     *
     * @param text      the bytes as UTF-8, a leading byte-order mark left out, bytes that are no UTF-8 as U+FFFD
     * @param malformed whether there were such bytes: a row holding U+FFFD is then an error ({@link #NOT_UTF8})
     */
    public record Decoded(String text, boolean malformed) {
    }

    /** Decodes a viewpoint file's bytes (see {@link Decoded}); the Spark job reads its tables with it too. */
    public static Decoded decode(byte[] bytes) {
        String text;
        boolean malformed = false;
        try {
            text = StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            text = new String(bytes, StandardCharsets.UTF_8);
            malformed = true;
        }
        return new Decoded(text.startsWith("\uFEFF") ? text.substring(1) : text, malformed);
    }

    /**
     * Parses viewpoint CSV text.
     *
     * @param source   the file's name, for messages
     * @param text     the whole file; a leading byte-order mark is skipped
     * @param defaults the request each row starts from
     * @throws ViewpointCsvException when there is no header line, a required column is missing, a
     *                               column is named twice or the CSV is broken (an unclosed quote)
     */
    public static Parsed parse(String source, String text, PanoramaRequest defaults) throws ViewpointCsvException {
        return parse(source, text, defaults, null);
    }

    /**
     * Parses viewpoint CSV text whose relative image paths are relative to {@code baseDir}.
     *
     * @param baseDir the folder relative image paths start from; null = the working directory
     */
    public static Parsed parse(String source, String text, PanoramaRequest defaults, Path baseDir) throws ViewpointCsvException {
        return parse(source, text, defaults, baseDir, false);
    }

    /**
     * As above; {@code malformed}: the file held bytes that are no UTF-8, decoded as U+FFFD, and a row holding one is
     * that row's error (the header's, the file's).
     */
    private static Parsed parse(String source, String text, PanoramaRequest defaults, Path baseDir, boolean malformed)
            throws ViewpointCsvException {
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1);
        }
        CSVFormat format = CSVFormat.DEFAULT.builder().setIgnoreEmptyLines(true).setIgnoreSurroundingSpaces(true).setCommentMarker('#')
                .setTrim(true).get();
        int[] lineStarts = lineStarts(text);
        List<BatchRow> rows = new ArrayList<>();
        List<String> ignored = new ArrayList<>();
        Map<String, Integer> columns = null;
        int headerFields = 0;
        Map<String, Integer> firstLineOfId = new HashMap<>();
        try (CSVParser parser = CSVParser.parse(text, format)) {
            Iterator<CSVRecord> it = parser.iterator();
            while (true) {
                CSVRecord r;
                int line;
                try {
                    if (!it.hasNext()) {
                        break;
                    }
                    r = it.next();
                    line = lineOf(text, lineStarts, r.getCharacterPosition());
                } catch (UncheckedIOException | IllegalStateException e) {
                    throw new ViewpointCsvException(source + ": broken CSV after line " + Math.max(1, parser.getCurrentLineNumber())
                            + " (" + oneLine(e.getCause() != null ? e.getCause().getMessage() : e.getMessage())
                            .replaceFirst("^\\((startline \\d+)\\)\\s*", "$1: ") // Commons CSV's own parentheses
                            + "): the file cannot be read past it", e);
                }
                List<String> f = r.toList();
                if (f.stream().allMatch(String::isEmpty)) {
                    continue; // a line of spaces or bare commas
                }
                boolean notUtf8 = malformed && f.stream().anyMatch(v -> v.indexOf('\uFFFD') >= 0);
                if (columns == null) {
                    if (notUtf8) {
                        throw new ViewpointCsvException(source + ": line " + line + ": not UTF-8 text (save the file as UTF-8)");
                    }
                    columns = header(source, line, f, ignored);
                    headerFields = f.size();
                    continue;
                }
                if (notUtf8) {
                    String id = columns.get(ID) != null && f.size() > columns.get(ID) ? f.get(columns.get(ID)) : "";
                    rows.add(BatchRow.invalid(line, BatchIds.printable(id), "line " + line + ": " + NOT_UTF8));
                    continue;
                }
                BatchRow row = row(line, f, headerFields, columns, defaults, firstLineOfId);
                rows.add(row.photo() == null || baseDir == null ? row : new BatchRow(row.lineNumber(), row.id(),
                        row.request(), new BatchPhoto(baseDir.resolve(row.photo().image()), row.photo().overrides(),
                        row.photo().ranges()), null));
            }
        } catch (ViewpointCsvException e) {
            throw e;
        } catch (IOException e) {
            throw new UncheckedIOException(e); // cannot happen: the text is in memory
        }
        if (columns == null) {
            throw new ViewpointCsvException(source + ": empty: want a header line naming the columns " + String.join(",", REQUIRED)
                    + " (optional: " + String.join(", ", COLUMNS.subList(REQUIRED.size(), COLUMNS.size())) + ")");
        }
        return new Parsed(rows, ignored);
    }

    private static Map<String, Integer> header(String source, int line, List<String> names, List<String> ignored)
            throws ViewpointCsvException {
        Map<String, Integer> columns = new LinkedHashMap<>();
        for (int i = 0; i < names.size(); i++) {
            String n = names.get(i).trim().toLowerCase(Locale.ROOT);
            if (COLUMNS.contains(n)) {
                if (columns.put(n, i) != null) {
                    throw new ViewpointCsvException(source + ": line " + line + ": the header names column '" + n + "' twice");
                }
            } else if (!n.isEmpty()) {
                ignored.add(names.get(i).trim());
            }
        }
        for (String c : REQUIRED) {
            if (!columns.containsKey(c) && !(columns.containsKey(IMAGE) && !c.equals(ID))) {
                String separator = names.size() == 1 ? otherSeparator(names.get(0)) : null;
                throw new ViewpointCsvException(source + ": line " + line + ": the header has no column '" + c + "' (it has: "
                        + oneLine(String.join(", ", names)) + "; required: " + String.join(", ", REQUIRED) + "; or id and image for photos)"
                        + (separator == null ? "" : ": the columns seem separated by " + separator + "; separate them by commas"));
            }
        }
        return columns;
    }

    /** How a one-column header line seems separated where not by commas ("a semicolon", "tabs"), else null. */
    private static String otherSeparator(String header) {
        return header.contains(";") ? "semicolons" : header.contains("\t") ? "tabs" : header.contains("|") ? "bars" : null;
    }

    private static BatchRow row(int line, List<String> f, int headerFields, Map<String, Integer> columns,
                                PanoramaRequest defaults, Map<String, Integer> firstLineOfId) {
        String id = f.size() > columns.get(ID) ? f.get(columns.get(ID)) : "";
        String at = "line " + line + ": ";
        if (f.size() != headerFields) {
            return BatchRow.invalid(line, id, at + f.size() + " fields, the header has " + headerFields);
        }
        String idProblem = BatchIds.problem(id);
        if (idProblem != null) {
            return BatchRow.invalid(line, id, at + idProblem);
        }
        Integer first = firstLineOfId.putIfAbsent(BatchIds.collisionKey(id), line);
        if (first != null) {
            return BatchRow.invalid(line, id, at + "duplicate id '" + id + "' (first on line " + first + ")");
        }
        for (Map.Entry<String, String> c : BatchIds.clashingIds(id).entrySet()) {
            Integer other = firstLineOfId.get(c.getKey());
            if (other != null) {
                return BatchRow.invalid(line, id, at + "id '" + id + "' would write " + c.getValue() + ", a file of id '"
                        + c.getKey() + "' (line " + other + "): choose ids that are not another id with a file suffix");
            }
        }
        try {
            if (!cell(f, columns, ALTITUDE_M).isEmpty() && !cell(f, columns, OFFSET_M).isEmpty()) {
                // The offset was ignored without a word beside an altitude (panorama and photo rows alike).
                throw new IllegalArgumentException("altitude_m and offset_m both set the standing height (an absolute"
                        + " altitude, or the DEM's height plus an offset): give one");
            }
            String image = cell(f, columns, IMAGE);
            if (!image.isEmpty()) {
                return photoRow(line, id, image, f, columns, defaults);
            }
            for (String c : PHOTO_COLUMNS) {
                if (!cell(f, columns, c).isEmpty()) {
                    throw new IllegalArgumentException(c + " is for photo rows: this row has no image");
                }
            }
            double lat = required(number(f, columns, LAT, "latitude", Double.NaN), "latitude");
            double lon = required(number(f, columns, LON, "longitude", Double.NaN), "longitude");
            PanoramaRequest r = atViewpoint(defaults, lat, lon);
            double altitude = number(f, columns, ALTITUDE_M, "altitude", Double.NaN);
            if (!Double.isNaN(altitude)) {
                r = r.withAltitudeMetres(altitude);
            }
            r = r.withOffsetMetres(number(f, columns, OFFSET_M, "offset", r.offsetMetres()))
                    .withEyeHeightMetres(number(f, columns, EYE_HEIGHT_M, "eye height", r.eyeHeightMetres()))
                    .withPixelsPerDegree(number(f, columns, PPD, "ppd", r.pixelsPerDegree()));
            return new BatchRow(line, id, withRange(r, f, columns), null, null);
        } catch (IllegalArgumentException e) {
            return BatchRow.invalid(line, id, at + oneLine(e.getMessage()));
        }
    }

    /** A photo row: the image, its camera values from the row, the defaults' render settings. */
    private static BatchRow photoRow(int line, String id, String image, List<String> f, Map<String, Integer> columns,
                                     PanoramaRequest defaults) {
        if (!cell(f, columns, PPD).isEmpty()) {
            throw new IllegalArgumentException("ppd is for panoramas: a photo is rendered on its own pixel grid");
        }
        Path path;
        try {
            path = Path.of(image);
        } catch (java.nio.file.InvalidPathException e) {
            throw new IllegalArgumentException("image '" + BatchIds.printable(image) + "' is not a file path");
        }
        double lat = number(f, columns, LAT, "latitude", Double.NaN), lon = number(f, columns, LON, "longitude", Double.NaN);
        PhotoOverrides o = PhotoOverrides.NONE;
        if (Double.isNaN(lat) != Double.isNaN(lon)) {
            throw new IllegalArgumentException("give both lat and lon, or neither (the photo's GPS position)");
        }
        PanoramaRequest r = defaults;
        if (!Double.isNaN(lat)) {
            r = atViewpoint(defaults, lat, lon); // checks the range
            o = o.withPosition(lat, lon);
        }
        for (PhotoColumn c : PHOTO_OVERRIDES) {
            double v = number(f, columns, c.column(), c.what(), Double.NaN);
            if (Math.abs(v) > c.limit()) {
                throw new IllegalArgumentException(c.column() + " must be within ±" + (int) c.limit() + " degrees, got " + v);
            }
            if (!Double.isNaN(v)) {
                o = c.override().apply(o, v);
            }
        }
        if (o.lensesGiven().size() > 1) { // (a row's only lens columns) the focal length was left unused without a word
            throw new IllegalArgumentException(HFOV_DEG + " and " + FOCAL35_MM + " both set the field of view: give one");
        }
        double headingRange = number(f, columns, HEADING_RANGE_DEG, "heading range", Double.NaN),
                hfovMin = number(f, columns, HFOV_MIN_DEG, "smallest field of view", Double.NaN),
                hfovMax = number(f, columns, HFOV_MAX_DEG, "largest field of view", Double.NaN),
                focalMin = number(f, columns, FOCAL35_MIN_MM, "shortest focal length", Double.NaN),
                focalMax = number(f, columns, FOCAL35_MAX_MM, "longest focal length", Double.NaN);
        SearchRanges ranges;
        try {
            ranges = new SearchRanges(headingRange, hfovMin, hfovMax, focalMin, focalMax);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("search ranges (" + HEADING_RANGE_DEG + ", " + HFOV_MIN_DEG + "/" + HFOV_MAX_DEG
                    + ", " + FOCAL35_MIN_MM + "/" + FOCAL35_MAX_MM + ", as dempano photo's flags): " + e.getMessage());
        }
        return new BatchRow(line, id, withRange(r, f, columns), new BatchPhoto(path, o, ranges), null);
    }

    private static PanoramaRequest withRange(PanoramaRequest r, List<String> f, Map<String, Integer> columns) {
        double rangeKm = number(f, columns, RANGE_KM, "range", Double.NaN);
        return Double.isNaN(rangeKm) ? r : r.withRangeMetres(rangeKm * 1000);
    }

    private static double required(double v, String what) {
        if (Double.isNaN(v)) {
            throw new IllegalArgumentException(what + " is empty");
        }
        return v;
    }

    /** A cell's text; empty when the column is missing. */
    private static String cell(List<String> f, Map<String, Integer> columns, String column) {
        Integer i = columns.get(column);
        return i == null ? "" : f.get(i);
    }

    /**
     * A cell as a plain decimal number, or {@code absent} when the column is missing or the cell empty.
     *
     * @throws IllegalArgumentException naming the column and the text for anything else (NaN, 1,5, 0x10, 12m)
     */
    private static double number(List<String> f, Map<String, Integer> columns, String column, String what, double absent) {
        String s = cell(f, columns, column);
        if (s.isEmpty()) {
            return absent;
        }
        if (!dempano.util.Decimals.isPlain(s)) {
            throw new IllegalArgumentException(what + " '" + BatchIds.printable(s) + "' is not a decimal number");
        }
        double v = Double.parseDouble(s);
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(what + " '" + s + "' is out of range");
        }
        return v;
    }

    /** The defaults request at another viewpoint (its coordinates checked). */
    static PanoramaRequest atViewpoint(PanoramaRequest d, double latDeg, double lonDeg) {
        return d.movedTo(latDeg, lonDeg);
    }

    /** Offsets at which lines start (a line ends at LF, CRLF or a lone CR). */
    private static int[] lineStarts(String text) {
        List<Integer> starts = new ArrayList<>();
        starts.add(0);
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n' || (c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n'))) {
                starts.add(i + 1);
            }
        }
        return starts.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The 1-based line of the first non-blank character at or after a record's start. */
    private static int lineOf(String text, int[] lineStarts, long position) {
        int p = (int) Math.min(position, text.length());
        while (true) { // a record's position is before the blank and comment lines that precede it
            while (p < text.length() && Character.isWhitespace(text.charAt(p))) {
                p++;
            }
            if (p >= text.length() || text.charAt(p) != '#') {
                break;
            }
            while (p < text.length() && text.charAt(p) != '\n' && text.charAt(p) != '\r') {
                p++;
            }
        }
        int lo = 0, hi = lineStarts.length - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (lineStarts[mid] <= p) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo + 1;
    }

    static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s*\\R\\s*", " ").strip();
    }
}
