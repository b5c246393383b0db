package dempano.panorama;

/**
 * The terrain itself, asked along one ray: where the {@link Stitcher}'s candidates fail (the
 * triangle a pixel centre's ray meets was too small, seen at grazing incidence, for any view sample
 * to see it), it finds the ray's first crossing with the surface by search.
 */
@FunctionalInterface
public interface RayProbe {
    /**
     * The distance along a unit ray from the eye to where it first goes below the terrain, searched
     * outward from {@code fromMetres} to {@code toMetres}, without stepping over a crest: a
     * crest behind a nearer one is where the candidates most often fail.
     *
     * @param dx         ray direction, unit length, in the eye's frame (jME axes: east, up, south)
     * @param fromMetres a distance at which the ray is expected above the terrain (searched from
     *                   nearer the eye when it is not)
     * @param toMetres   how far to search
     * @return the distance, metres; +∞ when the ray stays above the terrain out to the range of sight
     *         (or leaves the DEM); NaN when it stays above out to {@code toMetres} only (undecided)
     */
    double firstHitMetres(double dx, double dy, double dz, double fromMetres, double toMetres);

    /**
     * The nearest crossing of the ray with the full-resolution surface between two distances, by intersecting
     * the surface's triangles over that stretch only: no search from nearer, so a crossing before
     * {@code fromMetres} is not looked for. Cheap where the stretch is short.
     *
     * @return the distance, metres; NaN when the ray meets no triangle there, or the stretch is not tried
     *         (too long, off the DEM); this default tries none
     */
    default double nearestHitBetweenMetres(double dx, double dy, double dz, double fromMetres, double toMetres) {
        return Double.NaN;
    }
}
