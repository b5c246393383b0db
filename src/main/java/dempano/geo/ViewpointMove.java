package dempano.geo;

import java.util.Locale;

/**
 * Where the eye was asked to be and where it was put, and why (the automatic corrections of
 * {@link ViewpointAdjustment}).
 *
 * @param fromLatDeg            requested latitude, degrees
 * @param fromLonDeg            requested longitude, degrees
 * @param fromEyeAltitudeMetres eye altitude at the requested point (DEM height + offset + eye height, or the
 *                              absolute altitude + eye height), metres above sea level
 * @param toLatDeg              latitude used, degrees
 * @param toLonDeg              longitude used, degrees
 * @param toEyeAltitudeMetres   eye altitude used, metres above sea level
 * @param shiftMetres           horizontal distance moved, metres (0 without a snap)
 * @param liftMetres            how far the clear-view option raised the eye above where the (snapped) point put
 *                              it, metres (0 without it or when already clear)
 * @param reason                which options moved it, e.g. "--snap-to-summit-m 100"
 */
public record ViewpointMove(double fromLatDeg, double fromLonDeg, double fromEyeAltitudeMetres, double toLatDeg,
                            double toLonDeg, double toEyeAltitudeMetres, double shiftMetres, double liftMetres,
                            String reason) {
    /** One line for the user. */
    public String describe() {
        return String.format(Locale.ROOT, "viewpoint moved (%s): from %.6f, %.6f, eye %.1f m to %.6f, %.6f, eye %.1f m"
                        + " (%.1f m horizontally, %+.1f m in eye altitude, of which %.1f m lift)", reason, fromLatDeg,
                fromLonDeg, fromEyeAltitudeMetres, toLatDeg, toLonDeg, toEyeAltitudeMetres, shiftMetres,
                toEyeAltitudeMetres - fromEyeAltitudeMetres, liftMetres);
    }
}
