package dempano.summits;

/**
 * A named summit from a survey list.
 *
 * @param name            as the list spells it
 * @param latDeg          latitude, degrees, −90…90
 * @param lonDeg          longitude, degrees, −180…180
 * @param elevationMetres surveyed height above sea level, metres (NaN when the list gives none and it is not
 *                        placed on the DEM)
 * @param elevationFromDem true when the list gave no height and {@code elevationMetres} is the DEM's height at the
 *                        summit's position ({@link SummitProjector#placedOnDem}): an SRTM height, some 40 m below
 *                        a surveyed one on valid data, so the summit is drawn a little low rather than not at all
 */
public record Summit(String name, double latDeg, double lonDeg, double elevationMetres, boolean elevationFromDem) {
    /** A summit as a list gives it: its elevation (or NaN) is the list's own. */
    public Summit(String name, double latDeg, double lonDeg, double elevationMetres) {
        this(name, latDeg, lonDeg, elevationMetres, false);
    }

    public Summit {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("summit without a name");
        }
        if (!(latDeg >= -90 && latDeg <= 90) || !(lonDeg >= -180 && lonDeg <= 180)) {
            throw new IllegalArgumentException("summit " + name + ": coordinates out of range: " + latDeg + ", " + lonDeg);
        }
        if (!Double.isNaN(elevationMetres) && !(elevationMetres > -500 && elevationMetres < 9000)) {
            throw new IllegalArgumentException("summit " + name + ": implausible elevation " + elevationMetres + " m");
        }
        if (elevationFromDem && Double.isNaN(elevationMetres)) {
            throw new IllegalArgumentException("summit " + name + ": an elevation from the DEM must be a number");
        }
    }
}
