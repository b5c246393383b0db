package dempano.geo;

import dempano.dem.Mosaic;
import dempano.dem.TileSelection;
import java.util.Locale;

/**
 * Where the eye is. The standing altitude is either the DEM's height at the coordinate plus a signed
 * offset (the thesis's altitude correction, e.g. to step onto a ridge the 90 m DEM rounds off) or an
 * explicit absolute altitude; the eye is {@code eyeHeightMetres} above the standing altitude.
 *
 * @param latDeg                 latitude, degrees, [-90, 90]
 * @param lonDeg                 longitude, degrees, [-180, 180]
 * @param groundElevationMetres  DEM height at the coordinate (the drawn surface's, {@link Mosaic#heightAt}), metres above sea level
 * @param offsetMetres           signed correction added to the DEM height; NaN when an absolute altitude was given
 * @param standingAltitudeMetres ground the observer stands on, metres above sea level
 * @param eyeHeightMetres        eye above the standing altitude, metres (≥ 0)
 */
public record Viewpoint(double latDeg, double lonDeg, double groundElevationMetres, double offsetMetres,
                        double standingAltitudeMetres, double eyeHeightMetres) {
    /** A standing person's eye, metres. */
    public static final double DEFAULT_EYE_HEIGHT_METRES = 2.0;

    public Viewpoint {
        TileSelection.checkCoordinates(latDeg, lonDeg);
        if (!Double.isFinite(standingAltitudeMetres) || !(eyeHeightMetres >= 0 && eyeHeightMetres < 1e6)) {
            throw new IllegalArgumentException("bad viewpoint altitude: standing " + standingAltitudeMetres
                    + " m, eye height " + eyeHeightMetres + " m");
        }
        // An eye inside the terrain would see the landscape through the back of the surface, one on it would see the
        // ground under it at no distance (at 0 m the GL views showed sky or terrain 30 km off where the CPU reference
        // met the ground at its feet; at 0.01 m 254 pixels looking down were sky): refuse.
        double eye = standingAltitudeMetres + eyeHeightMetres;
        if (eye < groundElevationMetres) {
            throw new EyeBelowGroundException(String.format(Locale.ROOT,
                    "the eye (%.1f m) would be %.1f m below the DEM surface (%.1f m) at %.6f, %.6f: raise the offset"
                            + " or the altitude", eye, groundElevationMetres - eye, groundElevationMetres, latDeg, lonDeg));
        }
        if (eye < groundElevationMetres + MIN_EYE_CLEARANCE_METRES) {
            throw new EyeBelowGroundException(String.format(Locale.ROOT,
                    "the eye (%.2f m) would be only %.2f m above the DEM surface (%.2f m) at %.6f, %.6f, where the"
                            + " ground under it cannot be drawn: at least %.1f m is needed; raise the eye height, the"
                            + " offset or the altitude", eye, eye - groundElevationMetres, groundElevationMetres, latDeg,
                    lonDeg, MIN_EYE_CLEARANCE_METRES));
        }
    }

    /**
     * How far above the DEM's drawn surface ({@link Mosaic#heightAt}) the eye must be, metres: nearer, the views' near
     * plane (a centimetre at the least) cuts the ground under the eye away.
     */
    public static final double MIN_EYE_CLEARANCE_METRES = 0.1;

    /** Standing on the DEM at the coordinate, corrected by {@code offsetMetres}. */
    public static Viewpoint onDem(Mosaic mosaic, double latDeg, double lonDeg, double offsetMetres,
                                  double eyeHeightMetres) {
        TileSelection.checkCoordinates(latDeg, lonDeg);
        if (!Double.isFinite(offsetMetres)) {
            throw new IllegalArgumentException("altitude offset must be a finite number of metres, got " + offsetMetres);
        }
        double ground = groundAt(mosaic, latDeg, lonDeg);
        return new Viewpoint(latDeg, lonDeg, ground, offsetMetres, ground + offsetMetres, eyeHeightMetres);
    }

    /** Standing at an explicit altitude (metres above sea level) at the coordinate. */
    public static Viewpoint atAltitude(Mosaic mosaic, double latDeg, double lonDeg, double altitudeMetres,
                                       double eyeHeightMetres) {
        TileSelection.checkCoordinates(latDeg, lonDeg);
        if (!Double.isFinite(altitudeMetres) || Math.abs(altitudeMetres) > 1e6) {
            throw new IllegalArgumentException("altitude must be a number of metres within ±1e6 (above sea level), got " + altitudeMetres);
        }
        return new Viewpoint(latDeg, lonDeg, groundAt(mosaic, latDeg, lonDeg), Double.NaN, altitudeMetres,
                eyeHeightMetres);
    }

    /** The DEM's height at a point (its drawn surface's), metres; an error naming the point where the mosaic has none. */
    static double groundAt(Mosaic mosaic, double latDeg, double lonDeg) {
        double h = mosaic.heightAt(latDeg, lonDeg);
        if (Double.isNaN(h)) {
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "the DEM mosaic has no height at %.6f, %.6f", latDeg, lonDeg));
        }
        return h;
    }

    /**
     * A warning when the ground under the viewpoint (one of the four DEM samples its height is interpolated from) is a
     * void the DEM had no height for, filled by interpolation, and the eye's altitude was taken from it (no absolute
     * altitude given): that altitude is then invented, and may be hundreds of metres off (a summit in a void).
     */
    public java.util.Optional<String> filledVoidWarning(Mosaic mosaic) {
        if (Double.isNaN(offsetMetres)) {
            return java.util.Optional.empty(); // an absolute altitude: the DEM's height is not the eye's
        }
        int r = (int) Math.floor(mosaic.rowOf(latDeg)), c = (int) Math.floor(mosaic.colOf(lonDeg));
        for (int k = 0; k < 4; k++) {
            if ((mosaic.flags(r + (k >> 1), c + (k & 1)) & Mosaic.FLAG_FILLED_VOID) != 0) {
                return java.util.Optional.of(String.format(Locale.ROOT, "the viewpoint stands in a void of the DEM, filled by "
                        + "interpolation: its ground (%.1f m), and the eye's altitude from it, are invented; give the altitude "
                        + "(--altitude-m), or a DEM with data there (another --dem-dir after this one)", groundElevationMetres));
            }
        }
        return java.util.Optional.empty();
    }

    /** The eye's altitude, metres: standing altitude plus eye height. */
    public double eyeAltitudeMetres() {
        return standingAltitudeMetres + eyeHeightMetres;
    }

    /** The local east-north-up frame with its origin at the eye. */
    public LocalFrame eyeFrame() {
        return new LocalFrame(latDeg, lonDeg, eyeAltitudeMetres());
    }
}
