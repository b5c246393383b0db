package dempano.dem;

import java.util.Objects;

/**
 * What one source gave to one tile: where a tile's heights came from when several sources are
 * combined ({@link PriorityDem}), and the vertical datum they refer to.
 *
 * @param source        the file (or description) that served the samples
 * @param verticalDatum the heights' vertical datum: {@code EGM96} (SRTM), {@code EGM2008}
 *                      (Copernicus), {@code EPSG:nnnn} from a GeoTIFF's vertical CS key, or
 *                      {@code unknown}
 * @param samples       how many of the tile's samples this source served (valid samples, not voids
 *                      interpolated afterwards); ≥ 0
 */
public record DemContribution(String source, String verticalDatum, long samples) {
    /** Vertical datum of SRTM heights (.hgt). */
    public static final String EGM96 = "EGM96";
    /** Vertical datum of Copernicus DEM heights. */
    public static final String EGM2008 = "EGM2008";
    /** No vertical datum known. */
    public static final String UNKNOWN = "unknown";

    public DemContribution {
        Objects.requireNonNull(source);
        Objects.requireNonNull(verticalDatum);
        if (samples < 0) {
            throw new IllegalArgumentException("negative sample count " + samples);
        }
    }
}
