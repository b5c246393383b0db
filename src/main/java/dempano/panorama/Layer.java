package dempano.panorama;

/** Optional per-pixel layers besides colour and distance. Each is float32; NaN where the sky is seen. */
public enum Layer {
    /** Terrain elevation of the point seen, metres above sea level (refraction lift removed). */
    ELEVATION("elevation"),
    /** Latitude of the point seen, degrees. */
    LATITUDE("latitude"),
    /** Longitude of the point seen, degrees in [-180, 180). */
    LONGITUDE("longitude"),
    /** Geodesic distance on WGS84 from the viewpoint to the point seen, metres. */
    GROUND_DISTANCE("ground-distance"),
    /**
     * Angle between the ray and the tangent plane of the terrain seen, degrees in [0, 90]: 90 looking
     * straight down on flat ground, near 0 at grazing incidence (sea and plain horizons, slopes seen
     * edge-on). The surface is the drawn DEM triangle at the point seen, with earth curvature and the
     * refraction lift's slope.
     */
    INCIDENCE("incidence"),
    /**
     * Estimated error of the distance, metres, from the DEM's vertical error: 10 m (SRTM's relative
     * vertical accuracy, 90 % linear error) divided by the sine of {@link #INCIDENCE}, capped at the
     * distance itself; a 90 % figure like the DEM's. Excludes horizontal DEM error, refraction
     * uncertainty and the renderer's own geometric error.
     */
    UNCERTAINTY("uncertainty");

    private final String fileName;

    Layer(String fileName) {
        this.fileName = fileName;
    }

    /** Name used in options and file names ({@code P-<name>.npy}). */
    public String fileName() {
        return fileName;
    }

    public static Layer fromName(String s) {
        for (Layer l : values()) {
            if (l.fileName.equalsIgnoreCase(s) || l.name().equalsIgnoreCase(s)) {
                return l;
            }
        }
        throw new IllegalArgumentException("unknown layer '" + s + "' (use elevation, latitude, longitude, ground-distance, incidence, uncertainty)");
    }
}
