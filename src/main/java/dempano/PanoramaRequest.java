package dempano;

import dempano.dem.MissingTilePolicy;
import dempano.dem.TileSelection;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import dempano.panorama.DepthMode;
import dempano.panorama.ElevationRange;
import dempano.panorama.Layer;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.ViewLayout;
import dempano.terrain.LevelOfDetail;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

/**
 * What to render: where the eye stands ({@link Standpoint}), what the panorama covers ({@link Coverage}), how the GL
 * path draws its views ({@link ViewSettings}) and what it computes ({@link Products}). Start from
 * {@link #at(double, double)} (all defaults) and adjust with the {@code with…} methods; every value is also read
 * directly ({@link #latDeg()}, {@link #rangeMetres()}, …). Immutable; every value is checked when the request is made,
 * each group on its own and then what one group asks of another (layers need distances; the views must fit the
 * panorama's grid).
 *
 * @param standpoint where the eye stands
 * @param coverage   what the panorama covers, at which resolution, over which data
 * @param viewSettings how the GL path draws the panorama's views (the CPU reference casts every pixel's ray: it uses none)
 * @param products   what is computed
 */
public record PanoramaRequest(Standpoint standpoint, Coverage coverage, ViewSettings viewSettings, Products products) {
    public static final double DEFAULT_RANGE_METRES = 100_000;
    public static final double DEFAULT_PIXELS_PER_DEGREE = 20;
    public static final double DEFAULT_NEAR_METRES = 1;

    /**
     * Where the eye stands.
     *
     * @param latDeg             viewpoint latitude, degrees [-90, 90]
     * @param lonDeg             viewpoint longitude, degrees [-180, 180]
     * @param offsetMetres       signed correction to the DEM height at the viewpoint, within ±1e6 (default 0)
     * @param altitudeMetres     absolute standing altitude, metres above sea level within ±1e6; NaN (default) = from
     *                           the DEM
     * @param eyeHeightMetres    eye above the standing altitude, [0, 1e6) (default 2 m)
     * @param snapToSummitMetres radius, metres, within which the viewpoint moves to the highest DEM sample
     *                           ({@link dempano.geo.ViewpointAdjustment#highestWithin}); NaN (default) = stay
     * @param clearViewMetres    radius, metres, within which no terrain may rise above the eye's horizontal: the eye is
     *                           raised as far as needed ({@link dempano.geo.ViewpointAdjustment#clearViewEyeAltitudeMetres});
     *                           NaN (default) = no lift
     */
    public record Standpoint(double latDeg, double lonDeg, double offsetMetres, double altitudeMetres,
                             double eyeHeightMetres, double snapToSummitMetres, double clearViewMetres) {
        public Standpoint {
            TileSelection.checkCoordinates(latDeg, lonDeg);
            if (!(Math.abs(offsetMetres) < 1e6)) {
                throw new IllegalArgumentException("offset must be a number of metres within ±1e6, got " + offsetMetres);
            }
            if (!Double.isNaN(altitudeMetres) && !(Math.abs(altitudeMetres) < 1e6)) {
                throw new IllegalArgumentException("altitude must be a number of metres within ±1e6 (above sea level), got " + altitudeMetres);
            }
            if (!(eyeHeightMetres >= 0 && eyeHeightMetres < 1e6)) {
                throw new IllegalArgumentException("eye height must be a number of metres in [0, 1e6), got " + eyeHeightMetres);
            }
            checkRadius(snapToSummitMetres, "snap-to-summit radius");
            checkRadius(clearViewMetres, "clear-view radius");
        }

        /** The default standpoint at a coordinate: on the DEM, the eye 2 m up, not moved. */
        public static Standpoint at(double latDeg, double lonDeg) {
            return new Standpoint(latDeg, lonDeg, 0, Double.NaN, Viewpoint.DEFAULT_EYE_HEIGHT_METRES, Double.NaN, Double.NaN);
        }

        /** This standpoint at another coordinate, everything else kept. */
        public Standpoint movedTo(double latDeg, double lonDeg) {
            return new Standpoint(latDeg, lonDeg, offsetMetres, altitudeMetres, eyeHeightMetres, snapToSummitMetres, clearViewMetres);
        }

        private static void checkRadius(double radiusMetres, String what) {
            if (!Double.isNaN(radiusMetres)
                    && !(radiusMetres > 0 && radiusMetres <= dempano.geo.ViewpointAdjustment.MAX_RADIUS_METRES)) {
                throw new IllegalArgumentException(what + " must be in (0, "
                        + (long) dempano.geo.ViewpointAdjustment.MAX_RADIUS_METRES + "] metres, got " + radiusMetres);
            }
        }
    }

    /**
     * What the panorama covers.
     *
     * @param rangeMetres     range of sight, metres [100, {@link TileSelection#MAX_RANGE_METRES}] (default 100 km)
     * @param pixelsPerDegree panorama resolution, pixels per degree in (0, 200] with 360·ppd a whole number (default
     *                        20); normalized as {@link PanoramaGeometry#checkedPixelsPerDegree}, so the request and the
     *                        panorama's geometry hold the same value
     * @param elevationRange  elevation angles covered (default -30°:30°)
     * @param refraction      refraction coefficient (default k = 0.13)
     * @param missingTiles    what a missing tile means (default {@link MissingTilePolicy#AUTO}: sea beside data, an
     *                        error for no data at all or none under the viewpoint without an altitude)
     */
    public record Coverage(double rangeMetres, double pixelsPerDegree, ElevationRange elevationRange,
                           Refraction refraction, MissingTilePolicy missingTiles) {
        public static final Coverage DEFAULT = new Coverage(DEFAULT_RANGE_METRES, DEFAULT_PIXELS_PER_DEGREE,
                ElevationRange.DEFAULT, Refraction.STANDARD, MissingTilePolicy.AUTO);

        public Coverage {
            pixelsPerDegree = PanoramaGeometry.checkedPixelsPerDegree(pixelsPerDegree);
            if (!(rangeMetres >= 100 && rangeMetres <= TileSelection.MAX_RANGE_METRES)) {
                throw new IllegalArgumentException("range must be between 0.1 and " + TileSelection.MAX_RANGE_METRES / 1000
                        + " km, got " + rangeMetres / 1000 + " km");
            }
            Objects.requireNonNull(elevationRange, "elevationRange");
            Objects.requireNonNull(refraction, "refraction");
            Objects.requireNonNull(missingTiles, "missingTiles");
        }
    }

    /**
     * How the GL path draws the panorama's views.
     *
     * @param depthMode     how distances are read from the views (default {@link DepthMode#SHADER_RANGE})
     * @param nearMetres    near plane, metres in (0, 1000) (default 1 m; an upper bound, lowered where terrain comes
     *                      nearer)
     * @param supersampling view pixels per panorama pixel, linear (default 1)
     * @param views         perspective views (default 8)
     * @param lodErrorPx    bound on the screen error of simplified distant terrain, panorama pixels, [0, 100] (default
     *                      {@link LevelOfDetail#DEFAULT_MAX_ERROR_PX}; 0 = full resolution everywhere)
     */
    public record ViewSettings(DepthMode depthMode, double nearMetres, double supersampling, int views,
                               double lodErrorPx) {
        public static final ViewSettings DEFAULT = new ViewSettings(DepthMode.SHADER_RANGE, DEFAULT_NEAR_METRES, 1,
                ViewLayout.DEFAULT_VIEWS, LevelOfDetail.DEFAULT_MAX_ERROR_PX);

        public ViewSettings {
            Objects.requireNonNull(depthMode, "depthMode");
            if (!(lodErrorPx >= 0 && lodErrorPx <= 100)) {
                throw new IllegalArgumentException("level-of-detail error bound must be in [0, 100] pixels, got " + lodErrorPx);
            }
            if (!(nearMetres > 0 && nearMetres < 1000)) {
                throw new IllegalArgumentException("near plane must be in (0, 1000) metres, got " + nearMetres);
            }
        }
    }

    /**
     * What is computed.
     *
     * @param colour         the colour image (default true); false renders distances only, skipping colour shading,
     *                       read-back and stitching
     * @param distance       the distance map (default true); false renders colour only, skipping depth linearization
     *                       and the distance interpolation (the silhouette lines and an auto elevation range then use
     *                       the nearest view sample's range). Layers and summits need distances.
     * @param exactDistances each pixel's distance along its own centre ray (default true; see
     *                       {@link PanoramaRequest#withExactDistances})
     * @param layers         extra per-pixel layers (default none)
     */
    public record Products(boolean colour, boolean distance, boolean exactDistances, Set<Layer> layers) {
        public static final Products DEFAULT = new Products(true, true, true, EnumSet.noneOf(Layer.class));

        public Products {
            layers = Set.copyOf(Objects.requireNonNull(layers, "layers"));
            if (!colour && !distance) {
                throw new IllegalArgumentException("nothing to render: both colour and distance are switched off");
            }
            if (!distance && !layers.isEmpty()) {
                throw new IllegalArgumentException("layers " + layers + " are computed from distances: they need the distance map");
            }
        }
    }

    public PanoramaRequest {
        Objects.requireNonNull(standpoint, "standpoint");
        Objects.requireNonNull(coverage, "coverage");
        Objects.requireNonNull(viewSettings, "viewSettings");
        Objects.requireNonNull(products, "products");
        // Validates ppd, the number of views and supersampling together, with clear messages.
        ViewLayout.forPanorama(PanoramaGeometry.of(coverage.pixelsPerDegree(), coverage.elevationRange().bottomDeg(),
                coverage.elevationRange().topDeg()), viewSettings.views(), viewSettings.supersampling());
    }

    /** A request with every default at a coordinate. */
    public static PanoramaRequest at(double latDeg, double lonDeg) {
        return new PanoramaRequest(Standpoint.at(latDeg, lonDeg), Coverage.DEFAULT, ViewSettings.DEFAULT, Products.DEFAULT);
    }

    // The values, read directly.

    public double latDeg() {
        return standpoint.latDeg();
    }

    public double lonDeg() {
        return standpoint.lonDeg();
    }

    public double offsetMetres() {
        return standpoint.offsetMetres();
    }

    public double altitudeMetres() {
        return standpoint.altitudeMetres();
    }

    public double eyeHeightMetres() {
        return standpoint.eyeHeightMetres();
    }

    public double snapToSummitMetres() {
        return standpoint.snapToSummitMetres();
    }

    public double clearViewMetres() {
        return standpoint.clearViewMetres();
    }

    public double rangeMetres() {
        return coverage.rangeMetres();
    }

    public double pixelsPerDegree() {
        return coverage.pixelsPerDegree();
    }

    public ElevationRange elevationRange() {
        return coverage.elevationRange();
    }

    public Refraction refraction() {
        return coverage.refraction();
    }

    public MissingTilePolicy missingTiles() {
        return coverage.missingTiles();
    }

    public DepthMode depthMode() {
        return viewSettings.depthMode();
    }

    public double nearMetres() {
        return viewSettings.nearMetres();
    }

    public double supersampling() {
        return viewSettings.supersampling();
    }

    public int views() {
        return viewSettings.views();
    }

    public double lodErrorPx() {
        return viewSettings.lodErrorPx();
    }

    public boolean colour() {
        return products.colour();
    }

    public boolean distance() {
        return products.distance();
    }

    public boolean exactDistances() {
        return products.exactDistances();
    }

    public Set<Layer> layers() {
        return products.layers();
    }

    // Whole groups.

    public PanoramaRequest withStandpoint(Standpoint v) {
        return new PanoramaRequest(v, coverage, viewSettings, products);
    }

    public PanoramaRequest withCoverage(Coverage v) {
        return new PanoramaRequest(standpoint, v, viewSettings, products);
    }

    public PanoramaRequest withViewSettings(ViewSettings v) {
        return new PanoramaRequest(standpoint, coverage, v, products);
    }

    public PanoramaRequest withProducts(Products v) {
        return new PanoramaRequest(standpoint, coverage, viewSettings, v);
    }

    /** This request at another coordinate: everything else, the standpoint's offset, altitude and eye height too, kept. */
    public PanoramaRequest movedTo(double latDeg, double lonDeg) {
        return withStandpoint(standpoint.movedTo(latDeg, lonDeg));
    }

    // Single values.

    public PanoramaRequest withOffsetMetres(double v) {
        Standpoint s = standpoint;
        return withStandpoint(new Standpoint(s.latDeg(), s.lonDeg(), v, s.altitudeMetres(), s.eyeHeightMetres(),
                s.snapToSummitMetres(), s.clearViewMetres()));
    }

    public PanoramaRequest withAltitudeMetres(double v) {
        Standpoint s = standpoint;
        return withStandpoint(new Standpoint(s.latDeg(), s.lonDeg(), s.offsetMetres(), v, s.eyeHeightMetres(),
                s.snapToSummitMetres(), s.clearViewMetres()));
    }

    public PanoramaRequest withEyeHeightMetres(double v) {
        Standpoint s = standpoint;
        return withStandpoint(new Standpoint(s.latDeg(), s.lonDeg(), s.offsetMetres(), s.altitudeMetres(), v,
                s.snapToSummitMetres(), s.clearViewMetres()));
    }

    /** Snap the viewpoint to the highest DEM sample within this radius, metres; NaN = off (see {@link Standpoint}). */
    public PanoramaRequest withSnapToSummitMetres(double v) {
        Standpoint s = standpoint;
        return withStandpoint(new Standpoint(s.latDeg(), s.lonDeg(), s.offsetMetres(), s.altitudeMetres(),
                s.eyeHeightMetres(), v, s.clearViewMetres()));
    }

    /** Raise the eye above all terrain within this radius, metres; NaN = off (see {@link Standpoint}). */
    public PanoramaRequest withClearViewMetres(double v) {
        Standpoint s = standpoint;
        return withStandpoint(new Standpoint(s.latDeg(), s.lonDeg(), s.offsetMetres(), s.altitudeMetres(),
                s.eyeHeightMetres(), s.snapToSummitMetres(), v));
    }

    public PanoramaRequest withRangeMetres(double v) {
        Coverage c = coverage;
        return withCoverage(new Coverage(v, c.pixelsPerDegree(), c.elevationRange(), c.refraction(), c.missingTiles()));
    }

    public PanoramaRequest withPixelsPerDegree(double v) {
        Coverage c = coverage;
        return withCoverage(new Coverage(c.rangeMetres(), v, c.elevationRange(), c.refraction(), c.missingTiles()));
    }

    public PanoramaRequest withElevationRange(ElevationRange v) {
        Coverage c = coverage;
        return withCoverage(new Coverage(c.rangeMetres(), c.pixelsPerDegree(), v, c.refraction(), c.missingTiles()));
    }

    public PanoramaRequest withRefraction(Refraction v) {
        Coverage c = coverage;
        return withCoverage(new Coverage(c.rangeMetres(), c.pixelsPerDegree(), c.elevationRange(), v, c.missingTiles()));
    }

    public PanoramaRequest withMissingTiles(MissingTilePolicy v) {
        Coverage c = coverage;
        return withCoverage(new Coverage(c.rangeMetres(), c.pixelsPerDegree(), c.elevationRange(), c.refraction(), v));
    }

    public PanoramaRequest withDepthMode(DepthMode v) {
        ViewSettings s = viewSettings;
        return withViewSettings(new ViewSettings(v, s.nearMetres(), s.supersampling(), s.views(), s.lodErrorPx()));
    }

    public PanoramaRequest withNearMetres(double v) {
        ViewSettings s = viewSettings;
        return withViewSettings(new ViewSettings(s.depthMode(), v, s.supersampling(), s.views(), s.lodErrorPx()));
    }

    public PanoramaRequest withSupersampling(double v) {
        ViewSettings s = viewSettings;
        return withViewSettings(new ViewSettings(s.depthMode(), s.nearMetres(), v, s.views(), s.lodErrorPx()));
    }

    public PanoramaRequest withViews(int v) {
        ViewSettings s = viewSettings;
        return withViewSettings(new ViewSettings(s.depthMode(), s.nearMetres(), s.supersampling(), v, s.lodErrorPx()));
    }

    public PanoramaRequest withLodErrorPx(double v) {
        ViewSettings s = viewSettings;
        return withViewSettings(new ViewSettings(s.depthMode(), s.nearMetres(), s.supersampling(), s.views(), v));
    }

    public PanoramaRequest withColour(boolean v) {
        Products p = products;
        return withProducts(new Products(v, p.distance(), p.exactDistances(), p.layers()));
    }

    /** Whether to compute the distance map; false = colour only (see {@link Products}). */
    public PanoramaRequest withDistance(boolean v) {
        Products p = products;
        return withProducts(new Products(p.colour(), v, p.exactDistances(), p.layers()));
    }

    /**
     * Exact per-pixel distances: each pixel's distance measured along its own centre ray against the
     * triangles the views saw, the terrain probed where none is met (see {@link dempano.panorama.Stitcher}).
     * On by default. Off, distances interpolate the views' inverse depth: faster (about 0.5 s less per
     * 7200 × 1200 panorama on 2 cores), exact on planes, but tens of per cent off at grazing incidence
     * and at silhouettes, where a pixel takes a neighbouring sample's ray.
     */
    public PanoramaRequest withExactDistances(boolean v) {
        Products p = products;
        return withProducts(new Products(p.colour(), p.distance(), v, p.layers()));
    }

    public PanoramaRequest withLayers(Set<Layer> v) {
        Products p = products;
        return withProducts(new Products(p.colour(), p.distance(), p.exactDistances(), v));
    }
}
