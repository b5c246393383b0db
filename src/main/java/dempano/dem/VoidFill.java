package dempano.dem;

import java.util.Locale;

/**
 * How voids (samples a DEM has no height for) are filled after the sources in priority have given
 * what they have. All fills are deterministic, keep every valid sample unchanged and interpolate
 * only the voids; a tile without any valid sample becomes sea level (0 m) whatever the method.
 * Compared against surveyed summits in {@code docs/void-fill.md} ({@code gradle voidFillReport}).
 */
public enum VoidFill {
    /**
     * Inverse-distance weighting of the nearest valid sample along each of eight directions (as
     * GDAL's FillNodata): quick, but a void over a summit becomes a bowl-shaped average of its rim, far
     * below the summit (the fill before the thin-plate default).
     */
    IDW,
    /**
     * Harmonic (Laplace, "diffusion") fill: the smoothest membrane over the void, each filled sample
     * the mean of its four neighbours. Planes are restored exactly in voids away from the tile border;
     * no filled sample rises above the void's highest rim sample (maximum principle), so summits come
     * out low.
     */
    LAPLACE,
    /**
     * Thin-plate fill with slight tension: minimises the squared Laplacian (bending) of the surface
     * plus {@link SplineVoidFill#THIN_PLATE_TENSION} times its squared slope, so the slopes around a
     * void are carried on into it: a summit the rim rises towards is rebuilt as a dome above the rim.
     * Planes are restored exactly in voids away from the tile border. A void touching the tile border
     * (valid samples on one side only, where bending would extrapolate without bound) gets the
     * {@link #LAPLACE} fill instead. The default (best on surveyed summits in voids, see
     * docs/void-fill.md).
     */
    THIN_PLATE;

    /** The fill used unless another is asked for. */
    public static final VoidFill DEFAULT = THIN_PLATE;

    /** The name on the command line: {@code idw}, {@code laplace}, {@code thin-plate}. */
    public String cliName() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /**
     * The fill named on the command line (case-insensitive, '-' or '_').
     *
     * @throws IllegalArgumentException naming the accepted names
     */
    public static VoidFill parse(String name) {
        for (VoidFill f : values()) {
            if (f.cliName().equalsIgnoreCase(name.trim().replace('_', '-'))) {
                return f;
            }
        }
        throw new IllegalArgumentException("unknown void fill '" + name + "' (expected idw, laplace or thin-plate)");
    }

    /**
     * Fills the NaN samples of a square grid in place (row-major, {@code n × n}).
     *
     * @return what was found: void count, regions, largest region
     */
    public VoidReport fill(float[] heightsMetres, int n) {
        return VoidFiller.fill(heightsMetres, n, this);
    }
}
