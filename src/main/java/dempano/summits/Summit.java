package dempano.summits;

/**
 * A named summit from a survey list.
 *
 * @param name            as the list spells it
 * @param latDeg          latitude, degrees, −90…90
 * @param lonDeg          longitude, degrees, −180…180
 * @param elevationMetres surveyed height above sea level, metres (NaN when the list gives none)
 */
public record Summit(String name, double latDeg, double lonDeg, double elevationMetres) {
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
    }
}
