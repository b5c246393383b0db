package dempano;

import dempano.dem.MissingTilePolicy;
import dempano.dem.TileSelection;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import dempano.panorama.ViewLayout;
import java.util.EnumSet;
import java.util.Set;

/**
 * What to render. Start from {@link #at(double, double)} (all defaults) and adjust with the
 * {@code with…} methods. Immutable; every value is checked when the request is made.
 *
 * @param latDeg            viewpoint latitude, degrees [-90, 90]
 * @param lonDeg            viewpoint longitude, degrees [-180, 180]
 * @param offsetMetres      signed correction to the DEM height at the viewpoint (default 0)
 * @param altitudeMetres    absolute standing altitude, metres above sea level; NaN (default) = from the DEM
 * @param eyeHeightMetres   eye above the standing altitude (default 2 m)
 * @param rangeMetres       range of sight (default 100 km)
 * @param pixelsPerDegree   panorama resolution, pixels per degree in (0, 200] with 360·ppd a whole number
 *                          (default 20); normalized as {@link dempano.panorama.PanoramaGeometry#checkedPixelsPerDegree},
 *                          so the request and the panorama's geometry hold the same value
 * @param elevationRange    elevation angles covered (default -30°:30°)
 * @param refraction        refraction coefficient (default k = 0.13)
 * @param depthMode         how distances are obtained (default {@link DepthMode#SHADER_RANGE})
 * @param layers            extra per-pixel layers (default none)
 * @param nearMetres        near plane (default 1 m)
 * @param supersampling     view pixels per panorama pixel, linear (default 1)
 * @param views             perspective views (default 8)
 * @param missingTiles      what a missing tile means (default {@link MissingTilePolicy#AUTO}: sea beside data, an
 *                          error for no data at all or none under the viewpoint without an altitude)
 * @param lodErrorPx        bound on the screen error of simplified distant terrain, panorama pixels
 *                          (default {@link dempano.terrain.LevelOfDetail#DEFAULT_MAX_ERROR_PX}; 0 = full
 *                          resolution everywhere). The GL path only: the reference is always exact.
 * @param colour            compute the colour image (default true); false renders distances only,
 *                          skipping colour shading, read-back and stitching
 * @param distance          compute the distance map (default true); false renders colour only,
 *                          skipping depth linearization and the distance interpolation (the
 *                          silhouette lines and an auto elevation range then use the nearest view
 *                          sample's range). Layers and summits need distances.
 * @param snapToSummitMetres radius, metres, within which the viewpoint moves to the highest DEM sample
 *                          ({@link dempano.geo.ViewpointAdjustment#highestWithin}); NaN (default) = stay
 * @param clearViewMetres   radius, metres, within which no terrain may rise above the eye's horizontal: the
 *                          eye is raised as far as needed ({@link dempano.geo.ViewpointAdjustment#clearViewEyeAltitudeMetres});
 *                          NaN (default) = no lift
 */
public record PanoramaRequest(double latDeg, double lonDeg, double offsetMetres, double altitudeMetres,
                              double eyeHeightMetres, double rangeMetres, double pixelsPerDegree,
                              ElevationRange elevationRange, Refraction refraction, DepthMode depthMode,
                              Set<Layer> layers, double nearMetres, double supersampling, int views,
                              MissingTilePolicy missingTiles, double lodErrorPx, boolean colour,
                              boolean distance, double snapToSummitMetres, double clearViewMetres,
                              boolean exactDistances) {
    public static final double DEFAULT_RANGE_METRES = 100_000;
    public static final double DEFAULT_PIXELS_PER_DEGREE = 20;
    public static final double DEFAULT_NEAR_METRES = 1;

    public PanoramaRequest {
        TileSelection.checkCoordinates(latDeg, lonDeg);
        pixelsPerDegree = dempano.panorama.PanoramaGeometry.checkedPixelsPerDegree(pixelsPerDegree);
        if (!(Math.abs(offsetMetres) < 1e6)) {
            throw new IllegalArgumentException("offset must be a number of metres within ±1e6, got " + offsetMetres);
        }
        if (!Double.isNaN(altitudeMetres) && !(Math.abs(altitudeMetres) < 1e6)) {
            throw new IllegalArgumentException("altitude must be a number of metres within ±1e6 (above sea level), got " + altitudeMetres);
        }
        if (!(eyeHeightMetres >= 0 && eyeHeightMetres < 1e6)) {
            throw new IllegalArgumentException("eye height must be a number of metres in [0, 1e6), got " + eyeHeightMetres);
        }
        if (!(rangeMetres >= 100 && rangeMetres <= TileSelection.MAX_RANGE_METRES)) {
            throw new IllegalArgumentException("range must be between 0.1 and " + TileSelection.MAX_RANGE_METRES / 1000
                    + " km, got " + rangeMetres / 1000 + " km");
        }
        if (!(lodErrorPx >= 0 && lodErrorPx <= 100)) {
            throw new IllegalArgumentException("level-of-detail error bound must be in [0, 100] pixels, got " + lodErrorPx);
        }
        if (!(nearMetres > 0 && nearMetres < 1000)) {
            throw new IllegalArgumentException("near plane must be in (0, 1000) metres, got " + nearMetres);
        }
        checkRadius(snapToSummitMetres, "snap-to-summit radius");
        checkRadius(clearViewMetres, "clear-view radius");
        layers = Set.copyOf(layers);
        if (!colour && !distance) {
            throw new IllegalArgumentException("nothing to render: both colour and distance are switched off");
        }
        if (!distance && !layers.isEmpty()) {
            throw new IllegalArgumentException("layers " + layers + " are computed from distances: they need the distance map");
        }
        java.util.Objects.requireNonNull(elevationRange);
        java.util.Objects.requireNonNull(refraction);
        java.util.Objects.requireNonNull(depthMode);
        java.util.Objects.requireNonNull(missingTiles);
        // Validates ppd, views and supersampling with clear messages.
        ViewLayout.forPanorama(dempano.panorama.PanoramaGeometry.of(pixelsPerDegree, elevationRange.bottomDeg(),
                elevationRange.topDeg()), views, supersampling);
    }

    /** A request with every default at a coordinate. */
    public static PanoramaRequest at(double latDeg, double lonDeg) {
        return new PanoramaRequest(latDeg, lonDeg, 0, Double.NaN, Viewpoint.DEFAULT_EYE_HEIGHT_METRES,
                DEFAULT_RANGE_METRES, DEFAULT_PIXELS_PER_DEGREE, ElevationRange.DEFAULT, Refraction.STANDARD,
                DepthMode.SHADER_RANGE, EnumSet.noneOf(Layer.class), DEFAULT_NEAR_METRES, 1, ViewLayout.DEFAULT_VIEWS,
                MissingTilePolicy.AUTO, dempano.terrain.LevelOfDetail.DEFAULT_MAX_ERROR_PX, true, true, Double.NaN, Double.NaN, true);
    }

    public PanoramaRequest withOffsetMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, v, altitudeMetres, eyeHeightMetres, rangeMetres, pixelsPerDegree,
                elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withAltitudeMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, v, eyeHeightMetres, rangeMetres, pixelsPerDegree,
                elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withEyeHeightMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, v, rangeMetres, pixelsPerDegree,
                elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withRangeMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, v, pixelsPerDegree,
                elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withPixelsPerDegree(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres, v,
                elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withElevationRange(ElevationRange v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, v, refraction, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withRefraction(Refraction v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, v, depthMode, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withDepthMode(DepthMode v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, v, layers, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withLayers(Set<Layer> v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, v, nearMetres, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withNearMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, v, supersampling, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withSupersampling(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, v, views, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withViews(int v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, v, missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withMissingTiles(MissingTilePolicy v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views, v, lodErrorPx, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withLodErrorPx(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views,
                missingTiles, v, colour, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    public PanoramaRequest withColour(boolean v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views,
                missingTiles, lodErrorPx, v, distance, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    /** Whether to compute the distance map; false = colour only (see the record's Javadoc). */
    public PanoramaRequest withDistance(boolean v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views,
                missingTiles, lodErrorPx, colour, v, snapToSummitMetres, clearViewMetres, exactDistances);
    }

    /** Snap the viewpoint to the highest DEM sample within this radius, metres; NaN = off (see the record's Javadoc). */
    public PanoramaRequest withSnapToSummitMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views,
                missingTiles, lodErrorPx, colour, distance, v, clearViewMetres, exactDistances);
    }

    /** Raise the eye above all terrain within this radius, metres; NaN = off (see the record's Javadoc). */
    public PanoramaRequest withClearViewMetres(double v) {
        return new PanoramaRequest(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, rangeMetres,
                pixelsPerDegree, elevationRange, refraction, depthMode, layers, nearMetres, supersampling, views,
                missingTiles, lodErrorPx, colour, distance, snapToSummitMetres, v, exactDistances);
    }

    private static void checkRadius(double radiusMetres, String what) {
        if (!Double.isNaN(radiusMetres)
                && !(radiusMetres > 0 && radiusMetres <= dempano.geo.ViewpointAdjustment.MAX_RADIUS_METRES)) {
            throw new IllegalArgumentException(what + " must be in (0, "
                    + (long) dempano.geo.ViewpointAdjustment.MAX_RADIUS_METRES + "] metres, got " + radiusMetres);
        }
    }

    /**
     * Exact per-pixel distances: each pixel's distance measured along its own centre ray against the
     * triangles the views saw, the terrain probed where none is met (see {@link dempano.panorama.Stitcher}).
     * On by default. Off, distances interpolate the views' inverse depth: faster (about 0.5 s less per
     * 7200 × 1200 panorama on 2 cores), exact on planes, but tens of per cent off at grazing incidence
     * and at silhouettes, where a pixel takes a neighbouring sample's ray.
     */
    public PanoramaRequest withExactDistances(boolean v) {
        PanoramaRequest r = this;
        return new PanoramaRequest(r.latDeg, r.lonDeg, r.offsetMetres, r.altitudeMetres, r.eyeHeightMetres, r.rangeMetres,
                r.pixelsPerDegree, r.elevationRange, r.refraction, r.depthMode, r.layers, r.nearMetres, r.supersampling,
                r.views, r.missingTiles, r.lodErrorPx, r.colour, r.distance, r.snapToSummitMetres, r.clearViewMetres, v);
    }
}
