package dempano.dem;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A one-degree SRTM tile named by its south-west corner: {@code N46E008} covers 46–47°N, 8–9°E;
 * {@code S16E166} covers 16–15°S, 166–167°E.
 *
 * @param latSouthDeg latitude of the southern edge, degrees, in [-90, 89]
 * @param lonWestDeg  longitude of the western edge, degrees, in [-180, 179]
 */
public record TileId(int latSouthDeg, int lonWestDeg) implements Comparable<TileId> {
    // A name such as N46E008, optionally followed by a suffix (N19W155v2.3a) as GDAL accepts,
    // then .hgt, .hgt.zip or .hgt.gz (the gzip of AWS Terrain Tiles' "skadi" layout).
    private static final Pattern FILE_NAME =
            Pattern.compile("^([NS])(\\d{2})([EW])(\\d{3})([^/\\\\]*?)\\.hgt(\\.zip|\\.gz)?$", Pattern.CASE_INSENSITIVE);
    // GeoTIFF tiles: N46E008.tif (as gdal_translate output is usually named, suffix allowed) and the
    // Copernicus DEM naming, Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif (GLO-30; _30_ for GLO-90).
    private static final Pattern TIFF_NAME =
            Pattern.compile("^([NS])(\\d{2})([EW])(\\d{3})([^/\\\\]*?)\\.tiff?$", Pattern.CASE_INSENSITIVE);
    private static final Pattern COPERNICUS_NAME = Pattern.compile(
            "^Copernicus_DSM(?:_COG)?_\\d+_([NS])(\\d{2})_00_([EW])(\\d{3})_00_DEM\\.tiff?$", Pattern.CASE_INSENSITIVE);
    private static final String EXPECTED = "expected e.g. N46E008.hgt, S16E166.hgt.zip, N19W155v2.3a.hgt.zip, N46E008.hgt.gz, "
            + "N46E008.tif or Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif";

    public TileId {
        if (latSouthDeg < -90 || latSouthDeg > 89 || lonWestDeg < -180 || lonWestDeg > 179) {
            throw new IllegalArgumentException("no SRTM tile has its south-west corner at "
                    + latSouthDeg + ", " + lonWestDeg);
        }
    }

    /** The tile whose south-west corner is at the given integer degrees, longitude wrapped into [-180, 180). */
    public static TileId of(int latSouthDeg, int lonWestDeg) {
        return new TileId(latSouthDeg, Math.floorMod(lonWestDeg + 180, 360) - 180);
    }

    /** The tile containing a point; a point on a tile edge belongs to the tile north/east of it. */
    public static TileId containing(double latDeg, double lonDeg) {
        int lat = (int) Math.floor(latDeg);
        if (lat == 90) {
            lat = 89;
        }
        return of(lat, (int) Math.floor(lonDeg));
    }

    /**
     * Parses a tile file name ({@code N46E008.hgt}, {@code n46e008.hgt}, {@code N19W155v2.3a.hgt.zip}, {@code N46E008.hgt.gz},
     * GeoTIFFs {@code N46E008.tif} and {@code Copernicus_DSM_COG_10_N46_00_E008_00_DEM.tif}).
     *
     * @throws DemException if the name is not a tile name
     */
    public static TileId parseFileName(String fileName) {
        Matcher m = FILE_NAME.matcher(fileName);
        if (!m.matches()) {
            m = TIFF_NAME.matcher(fileName);
        }
        if (!m.matches()) {
            m = COPERNICUS_NAME.matcher(fileName);
        }
        if (!m.matches()) {
            throw new DemException("'" + fileName + "' is not a tile file name (" + EXPECTED + ")");
        }
        return ofNameParts(m, fileName);
    }

    /** The tile a match's groups 1–4 (N|S, latitude, E|W, longitude) name, or a DemException naming the file. */
    private static TileId ofNameParts(Matcher m, String fileName) {
        int lat = Integer.parseInt(m.group(2));
        int lon = Integer.parseInt(m.group(4));
        boolean south = m.group(1).equalsIgnoreCase("S");
        boolean west = m.group(3).equalsIgnoreCase("W");
        if (lat > (south ? 90 : 89) || lon > (west ? 180 : 179)) {
            throw new DemException("'" + fileName + "' names a tile outside the globe (lat " + (south ? "S" : "N")
                    + lat + ", lon " + (west ? "W" : "E") + lon + ")");
        }
        if ((south && lat == 0) || (west && lon == 0)) {
            // A tile is named by its south-west corner: S00 and W000 name none (0…1° S is S01, 0…1° W is W001); read as
            // N00/E000 such a file was placed a degree off without a word.
            throw new DemException("'" + fileName + "' names no tile: a tile is named by its south-west corner, so "
                    + (south && lat == 0 ? "0…1° S is S01 and 0…1° N is N00" : "0…1° W is W001 and 0…1° E is E000"));
        }
        return new TileId(south ? -lat : lat, west ? -lon : lon);
    }

    /** True if a file name parses as a tile name (of a tile on the globe: not {@code N99E999.hgt}). */
    public static boolean isTileFileName(String fileName) {
        try {
            parseFileName(fileName);
            return true;
        } catch (DemException e) {
            return false;
        }
    }

    /**
     * True if a file name ends in {@code .hgt}, {@code .hgt.zip}, {@code .hgt.gz}, {@code .tif} or {@code .tiff}, any
     * case: meant as a tile, valid or not.
     */
    public static boolean looksLikeTileFile(String fileName) {
        String lower = fileName.toLowerCase(Locale.ROOT);
        return lower.endsWith(".hgt") || lower.endsWith(".hgt.zip") || lower.endsWith(".hgt.gz") || isGeoTiffFileName(lower);
    }

    private static final Pattern NAME_START = Pattern.compile("^([NS])(\\d{2})([EW])(\\d{3})", Pattern.CASE_INSENSITIVE);

    /**
     * The tile a file's name begins with ({@code N46E008.hgt.bak}, {@code n46e008_old.HGT.tmp}), whatever follows; null
     * when it begins with none. For hints: a missing tile whose file is there under a name that is not read.
     */
    public static TileId namedAtStart(String fileName) {
        Matcher m = NAME_START.matcher(fileName);
        if (!m.find()) {
            return null;
        }
        try {
            return ofNameParts(m, fileName);
        } catch (DemException e) {
            return null; // N99E999.bak names no tile
        }
    }

    /** True if a file name ends in {@code .tif} or {@code .tiff}, any case. */
    public static boolean isGeoTiffFileName(String fileName) {
        String lower = fileName.toLowerCase(Locale.ROOT);
        return lower.endsWith(".tif") || lower.endsWith(".tiff");
    }

    /** What tile file names look like, for messages. */
    static String expectedNames() {
        return EXPECTED;
    }

    /** The canonical name, e.g. {@code N46E008}, {@code S16E166}, {@code N00W001}. */
    public String name() {
        return String.format(Locale.ROOT, "%s%02d%s%03d", latSouthDeg < 0 ? "S" : "N", Math.abs(latSouthDeg),
                lonWestDeg < 0 ? "W" : "E", Math.abs(lonWestDeg));
    }

    @Override
    public int compareTo(TileId o) {
        int c = Integer.compare(o.latSouthDeg, latSouthDeg); // north first
        return c != 0 ? c : Integer.compare(lonWestDeg, o.lonWestDeg);
    }

    @Override
    public String toString() {
        return name();
    }
}
