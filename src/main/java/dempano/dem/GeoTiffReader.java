package dempano.dem;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import mil.nga.tiff.FieldTagType;
import mil.nga.tiff.FileDirectory;
import mil.nga.tiff.TIFFImage;
import mil.nga.tiff.TiffReader;

/**
 * Reads GeoTIFF DEMs in geographic coordinates (latitude/longitude in degrees, e.g. EPSG:4326) and
 * resamples them onto the one-degree tile grid that {@link Mosaic} stitches.
 *
 * <p>Supported: one band of int8/uint8/int16/uint16/int32/uint32/float32/float64 heights in metres;
 * uncompressed, LZW, Deflate and PackBits compression, horizontal (2) and floating-point (3)
 * predictors; striped and tiled layouts; Cloud-Optimized GeoTIFFs (the full-resolution image is read,
 * overviews are ignored); georeferencing by one ModelTiepoint plus ModelPixelScale, or by a
 * ModelTransformation without rotation; PixelIsArea (the default) and PixelIsPoint; the GDAL_NODATA
 * tag (samples equal to it, and NaN, are voids); a band scale and offset in the GDAL_METADATA tag (height = value ×
 * scale + offset, e.g. heights stored in decimetres); either byte order. Refused, with a one-line message
 * naming the file: projected CRSs, a prime meridian other than Greenwich, heights in feet (a
 * VerticalUnitsGeoKey other than metre, or a vertical CRS named "(ft)"/"(ftUS)" as EPSG names them),
 * rotated or control-point georeferencing, several bands, complex, 1-bit, 16-bit float or 64-bit integer samples, other
 * compressions (JPEG, ZSTD, LERC, ...), BigTIFF, angular units other than degrees, heights outside
 * −1000…9000 m (corrupt, other units, or a nodata value without the GDAL_NODATA tag), and files that
 * are no (or a truncated) TIFF. The TIFF library (mil.nga tiff) parses the directories and
 * decompresses the blocks; predictors and sample conversion are done here.
 *
 * <p>Tiles are indexed by file name ({@link TileId#parseFileName}); each is resampled onto a square
 * grid of samples on the tile's edges, as {@link HgtTile} holds them (see {@link #toTile}), so tiles of
 * any resolution mix in one {@link Mosaic}. Copernicus tiles, whose last row and column stop one pixel
 * short of the tile's edges, are joined to their neighbours' first column and row (see
 * {@link #read(Path, java.util.function.Function)}).
 *
 * <p>Where pixels lie: with PixelIsArea the tiepoint names the corner of a pixel, so the centre of
 * column {@code c} is at longitude {@code X + (c + 0.5 − I)·Sx}; with PixelIsPoint the tiepoint names
 * the pixel's centre, {@code X + (c − I)·Sx}. The height of a pixel is the height at its centre.
 */
public final class GeoTiffReader {
    /** The finest tile grid a GeoTIFF is resampled onto: 1 arc-second (SRTM1, Copernicus GLO-30). */
    public static final int MAX_INTERVALS_PER_DEGREE = 3600;

    // GeoKey ids (GeoTIFF 1.1 spec).
    /** Geographic CRSs read as WGS 84: WGS 84 (2-D, 3-D) and ETRS89 and NAD83, within a metre or two of it. */
    private static final java.util.Set<Integer> WGS84_LIKE_CRS = java.util.Set.of(4326, 4979, 4258, 4269);
    private static final int GEOG_GEODETIC_DATUM = 2050, WGS84_DATUM = 6326;
    private static final int GT_MODEL_TYPE = 1024, GT_RASTER_TYPE = 1025, GT_CITATION = 1026, GEOGRAPHIC_TYPE = 2048,
            GEOG_PRIME_MERIDIAN = 2051, GEOG_ANGULAR_UNITS = 2054, GEOG_PRIME_MERIDIAN_LONG = 2061, VERTICAL_UNITS = 4099, PROJECTED_CS_TYPE = 3072, VERTICAL_CS_TYPE = 4096, VERTICAL_CITATION = 4097,
            VERTICAL_DATUM = 4098;
    private static final int TAG_GEO_DOUBLE_PARAMS = 34736, TAG_GEO_ASCII_PARAMS = 34737;
    private static final int MODEL_PROJECTED = 1, MODEL_GEOGRAPHIC = 2, RASTER_PIXEL_IS_POINT = 2;
    private static final int USER_DEFINED = 32767;

    private GeoTiffReader() {
    }

    /**
     * Where a geographic grid's pixel centres lie.
     *
     * @param lonOfCol0Deg  longitude of the centre of column 0, degrees
     * @param latOfRow0Deg  latitude of the centre of row 0, degrees
     * @param colSpacingDeg longitude step per column, degrees (&gt; 0: column 0 is west)
     * @param rowSpacingDeg latitude step per row, degrees (&gt; 0: row 0 is north, the usual case)
     * @param pixelIsPoint  the raster type the file declared (already applied to the two origins)
     */
    public record PixelCentres(double lonOfCol0Deg, double latOfRow0Deg, double colSpacingDeg, double rowSpacingDeg,
                               boolean pixelIsPoint) {
        /** Fractional column of a longitude (column centres are integers). */
        public double colOf(double lonDeg) {
            return (lonDeg - lonOfCol0Deg) / colSpacingDeg;
        }

        /** Fractional row of a latitude (row centres are integers). */
        public double rowOf(double latDeg) {
            return (latOfRow0Deg - latDeg) / rowSpacingDeg;
        }

        /** Longitude of a (fractional) column, degrees. */
        public double lonOfCol(double col) {
            return lonOfCol0Deg + col * colSpacingDeg;
        }

        /** Latitude of a (fractional) row, degrees. */
        public double latOfRow(double row) {
            return latOfRow0Deg - row * rowSpacingDeg;
        }
    }

    /**
     * A GeoTIFF's full-resolution heights and where its pixel centres lie.
     *
     * @param source          the file, for messages
     * @param width           columns
     * @param height          rows
     * @param heightsMetres   row-major heights, metres; NaN for voids (nodata)
     * @param centres         where the pixel centres lie
     * @param verticalDatum   see {@link DemContribution#verticalDatum()}
     * @param geographicEpsg  the geographic CRS's EPSG code (4326 for WGS 84), 32767 if user-defined
     */
    public record Grid(String source, int width, int height, float[] heightsMetres, PixelCentres centres,
                       String verticalDatum, int geographicEpsg) {
        /** Fractional column of a longitude (column centres are integers). */
        public double colOf(double lonDeg) {
            return centres.colOf(lonDeg);
        }

        /** Fractional row of a latitude (row centres are integers). */
        public double rowOf(double latDeg) {
            return centres.rowOf(latDeg);
        }

        /** The longitude 360° away from lonDeg that is nearest the grid's centre. */
        double unwrap(double lonDeg) {
            double centre = centres.lonOfCol((width - 1) / 2.0);
            return lonDeg + 360 * Math.rint((centre - lonDeg) / 360);
        }
    }

    /**
     * Reads a GeoTIFF tile named like {@code N46E008.tif} or
     * {@code Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif}, resampled onto that tile's grid (see
     * {@link #toTile}) and void-filled.
     *
     * @throws DemException naming the file and the problem
     */
    public static HgtTile read(Path file) {
        return read(file, t -> null);
    }

    /**
     * Like {@link #read(Path)}, but where the file's pixels stop short of the tile's eastern or southern
     * edge (Copernicus tiles: the edge pixels are the neighbours'), the samples between the last pixel
     * centres and the edge are interpolated towards the neighbouring GeoTIFFs' first column / row
     * (only those are decoded) instead of repeating the last pixels. Without a neighbour, or when it
     * cannot be read, the last pixels are repeated (and a warning says why for an unreadable one).
     *
     * @param neighbours the GeoTIFF holding a tile, or null if there is none
     */
    public static HgtTile read(Path file, java.util.function.Function<TileId, Path> neighbours) {
        return read(file, neighbours, VoidFill.DEFAULT);
    }

    /** {@link #read(Path, java.util.function.Function)} with the given void fill. */
    public static HgtTile read(Path file, java.util.function.Function<TileId, Path> neighbours, VoidFill fill) {
        TileId id = TileId.parseFileName(file.getFileName().toString());
        Grid g = readGrid(file);
        List<String> warnings = new ArrayList<>();
        return toTile(stitch(g, id, neighbours, warnings), id, warnings, fill);
    }

    /**
     * The grid with one more column (row) just east (south) of it, from the neighbouring tiles' files,
     * where its last pixel centres stop short of the tile's eastern (southern) edge by up to one pixel.
     */
    static Grid stitch(Grid g, TileId id, java.util.function.Function<TileId, Path> neighbours, List<String> warnings) {
        double eastCol = g.colOf(g.unwrap(id.lonWestDeg() + 1)), southRow = g.rowOf(id.latSouthDeg());
        boolean east = eastCol > g.width() - 1 + 1e-6 && eastCol <= g.width() + 1e-6;
        boolean south = southRow > g.height() - 1 + 1e-6 && southRow <= g.height() + 1e-6;
        if (!east && !south) {
            return g;
        }
        int w = g.width() + (east ? 1 : 0), h = g.height() + (south ? 1 : 0);
        double lonV = g.centres().lonOfCol(g.width()), latV = g.centres().latOfRow(g.height());
        float[] z = new float[w * h];
        for (int r = 0; r < g.height(); r++) {
            System.arraycopy(g.heightsMetres(), r * g.width(), z, r * w, g.width());
        }
        Grid e = east ? neighbour(neighbours, TileId.of(id.latSouthDeg(), id.lonWestDeg() + 1), Part.FIRST_COLUMN, g, warnings) : null;
        Grid s = south ? neighbour(neighbours, TileId.of(id.latSouthDeg() - 1 < -90 ? id.latSouthDeg() : id.latSouthDeg() - 1,
                id.lonWestDeg()), Part.FIRST_ROW, g, warnings) : null;
        if (south && id.latSouthDeg() == -90) {
            s = null;
        }
        if (east) {
            for (int r = 0; r < g.height(); r++) {
                z[r * w + g.width()] = e != null ? at(e, g.centres().latOfRow(r), lonV) : z[r * w + g.width() - 1];
            }
        }
        if (south) {
            for (int c = 0; c < g.width(); c++) {
                z[g.height() * w + c] = s != null ? at(s, latV, g.centres().lonOfCol(c)) : z[(g.height() - 1) * w + c];
            }
        }
        if (east && south) {
            Grid se = id.latSouthDeg() == -90 ? null
                    : neighbour(neighbours, TileId.of(id.latSouthDeg() - 1, id.lonWestDeg() + 1), Part.FIRST_PIXEL, g, warnings);
            z[w * h - 1] = se != null ? at(se, latV, lonV)
                    : s != null ? z[w * h - 2] : e != null ? z[(h - 1) * w - 1] : z[(h - 2) * w + w - 2];
        }
        return new Grid(g.source(), w, h, z, g.centres(), g.verticalDatum(), g.geographicEpsg());
    }

    private static Grid neighbour(java.util.function.Function<TileId, Path> neighbours, TileId id, Part part, Grid of,
                                  List<String> warnings) {
        Path file = neighbours.apply(id);
        if (file == null) {
            return null;
        }
        try {
            return readGrid(file, part);
        } catch (DemException e) {
            warnings.add(of.source() + ": edge towards " + id + " not joined (" + e.getMessage() + "); the last pixels are repeated");
            return null;
        }
    }

    /** A neighbour's height at a coordinate (its pixels, bilinear, up to one pixel beyond), NaN if void. */
    private static float at(Grid n, double latDeg, double lonDeg) {
        return sample(n, n.rowOf(latDeg), n.colOf(n.unwrap(lonDeg)), true, true);
    }

    /**
     * Reads the full-resolution heights and georeferencing of a GeoTIFF.
     *
     * @throws DemException naming the file and the problem (unreadable, not a TIFF, truncated,
     *                      unsupported layout or compression, projected CRS, implausible heights)
     */
    public static Grid readGrid(Path file) {
        return readGrid(file, Part.ALL);
    }

    /** Which pixels to decode: all, or only the first column or row (for a neighbour's edge). */
    enum Part {
        ALL, FIRST_COLUMN, FIRST_ROW, FIRST_PIXEL
    }

    static Grid readGrid(Path file, Part part) {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new DemException(file + ": no such file", e);
        } catch (IOException e) {
            throw new DemException(file + ": cannot read (" + e + ")", e);
        }
        return decode(file.toString(), file.getFileName().toString(), bytes, part);
    }

    /** {@link #readGrid} on bytes already read; {@code fileName} decides the datum by naming convention. */
    static Grid decode(String source, String fileName, byte[] bytes, Part part) {
        if (bytes.length >= 4 && (bytes[0] == 'I' && bytes[2] == 43 && bytes[3] == 0 || bytes[0] == 'M' && bytes[2] == 0 && bytes[3] == 43)) {
            throw new DemException(source + " is a BigTIFF, which dempano cannot read; rewrite it as a classic TIFF, "
                    + "e.g. gdal_translate -co BIGTIFF=NO (one-degree tiles are far below 4 GB)");
        }
        checkDirectoryChain(source, bytes);
        FileDirectory dir;
        try {
            TIFFImage image = TiffReader.readTiff(bytes);
            dir = fullResolution(image);
        } catch (RuntimeException e) {
            throw new DemException(source + " is not a readable TIFF file (" + reason(e) + "; truncated, or not a TIFF?)", e);
        }
        if (dir == null) {
            throw new DemException(source + " holds no image");
        }
        Map<Integer, Object> keys = geoKeys(source, dir);
        Object model = keys.get(GT_MODEL_TYPE);
        if (model == null) {
            throw new DemException(source + " has no GeoTIFF georeferencing keys (GTModelTypeGeoKey): cannot tell "
                    + "where its pixels lie; write it as a GeoTIFF in EPSG:4326, e.g. gdal_translate -a_srs EPSG:4326");
        }
        if (intKey(keys, GT_MODEL_TYPE) == MODEL_PROJECTED) {
            Integer epsg = keys.get(PROJECTED_CS_TYPE) instanceof Integer i ? i : null;
            String crs = epsg == null ? "no EPSG code" : epsg == USER_DEFINED ? "user-defined" : "EPSG:" + epsg;
            throw new DemException(source + " is in a projected CRS (" + crs + "); reproject it to geographic lat/lon, "
                    + "e.g. with gdalwarp -t_srs EPSG:4326");
        }
        if (intKey(keys, GT_MODEL_TYPE) != MODEL_GEOGRAPHIC) {
            throw new DemException(source + " has model type " + model + " (not geographic lat/lon); reproject it "
                    + "to geographic lat/lon, e.g. with gdalwarp -t_srs EPSG:4326");
        }
        Object units = keys.get(GEOG_ANGULAR_UNITS);
        if (units instanceof Integer u && u != 9102 && u != 9122) {
            throw new DemException(source + " gives coordinates in angular unit EPSG:" + u + ", not degrees; "
                    + "reproject it with gdalwarp -t_srs EPSG:4326");
        }
        Object meridian = keys.get(GEOG_PRIME_MERIDIAN), meridianLon = keys.get(GEOG_PRIME_MERIDIAN_LONG);
        if (meridian instanceof Integer pm && pm != 8901 && pm != USER_DEFINED
                || meridianLon instanceof Double lon && lon != 0) {
            throw new DemException(source + " counts longitudes from a prime meridian other than Greenwich ("
                    + (meridianLon instanceof Double lon ? lon + "° east of it" : "EPSG:" + meridian)
                    + "); reproject it with gdalwarp -t_srs EPSG:4326");
        }
        String heightUnit = heightUnitProblem(keys);
        if (heightUnit != null) {
            throw new DemException(source + " gives heights in " + heightUnit + ", not metres; convert them, "
                    + "e.g. gdal_translate -scale with the factor to metres and -a_srs EPSG:4326");
        }
        int geographic = keys.get(GEOGRAPHIC_TYPE) instanceof Integer g ? g : USER_DEFINED;
        Object datum = keys.get(GEOG_GEODETIC_DATUM);
        if (geographic != USER_DEFINED && !WGS84_LIKE_CRS.contains(geographic)
                || geographic == USER_DEFINED && datum instanceof Integer d && d != WGS84_DATUM && d != USER_DEFINED) {
            // Another datum's latitudes and longitudes are off WGS 84's by up to hundreds of metres (ED50: ~100 m).
            throw new DemException(source + " gives latitude and longitude on the geodetic datum of "
                    + (geographic != USER_DEFINED ? "EPSG:" + geographic : "datum EPSG:" + datum)
                    + ", not WGS 84 (positions would be off by up to hundreds of metres); reproject it with gdalwarp -t_srs EPSG:4326");
        }
        boolean point = keys.get(GT_RASTER_TYPE) instanceof Integer t && t == RASTER_PIXEL_IS_POINT;

        long declaredWidth = dir.getImageWidth().longValue(), declaredHeight = dir.getImageHeight().longValue();
        if (declaredWidth <= 0 || declaredHeight <= 0) {
            throw new DemException(source + " declares an image of " + declaredWidth + " × " + declaredHeight + " pixels (corrupt file?)");
        }
        if (declaredWidth * declaredHeight > MAX_PIXELS) {
            throw new DemException(String.format(Locale.ROOT, "%s declares %d × %d pixels, more than dempano reads from one file "
                    + "(%.0f M; a one-degree tile at 1/3″ is 10 812 × 10 812 = 117 M, and tiles are resampled to at most 3600 "
                    + "intervals a degree): cut it into one-degree tiles, or coarsen it (gdal_translate -tr)",
                    source, declaredWidth, declaredHeight, MAX_PIXELS / 1e6));
        }
        int width = (int) declaredWidth, height = (int) declaredHeight;
        double[] geo = georeferencing(source, dir); // X, Y of raster position (I, J), Sx, Sy
        double shift = point ? 0 : 0.5; // raster coordinates of pixel (0, 0)'s centre
        double lon0 = geo[0] + (shift - geo[4]) * geo[2];
        double lat0 = geo[1] - (shift - geo[5]) * geo[3];
        if (part == Part.FIRST_COLUMN || part == Part.FIRST_PIXEL) {
            width = 1;
        }
        if (part == Part.FIRST_ROW || part == Part.FIRST_PIXEL) {
            height = 1;
        }
        float[] heights;
        try {
            heights = heights(source, dir, bytes, width, height);
        } catch (OutOfMemoryError e) {
            throw new DemException(String.format(Locale.ROOT, "%s: too little memory to read its %d × %d pixels (Java heap "
                    + "limit %.0f MB): give Java more memory, e.g. DEMPANO_OPTS=-Xmx%dg, or cut the file into smaller tiles",
                    source, width, height, Runtime.getRuntime().maxMemory() / 1e6,
                    Math.max(2, 2 * (int) Math.ceil(Runtime.getRuntime().maxMemory() / 1e9))), e);
        }
        return new Grid(source, width, height, heights, new PixelCentres(lon0, lat0, geo[2], geo[3], point),
                verticalDatum(keys, fileName), geographic);
    }

    /**
     * Why the heights are not in metres, or null: a VerticalUnitsGeoKey other than metre (EPSG:9001), or,
     * as GDAL writes a compound CRS without that key, a vertical CRS whose name says feet (EPSG names of
     * such CRSs end in "(ft)" or "(ftUS)", e.g. "NAVD88 height (ftUS)", EPSG:6360).
     */
    private static String heightUnitProblem(Map<Integer, Object> keys) {
        if (keys.get(VERTICAL_UNITS) instanceof Integer u && u != 9001 && u != USER_DEFINED) {
            return "unit EPSG:" + u + " (VerticalUnitsGeoKey)";
        }
        for (int key : new int[] {GT_CITATION, VERTICAL_CITATION}) {
            if (keys.get(key) instanceof String name) {
                java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\((ft|ftUS|ftIndian|ftCla|ftSe|ftGC|ftBr[^)]*|foot|feet)\\)",
                        java.util.regex.Pattern.CASE_INSENSITIVE).matcher(name);
                if (m.find()) {
                    return "feet (vertical CRS \"" + name.replaceAll(".*\\+\\s*", "").trim() + "\")";
                }
            }
        }
        return null;
    }

    /**
     * Most pixels read from one file: 2^28 (268 M, 1 GB of heights as floats), 16 384² — over twice a one-degree tile at
     * 1/3″ (10 812², USGS 3DEP); tiles are resampled to at most {@link #MAX_INTERVALS_PER_DEGREE} intervals a degree anyway.
     * A file declaring more is refused before anything is allocated (a 282-byte file declaring 46 341² pixels
     * overflowed the heights' array size, one declaring 30 000² took 3.7 GB before it was refused).
     */
    static final long MAX_PIXELS = 1L << 28;

    /** Most image directories in one file: a Cloud-Optimized GeoTIFF has its image, a dozen overviews and their masks. */
    static final int MAX_DIRECTORIES = 1000;

    /**
     * Refuses a file whose chain of image directories loops back or runs on without end (the TIFF library follows it
     * for ever, holding every directory: a 282-byte file whose first directory named itself as the next grew to 18 GB),
     * or that holds an empty text tag (the library fails with an index out of bounds). Only the chain and the
     * entries' types and counts are read; anything else wrong is the library's to find.
     */
    static void checkDirectoryChain(String source, byte[] b) {
        if (b.length < 8 || !(b[0] == 'I' && b[1] == 'I' || b[0] == 'M' && b[1] == 'M')) {
            return; // not a TIFF header: the library says so
        }
        ByteBuffer buf = ByteBuffer.wrap(b).order(b[0] == 'I' ? java.nio.ByteOrder.LITTLE_ENDIAN : java.nio.ByteOrder.BIG_ENDIAN);
        java.util.Set<Long> seen = new java.util.HashSet<>();
        long offset = buf.getInt(4) & 0xffffffffL;
        while (offset != 0 && offset + 2 <= b.length) {
            if (!seen.add(offset)) {
                throw new DemException(source + " is a corrupt TIFF file: its chain of image directories loops back to the one at byte "
                        + offset);
            }
            if (seen.size() > MAX_DIRECTORIES) {
                throw new DemException(source + " is a corrupt TIFF file: its chain of image directories runs past "
                        + MAX_DIRECTORIES + " directories");
            }
            int entries = buf.getShort((int) offset) & 0xffff;
            long next = offset + 2 + 12L * entries;
            if (next + 4 > b.length) {
                return; // cut short: the library says so
            }
            for (int i = 0; i < entries; i++) {
                int entry = (int) offset + 2 + 12 * i;
                if (buf.getShort(entry + 2) == 2 && emptyText(buf, entry)) { // (the library fails on it, naming nothing)
                    int tag = buf.getShort(entry) & 0xffff;
                    throw new DemException(source + " is a corrupt TIFF file: its text tag " + tag
                            + (tag == 42113 ? " (GDAL_NODATA)" : "") + " is empty (no characters before its closing NUL)");
                }
            }
            offset = buf.getInt((int) next) & 0xffffffffL;
        }
    }

    /** Whether a text (ASCII) entry holds nothing but NULs, or nothing at all. */
    private static boolean emptyText(ByteBuffer buf, int entry) {
        long count = buf.getInt(entry + 4) & 0xffffffffL;
        long at = count <= 4 ? entry + 8 : buf.getInt(entry + 8) & 0xffffffffL;
        if (at + count > buf.capacity()) {
            return false; // cut short: the library says so
        }
        for (long k = 0; k < count; k++) {
            if (buf.get((int) (at + k)) != 0) {
                return false;
            }
        }
        return true;
    }

    /** The first image that is not a reduced-resolution overview or a mask (NewSubfileType 0). */
    private static FileDirectory fullResolution(TIFFImage image) {
        for (FileDirectory d : image.getFileDirectories()) {
            Number type = d.getNumberEntryValue(FieldTagType.NewSubfileType);
            if (type == null || (type.longValue() & 5) == 0) {
                return d;
            }
        }
        return null;
    }

    /** GeoKey id → Integer, Double or String value. */
    private static Map<Integer, Object> geoKeys(String source, FileDirectory dir) {
        Map<Integer, Object> keys = new TreeMap<>();
        List<Integer> d = dir.getIntegerListEntryValue(FieldTagType.GeoKeyDirectory);
        if (d == null) {
            return keys;
        }
        List<Double> doubles = dir.getDoubleListEntryValue(FieldTagType.GeoDoubleParams);
        String ascii = dir.getStringEntryValue(FieldTagType.GeoAsciiParams);
        if (d.size() < 4 || d.size() < 4 + 4 * d.get(3)) {
            throw new DemException(source + ": corrupt GeoKeyDirectory (" + d.size() + " values for " + (d.size() < 4 ? "?" : d.get(3))
                    + " keys)");
        }
        for (int k = 0; k < d.get(3); k++) {
            int id = d.get(4 + 4 * k), location = d.get(5 + 4 * k), count = d.get(6 + 4 * k), value = d.get(7 + 4 * k);
            if (location == 0) {
                keys.put(id, value);
            } else if (location == TAG_GEO_DOUBLE_PARAMS && doubles != null && value < doubles.size()) {
                keys.put(id, doubles.get(value));
            } else if (location == TAG_GEO_ASCII_PARAMS && ascii != null && value + count <= ascii.length()) {
                keys.put(id, ascii.substring(value, value + count).replaceAll("\\|$", ""));
            }
        }
        return keys;
    }

    private static int intKey(Map<Integer, Object> keys, int id) {
        return keys.get(id) instanceof Integer i ? i : -1;
    }

    /** X, Y (degrees) of raster position (I, J), pixel sizes Sx, Sy (degrees, Sy positive north-up), I, J. */
    private static double[] georeferencing(String source, FileDirectory dir) {
        List<Double> tie = dir.getModelTiepoint();
        List<Double> scale = dir.getModelPixelScale();
        List<Double> m = dir.getDoubleListEntryValue(FieldTagType.ModelTransformation);
        double[] g;
        if (tie != null && tie.size() > 6) {
            throw new DemException(source + " is georeferenced by " + tie.size() / 6 + " control points, not a regular "
                    + "grid; warp it first, e.g. gdalwarp -t_srs EPSG:4326");
        } else if (tie != null && tie.size() == 6 && scale != null && scale.size() >= 2) {
            g = new double[] {tie.get(3), tie.get(4), scale.get(0), scale.get(1), tie.get(0), tie.get(1)};
        } else if (m != null && m.size() == 16) {
            if (m.get(1) != 0 || m.get(4) != 0) {
                throw new DemException(source + " has a rotated or sheared grid (ModelTransformation); warp it first, "
                        + "e.g. gdalwarp -t_srs EPSG:4326");
            }
            g = new double[] {m.get(3), m.get(7), m.get(0), -m.get(5), 0, 0};
        } else {
            throw new DemException(source + " has no usable georeferencing (neither ModelTiepoint with ModelPixelScale "
                    + "nor ModelTransformation)");
        }
        if (!(g[2] > 0) || !(g[3] != 0) || !Double.isFinite(g[0]) || !Double.isFinite(g[1]) || Double.isInfinite(g[3])) {
            throw new DemException(source + ": unusable pixel size " + g[2] + "° × " + g[3]
                    + "° (needs a positive, finite east-west size)");
        }
        return g;
    }

    /** Compression codes the TIFF library decodes. */
    private static final Map<Integer, String> COMPRESSIONS = Map.of(1, "none", 5, "LZW", 8, "Deflate",
            32946, "Deflate", 32773, "PackBits");
    private static final Map<Integer, String> KNOWN_UNSUPPORTED = Map.of(6, "old JPEG", 7, "JPEG", 34887, "LERC",
            34925, "LZMA", 50000, "ZSTD", 50001, "WebP", 50002, "JPEG XL", 2, "CCITT RLE", 3, "CCITT G3", 4, "CCITT G4");

    /**
     * Decodes the pixels [0, width) × [0, height) into heights, NaN for voids. The TIFF library parses
     * the directory and decompresses each strip or tile; predictors and sample conversion are done
     * here, on whole blocks (the library's per-sample path takes ~8 s for a 3600² float tile, and
     * undoes predictors in little-endian order only).
     */
    private static float[] heights(String source, FileDirectory dir, byte[] file, int width, int height) {
        int compression = dir.getCompression() == null ? 1 : dir.getCompression();
        if (!COMPRESSIONS.containsKey(compression)) {
            throw new DemException(source + " uses TIFF compression " + compression
                    + (KNOWN_UNSUPPORTED.containsKey(compression) ? " (" + KNOWN_UNSUPPORTED.get(compression) + ")" : "")
                    + ", which dempano cannot decode; recompress it, e.g. gdal_translate -co COMPRESS=DEFLATE");
        }
        int predictor = dir.getPredictor() == null ? 1 : dir.getPredictor();
        if (predictor != 1 && predictor != 2 && predictor != 3) {
            throw new DemException(source + " uses TIFF predictor " + predictor + ", which dempano cannot decode "
                    + "(supported: 1 none, 2 horizontal, 3 floating point)");
        }
        if (dir.getSamplesPerPixel() != 1) {
            throw new DemException(source + " has " + dir.getSamplesPerPixel() + " bands; a DEM needs exactly one "
                    + "band of heights (extract it, e.g. gdal_translate -b 1)");
        }
        int bits = dir.getBitsPerSample() == null ? 1 : dir.getBitsPerSample().get(0);
        int format = dir.getSampleFormat() == null ? 1 : dir.getSampleFormat().get(0);
        boolean floating = format == 3;
        if (!(floating ? bits == 32 || bits == 64 : (format == 1 || format == 2) && (bits == 8 || bits == 16 || bits == 32))) {
            throw new DemException(source + ": unsupported sample type (" + bits + "-bit " + (floating ? "float"
                    : format == 2 ? "signed integer" : format == 1 ? "unsigned integer" : format == 5 ? "complex integer"
                    : format == 6 ? "complex float" : "sample format " + format)
                    + "; supported: 8/16/32-bit integers, 32/64-bit floats)");
        }
        if (predictor == 3 && !floating) {
            throw new DemException(source + ": floating-point predictor on integer samples (corrupt file?)");
        }
        int bytes = bits / 8;
        java.nio.ByteOrder order = dir.getReader().getByteOrder();
        boolean tiled = dir.isTiled();
        int fullWidth = dir.getImageWidth().intValue(), fullHeight = dir.getImageHeight().intValue();
        int bw = tiled ? dir.getTileWidth().intValue() : fullWidth;
        int bh = tiled ? dir.getTileHeight().intValue()
                : dir.getRowsPerStrip() == null ? fullHeight : (int) Math.min(fullHeight, dir.getRowsPerStrip().longValue());
        List<? extends Number> offsets = tiled ? dir.getTileOffsets() : dir.getStripOffsets();
        List<? extends Number> counts = tiled ? dir.getTileByteCounts() : dir.getStripByteCounts();
        if (bw <= 0 || bh <= 0 || offsets == null || counts == null) {
            throw new DemException(source + ": no image data layout (strip or tile offsets missing; corrupt file?)");
        }
        int across = (fullWidth + bw - 1) / bw, down = (fullHeight + bh - 1) / bh;
        if (offsets.size() < (long) across * down || counts.size() < (long) across * down) {
            throw new DemException(source + ": " + offsets.size() + " image blocks listed, " + across * down
                    + " needed (corrupt file?)");
        }
        // Before anything is allocated: a block of n bytes decompresses to at most n × its method's greatest ratio, so
        // a file declaring more pixels than its blocks can hold is refused here, not after gigabytes were allocated.
        long ratio = MAX_RATIO.get(compression);
        for (int by = 0; by * bh < height; by++) {
            for (int bx = 0; bx * bw < width; bx++) {
                int k = by * across + bx, rows = tiled ? bh : Math.min(bh, fullHeight - by * bh);
                long len = counts.get(k).longValue(), needed = (long) bw * rows * bytes;
                if (len < 0 || len * ratio < needed) {
                    throw new DemException(source + ": image block " + k + " holds " + len + " bytes, " + needed + " expected"
                            + (ratio > 1 ? " (no " + COMPRESSIONS.get(compression) + " data expands " + ratio + "-fold or more)" : "")
                            + " for its " + bw + " × " + rows + " pixels (truncated or corrupt file, or not the "
                            + fullWidth + " × " + fullHeight + " pixels it declares?)");
                }
            }
        }
        double nodata = nodata(source, dir);
        float nodataFloat = (float) nodata;
        double[] scaleOffset = scaleOffset(source, dir);
        double scale = scaleOffset[0], offset = scaleOffset[1];
        float[] out = new float[width * height];
        mil.nga.tiff.compression.CompressionDecoder decoder = dir.getDecoder();
        for (int by = 0; by * bh < height; by++) {
            for (int bx = 0; bx * bw < width; bx++) {
                int k = by * across + bx;
                long off = offsets.get(k).longValue(), len = counts.get(k).longValue();
                if (off < 0 || len < 0 || off + len > file.length) {
                    throw new DemException(source + ": image block " + k + " lies beyond the end of the file ("
                            + file.length + " bytes; truncated?)");
                }
                int rows = tiled ? bh : Math.min(bh, fullHeight - by * bh);
                byte[] block;
                long blockBytes = (long) bw * bh * bytes; // a whole block (a last strip may be written whole)
                try {
                    block = compression == 8 || compression == 32946 ? inflate(file, (int) off, (int) len, blockBytes)
                            : decoder.decode(java.util.Arrays.copyOfRange(file, (int) off, (int) (off + len)), order);
                } catch (RuntimeException | java.util.zip.DataFormatException e) {
                    throw new DemException(source + ": cannot decompress image block " + k + " (" + reason(e)
                            + "; truncated or corrupt file?)", e);
                }
                if (block != null && block.length > blockBytes) {
                    throw new DemException(source + ": image block " + k + " decompresses to more than the " + blockBytes
                            + " bytes of its " + bw + " × " + bh + " pixels (corrupt file, or a decompression bomb)");
                }
                if (block == null || block.length < (long) bw * rows * bytes) {
                    throw new DemException(source + ": image block " + k + " holds " + (block == null ? 0 : block.length)
                            + " bytes, " + (long) bw * rows * bytes + " expected (truncated or corrupt file?)");
                }
                ByteBuffer buf = ByteBuffer.wrap(block).order(order);
                for (int r = 0; r < rows; r++) {
                    int y = by * bh + r;
                    if (y >= height) {
                        break;
                    }
                    int rowStart = r * bw * bytes;
                    if (predictor == 2) {
                        undoHorizontal(buf, rowStart, bw, bytes);
                    }
                    int cols = Math.min(bw, width - bx * bw);
                    for (int c = 0; c < cols; c++) {
                        double v;
                        if (predictor == 3) {
                            v = floatingPointSample(block, rowStart, bw, bytes, c);
                        } else {
                            int at = rowStart + c * bytes;
                            v = switch (bytes) {
                                case 1 -> format == 2 ? block[at] : block[at] & 0xff;
                                case 2 -> format == 2 ? buf.getShort(at) : buf.getShort(at) & 0xffff;
                                case 4 -> floating ? buf.getFloat(at) : format == 2 ? buf.getInt(at) : buf.getInt(at) & 0xffffffffL;
                                default -> buf.getDouble(at);
                            };
                        }
                        int x = bx * bw + c, i = y * width + x;
                        if (Double.isNaN(v) || v == nodata || (bits == 32 && floating && (float) v == nodataFloat)) {
                            out[i] = Float.NaN;
                            continue;
                        }
                        v = v * scale + offset; // the stored value → metres (GDAL's scale and offset; 1 and 0 by default)
                        if (v < HgtReader.MIN_PLAUSIBLE_METRES || v > HgtReader.MAX_PLAUSIBLE_METRES) {
                            throw new DemException(String.format(Locale.ROOT, "%s: implausible height %s m at row %d, column %d "
                                    + "(corrupt, not metres, or a nodata value without a GDAL_NODATA tag%s)", source,
                                    fmt(v), y, x, Double.isNaN(nodata) ? "" : "; GDAL_NODATA is " + fmt(nodata)));
                        } else {
                            out[i] = (float) v;
                        }
                    }
                }
            }
        }
        return out;
    }

    /**
     * The greatest ratio of decompressed to compressed bytes of each supported compression: Deflate's 258-byte matches
     * coded in 2 bits (1032), LZW's longest strings (under 4096 bytes) for a 12-bit code, PackBits' 128-byte run for 2
     * bytes. Upper bounds, so no real file is refused.
     */
    private static final Map<Integer, Long> MAX_RATIO = Map.of(1, 1L, 5, 4096L, 8, 1100L, 32946, 1100L, 32773, 64L);

    /**
     * A Deflate (zlib) block, stopped as soon as it yields more than {@code capBytes} (a decompression bomb: a 1 MB
     * file whose block inflated to 1 GB was read whole, and its surplus ignored). A stream cut short gives what it
     * holds; the caller finds it short.
     */
    private static byte[] inflate(byte[] file, int off, int len, long capBytes) throws java.util.zip.DataFormatException {
        java.util.zip.Inflater inflater = new java.util.zip.Inflater();
        try {
            inflater.setInput(file, off, len);
            java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream((int) Math.min(capBytes + 1, 1 << 20));
            byte[] chunk = new byte[1 << 16];
            while (!inflater.finished() && out.size() <= capBytes) {
                int n = inflater.inflate(chunk);
                if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                    break;
                }
                out.write(chunk, 0, n);
            }
            return out.toByteArray();
        } finally {
            inflater.end();
        }
    }

    /** Undoes the horizontal predictor (2) on one row of a block in place: sums along the row, wrapping. */
    private static void undoHorizontal(ByteBuffer buf, int rowStart, int n, int bytes) {
        for (int c = 1; c < n; c++) {
            int at = rowStart + c * bytes, prev = at - bytes;
            switch (bytes) {
                case 1 -> buf.put(at, (byte) (buf.get(at) + buf.get(prev)));
                case 2 -> buf.putShort(at, (short) (buf.getShort(at) + buf.getShort(prev)));
                case 4 -> buf.putInt(at, buf.getInt(at) + buf.getInt(prev));
                default -> buf.putLong(at, buf.getLong(at) + buf.getLong(prev));
            }
        }
    }

    /**
     * Sample c of a row under the floating-point predictor (3): the row holds byte planes, most
     * significant first, differenced byte by byte. The first call for a row (c == 0) undoes the
     * differencing in place.
     */
    private static double floatingPointSample(byte[] block, int rowStart, int n, int bytes, int c) {
        if (c == 0) {
            for (int j = rowStart + 1; j < rowStart + n * bytes; j++) {
                block[j] += block[j - 1];
            }
        }
        long v = 0;
        for (int k = 0; k < bytes; k++) {
            v = (v << 8) | (block[rowStart + k * n + c] & 0xff);
        }
        return bytes == 4 ? Float.intBitsToFloat((int) v) : Double.longBitsToDouble(v);
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    /** The GDAL_METADATA items and the attributes read from them ({@link #scaleOffset}). */
    private static final java.util.regex.Pattern GDAL_ITEM = java.util.regex.Pattern.compile("<Item\\s([^>]*)>([^<]*)</Item>"),
            GDAL_ROLE = java.util.regex.Pattern.compile("role\\s*=\\s*\"(scale|offset)\"", java.util.regex.Pattern.CASE_INSENSITIVE),
            GDAL_SAMPLE = java.util.regex.Pattern.compile("sample\\s*=\\s*\"(\\d+)\"");

    /**
     * The band's scale and offset from the GDAL_METADATA tag ({@code <Item name="SCALE" role="scale">}, {@code
     * role="offset"}, of band 0 or of no band): height = stored value × scale + offset. {1, 0} when absent. A file in
     * decimetres or centimetres (scale 0.1, 0.01) was read as metres, heights 10 or 100 times too large, or one with
     * scale 2 at half its height.
     */
    static double[] scaleOffset(String source, FileDirectory dir) {
        String xml = dir.getStringEntryValue(FieldTagType.GDAL_METADATA);
        double[] out = {1, 0};
        if (xml == null || xml.isBlank()) {
            return out;
        }
        java.util.regex.Matcher m = GDAL_ITEM.matcher(xml);
        while (m.find()) {
            String attributes = m.group(1);
            java.util.regex.Matcher role = GDAL_ROLE.matcher(attributes);
            java.util.regex.Matcher sample = GDAL_SAMPLE.matcher(attributes);
            if (!role.find() || (sample.find() && !sample.group(1).equals("0"))) {
                continue;
            }
            double v;
            try {
                v = Double.parseDouble(m.group(2).trim());
            } catch (NumberFormatException e) {
                throw new DemException(source + ": GDAL metadata " + role.group(1).toLowerCase(Locale.ROOT) + " '"
                        + m.group(2).trim() + "' is not a number");
            }
            boolean isScale = role.group(1).equalsIgnoreCase("scale");
            if (!Double.isFinite(v) || (isScale && v == 0)) {
                throw new DemException(source + ": GDAL metadata " + (isScale ? "scale" : "offset") + " " + fmt(v)
                        + " cannot turn stored values into heights");
            }
            out[isScale ? 0 : 1] = v;
        }
        return out;
    }

    /** The GDAL_NODATA value, NaN if none (NaN samples are voids anyway). */
    private static double nodata(String source, FileDirectory dir) {
        String s = dir.getStringEntryValue(FieldTagType.GDAL_NODATA);
        if (s == null || s.isBlank()) {
            return Double.NaN;
        }
        String t = s.trim().replace("\0", "").toLowerCase(Locale.ROOT);
        try {
            return switch (t) {
                case "nan", "-nan" -> Double.NaN;
                case "inf", "+inf" -> Double.POSITIVE_INFINITY;
                case "-inf" -> Double.NEGATIVE_INFINITY;
                default -> Double.parseDouble(t);
            };
        } catch (NumberFormatException e) {
            throw new DemException(source + ": GDAL_NODATA tag '" + s.trim() + "' is not a number");
        }
    }

    /** The vertical datum from the vertical GeoKeys, else the Copernicus naming, else unknown. */
    private static String verticalDatum(Map<Integer, Object> keys, String fileName) {
        int cs = intKey(keys, VERTICAL_CS_TYPE), datum = intKey(keys, VERTICAL_DATUM);
        if (cs == 5773 || datum == 5171) {
            return DemContribution.EGM96;
        }
        if (cs == 3855 || datum == 1027) {
            return DemContribution.EGM2008;
        }
        if (cs > 0 && cs != USER_DEFINED) {
            return "EPSG:" + cs;
        }
        if (keys.get(VERTICAL_CITATION) instanceof String citation) {
            String c = citation.toUpperCase(Locale.ROOT).replace(" ", "");
            if (c.contains("EGM2008") || c.contains("EGM08")) {
                return DemContribution.EGM2008;
            }
            if (c.contains("EGM96")) {
                return DemContribution.EGM96;
            }
        }
        if (fileName.toLowerCase(Locale.ROOT).startsWith("copernicus_")) {
            return DemContribution.EGM2008; // Copernicus DEM heights refer to EGM2008 (product handbook)
        }
        return DemContribution.UNKNOWN;
    }

    /** Intervals per degree of the tile grid for a pixel size: 1/size rounded, at most {@link #MAX_INTERVALS_PER_DEGREE}. */
    static int intervalsPerDegree(double pixelSizeDeg) {
        double per = 1 / Math.abs(pixelSizeDeg);
        long rounded = Math.round(per);
        long ipd = Math.abs(per - rounded) < 1e-6 * per ? rounded : (long) Math.ceil(per);
        return (int) Math.max(1, Math.min(MAX_INTERVALS_PER_DEGREE, ipd));
    }

    /**
     * Resamples a grid onto one tile's grid: (n + 1)² samples on the tile's edges, n = 1/pixel size
     * (the finer of the two directions, so Copernicus' width-reduced tiles above 50° come out square
     * at their latitude resolution) capped at {@link #MAX_INTERVALS_PER_DEGREE}. A tile sample on a
     * pixel centre (within 10⁻⁶ pixel) takes that pixel's height exactly; others are bilinear from the
     * four pixels around them, void if any of those with a non-zero weight is void. Samples on the tile's
     * edges up to one pixel beyond the outermost pixel centres (Copernicus tiles hold no southern row and eastern
     * column: they are the neighbours' first) take the edge pixels' heights; other samples beyond the pixel centres
     * (a file covering part of its tile) are voids, for the void fill or the next DEM source. Voids are then filled as for .hgt tiles.
     *
     * @throws DemException if the grid covers no part of the tile a pixel across (a file named for another tile); a grid
     *                      reaching more than a pixel beyond the tile is read for the tile alone, with a warning
     */
    public static HgtTile toTile(Grid g, TileId id) {
        return toTile(g, id, List.of());
    }

    /** {@link #toTile(Grid, TileId)} with warnings found before (they come first in the tile's). */
    static HgtTile toTile(Grid g, TileId id, List<String> earlierWarnings) {
        return toTile(g, id, earlierWarnings, VoidFill.DEFAULT);
    }

    /** {@link #toTile(Grid, TileId, List)} with the given void fill. */
    static HgtTile toTile(Grid g, TileId id, List<String> earlierWarnings, VoidFill fill) {
        int ipd = intervalsPerDegree(Math.min(g.centres().colSpacingDeg(), Math.abs(g.centres().rowSpacingDeg())));
        // The tile in the grid's rows and columns (a south-up grid counts rows the other way).
        double rowA = g.rowOf(id.latSouthDeg()), rowB = g.rowOf(id.latSouthDeg() + 1);
        double centreCol = g.colOf(g.unwrap(id.lonWestDeg() + 0.5)), halfCols = 0.5 / g.centres().colSpacingDeg();
        double tileRowLo = Math.min(rowA, rowB), tileRowHi = Math.max(rowA, rowB);
        double tileColLo = centreCol - halfCols, tileColHi = centreCol + halfCols;
        double latA = g.centres().latOfRow(0), latB = g.centres().latOfRow(g.height() - 1);
        double lonA = g.centres().lonOfCol(0), lonB = g.centres().lonOfCol(g.width() - 1);
        String covers = String.format(Locale.ROOT, "its pixels cover latitude %.4f…%.4f°, longitude %.4f…%.4f°",
                Math.min(latA, latB), Math.max(latA, latB), lonA, lonB);
        // Any part of the tile a pixel or more across will do (a file covering part of its tile leaves the rest void);
        // none, or only its edge, is a file named for another tile.
        if (!(Math.min(tileRowHi, g.height() - 1) - Math.max(tileRowLo, 0) >= 1
                && Math.min(tileColHi, g.width() - 1) - Math.max(tileColLo, 0) >= 1)) {
            throw new DemException(g.source() + " is named for tile " + id + " but " + covers);
        }
        List<String> beyond = new ArrayList<>();
        if (tileRowLo - 1 > 0 || g.height() - 1 > tileRowHi + 1 || tileColLo - 1 > 0 || g.width() - 1 > tileColHi + 1) {
            // Pixels more than one beyond the tile's edges (PixelIsArea and Copernicus' layouts stay within one) are not
            // read: each tile is read from the file named for it.
            beyond.add(g.source() + " reaches beyond its tile " + id + " (" + covers + "): only " + id
                    + " is read from it; cut it into one-degree tiles, one file each (gdal_translate -projwin W N E S)");
        }
        int n = ipd + 1;
        float[] h = new float[n * n];
        double[] cols = new double[n];
        for (int c = 0; c < n; c++) {
            cols[c] = g.colOf(g.unwrap(id.lonWestDeg() + (double) c / ipd));
        }
        for (int r = 0; r < n; r++) {
            double row = g.rowOf(id.latSouthDeg() + 1 - (double) r / ipd);
            for (int c = 0; c < n; c++) {
                // Only the tile's own edge samples may take the edge pixels' heights from up to a pixel away (a
                // Copernicus tile's missing last row and column): inside the tile, beyond a file that covers part of
                // it, samples are voids (a repeated edge column was taken as data, and the next DEM source's blend
                // carried its error kilometres in).
                h[r * n + c] = sample(g, row, cols[c], r == 0 || r == n - 1, c == 0 || c == n - 1);
            }
        }
        List<String> warnings = new ArrayList<>(earlierWarnings);
        warnings.addAll(beyond);
        String zeros = Plausibility.zeroRowsBelowLand(h, n, g.source());
        if (zeros != null) {
            warnings.add(zeros);
        }
        BitSet mask = VoidFiller.voidMask(h);
        VoidReport voids = VoidFiller.fill(h, n, fill);
        String needles = Plausibility.needles(h, n, id, g.source());
        if (needles != null) {
            warnings.add(needles);
        }
        return new HgtTile(id, g.source(), n, h, voids, mask, warnings).withVerticalDatum(g.verticalDatum());
    }

    /**
     * Height at fractional (row, col) of the grid, NaN if void or out of range (see {@link #toTile}): up to one pixel
     * beyond the outermost pixel centres where {@code rowMayClamp}/{@code colMayClamp} allow it (the edge pixels'
     * heights), else only within them.
     */
    static float sample(Grid g, double row, double col, boolean rowMayClamp, boolean colMayClamp) {
        row = snap(row);
        col = snap(col);
        double rowSlack = rowMayClamp ? 1 : 0, colSlack = colMayClamp ? 1 : 0;
        if (!(row >= -rowSlack && row <= g.height() - 1 + rowSlack && col >= -colSlack && col <= g.width() - 1 + colSlack)) {
            return Float.NaN;
        }
        row = Math.max(0, Math.min(g.height() - 1, row));
        col = Math.max(0, Math.min(g.width() - 1, col));
        int r0 = (int) Math.floor(row), c0 = (int) Math.floor(col);
        double fr = row - r0, fc = col - c0;
        float[] z = g.heightsMetres();
        int w = g.width();
        double sum = 0;
        for (int dr = 0; dr < 2; dr++) {
            double wr = dr == 0 ? 1 - fr : fr;
            if (wr == 0) {
                continue;
            }
            for (int dc = 0; dc < 2; dc++) {
                double wc = dc == 0 ? 1 - fc : fc;
                if (wc == 0) {
                    continue;
                }
                float v = z[(r0 + dr) * w + c0 + dc];
                if (Float.isNaN(v)) {
                    return Float.NaN;
                }
                sum += wr * wc * v;
            }
        }
        return (float) sum;
    }

    private static double snap(double x) {
        double r = Math.rint(x);
        return Math.abs(x - r) < 1e-6 ? r : x;
    }

    private static String reason(Throwable e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null || m.isBlank() ? "" : ": " + m);
    }
}
