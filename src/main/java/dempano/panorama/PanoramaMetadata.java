package dempano.panorama;

import java.util.List;
import java.util.Map;

/**
 * How a panorama was made: everything needed to interpret its pixels, and what it cost.
 *
 * @param viewpoint             the eye the panorama was drawn from (after any automatic correction: see
 *                              {@code viewpointMove}); its fields are also this record's own accessors below
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
public record PanoramaMetadata(dempano.geo.Viewpoint viewpoint, double rangeMetres, double refractionCoefficient, DepthMode depthMode,
                               double nearMetres, double farMetres, int views, int viewWidthPx, int viewHeightPx,
                               List<String> tilesUsed, List<String> tilesMissing, List<String> warnings,
                               Map<String, Double> timingsMillis, String glRenderer,
                               double lodErrorPx, long terrainTriangles, dempano.geo.ViewpointMove viewpointMove,
                               List<TileSource> demSources) {
    public PanoramaMetadata {
        java.util.Objects.requireNonNull(viewpoint, "viewpoint");
        // Immutable as the panorama that holds it (the renderer's own lists were handed out, and a caller's change
        // reached the files written later).
        tilesUsed = tilesUsed == null ? null : List.copyOf(tilesUsed);
        tilesMissing = tilesMissing == null ? null : List.copyOf(tilesMissing);
        warnings = warnings == null ? null : List.copyOf(warnings);
        timingsMillis = timingsMillis == null ? null : java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(timingsMillis));
        demSources = demSources == null ? null : List.copyOf(demSources);
    }

    /** Viewpoint latitude, degrees. */
    public double latDeg() {
        return viewpoint.latDeg();
    }

    /** Viewpoint longitude, degrees. */
    public double lonDeg() {
        return viewpoint.lonDeg();
    }

    /** DEM height at the viewpoint, metres. */
    public double groundElevationMetres() {
        return viewpoint.groundElevationMetres();
    }

    /** Altitude correction added to the DEM height, metres (NaN if an absolute altitude was given). */
    public double offsetMetres() {
        return viewpoint.offsetMetres();
    }

    /** Ground the observer stands on, metres above sea level. */
    public double standingAltitudeMetres() {
        return viewpoint.standingAltitudeMetres();
    }

    /** Eye above the standing altitude, metres. */
    public double eyeHeightMetres() {
        return viewpoint.eyeHeightMetres();
    }

    /** The eye, metres above sea level. */
    public double eyeAltitudeMetres() {
        return viewpoint.eyeAltitudeMetres();
    }

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
