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
    GROUND_DISTANCE("ground-distance");

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
        throw new IllegalArgumentException("unknown layer '" + s + "' (use elevation, latitude, longitude, ground-distance)");
    }
}
