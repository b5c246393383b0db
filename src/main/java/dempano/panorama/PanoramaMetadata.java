package dempano.panorama;

import java.util.List;
import java.util.Map;

/**
 * How a panorama was made: everything needed to interpret its pixels, and what it cost.
 *
 * @param latDeg                viewpoint latitude, degrees
 * @param lonDeg                viewpoint longitude, degrees
 * @param groundElevationMetres DEM height at the viewpoint, metres
 * @param offsetMetres          altitude correction added to the DEM height (NaN if an absolute altitude was given)
 * @param standingAltitudeMetres ground the observer stands on, metres
 * @param eyeHeightMetres       eye above the standing altitude, metres
 * @param eyeAltitudeMetres     the eye, metres above sea level
 * @param rangeMetres           range of sight, metres
 * @param refractionCoefficient k
 * @param depthMode             how distances were obtained
 * @param nearMetres            near plane, metres (NaN for the CPU reference, which has none)
 * @param farMetres             far plane (STANDARD_24) / culling distance
 * @param views                 number of perspective views drawn (0 for the CPU reference)
 * @param viewWidthPx           view width
 * @param viewHeightPx          view height
 * @param tilesUsed             tile names read
 * @param tilesMissing          tile names needed but absent (sea level)
 * @param warnings              warnings for the user
 * @param timingsMillis         stage → wall time, milliseconds, in order
 * @param glRenderer            the OpenGL renderer string
 * @param lodErrorPx            bound on the screen error of simplified terrain, pixels (0 = full resolution)
 * @param terrainTriangles      triangles in the terrain mesh drawn (0 for the CPU reference, which
 *                              intersects the full-resolution surface directly)
 * @param viewpointMove         where the automatic corrections moved the eye from and to (the fields above
 *                              describe the viewpoint used); null when none was asked for
 * @param demSources            per tile used, each source that served samples of it, with the vertical datum
 *                              of its heights (several per tile where later DEM sources filled voids)
 */
public record PanoramaMetadata(double latDeg, double lonDeg, double groundElevationMetres, double offsetMetres,
                               double standingAltitudeMetres, double eyeHeightMetres, double eyeAltitudeMetres,
                               double rangeMetres, double refractionCoefficient, DepthMode depthMode,
                               double nearMetres, double farMetres, int views, int viewWidthPx, int viewHeightPx,
                               List<String> tilesUsed, List<String> tilesMissing, List<String> warnings,
                               Map<String, Double> timingsMillis, String glRenderer,
                               double lodErrorPx, long terrainTriangles, dempano.geo.ViewpointMove viewpointMove,
                               List<TileSource> demSources) {
    /**
     * One source's share of one tile.
     *
     * @param tile          tile name, e.g. N46E008
     * @param source        the file that served the samples
     * @param verticalDatum EGM96, EGM2008, EPSG:nnnn or unknown
     * @param samples       samples of the tile (on its grid) served by this file
     */
    public record TileSource(String tile, String source, String verticalDatum, long samples) {
    }

    /** The earth model. */
    public static final String EARTH_MODEL = "WGS84 ellipsoid (exact ECEF/ENU), heights above sea level taken as ellipsoidal";
}
