package dempano.geo;

import net.sf.geographiclib.Constants;

/**
 * The WGS84 ellipsoid and conversions between geodetic coordinates and earth-centred, earth-fixed
 * (ECEF) cartesian coordinates, in double precision.
 *
 * <p>Heights are metres above the ellipsoid. SRTM heights are above the EGM96 geoid; the geoid
 * undulation changes by only metres over a few hundred kilometres, so treating them as ellipsoidal
 * heights shifts eye and terrain alike and leaves the eye-relative geometry unchanged to well under
 * a metre at 100 km.
 */
public final class Ellipsoid {
    /** Equatorial radius, metres. */
    public static final double A_METRES = Constants.WGS84_a;
    /** Flattening. */
    public static final double F = Constants.WGS84_f;
    /** First eccentricity squared. */
    public static final double E2 = F * (2 - F);
    /** Polar radius, metres. */
    public static final double B_METRES = A_METRES * (1 - F);
    /** IUGG mean earth radius R1 = (2a + b) / 3, metres; used for refraction. */
    public static final double MEAN_RADIUS_METRES = (2 * A_METRES + B_METRES) / 3;

    private Ellipsoid() {
    }

    /** Prime-vertical radius of curvature N(φ), metres. */
    public static double primeVerticalRadiusMetres(double latDeg) {
        return primeVerticalRadiusOfSinMetres(Math.sin(Math.toRadians(latDeg)));
    }

    /** Prime-vertical radius of curvature N(φ) = a / √(1 − e² sin²φ), metres, from sin φ (hot loops have it). */
    public static double primeVerticalRadiusOfSinMetres(double sinLat) {
        return A_METRES / Math.sqrt(1 - E2 * sinLat * sinLat);
    }

    /** Meridian radius of curvature M(φ) = a (1 − e²) / (1 − e² sin²φ)^{3/2}, metres, from sin φ. */
    public static double meridianRadiusOfSinMetres(double sinLat) {
        double w2 = 1 - E2 * sinLat * sinLat;
        return A_METRES * (1 - E2) / (w2 * Math.sqrt(w2));
    }

    /**
     * Geodetic to ECEF.
     *
     * @param out receives x, y, z in metres (length ≥ 3)
     */
    public static void toEcef(double latDeg, double lonDeg, double heightMetres, double[] out) {
        double phi = Math.toRadians(latDeg);
        double lambda = Math.toRadians(lonDeg);
        toEcef(Math.sin(phi), Math.cos(phi), Math.sin(lambda), Math.cos(lambda), heightMetres, out);
    }

    /** Geodetic to ECEF from precomputed sines and cosines (hot loops reuse them per row/column). */
    public static void toEcef(double sinLat, double cosLat, double sinLon, double cosLon,
                              double heightMetres, double[] out) {
        double n = primeVerticalRadiusOfSinMetres(sinLat);
        out[0] = (n + heightMetres) * cosLat * cosLon;
        out[1] = (n + heightMetres) * cosLat * sinLon;
        out[2] = (n * (1 - E2) + heightMetres) * sinLat;
    }

    /**
     * ECEF to geodetic, accurate to well under a millimetre for heights from -100 km to 1000 km (a fixed-point
     * iteration of the geodetic latitude on N(φ), started at the latitude of zero height, to 1e-15 rad; the height
     * from the projection that stays well conditioned at the poles).
     *
     * @return {latDeg, lonDeg, heightMetres}
     */
    public static double[] toGeodetic(double x, double y, double z) {
        double p = Math.hypot(x, y);
        double lon = Math.atan2(y, x);
        if (p < 1e-9) {
            double lat = z >= 0 ? 90 : -90;
            return new double[] {lat, 0, Math.abs(z) - B_METRES};
        }
        // Iterate φ with the standard fixed-point on N(φ); converges to 1e-15 rad in a few steps
        // for terrestrial heights.
        double lat = Math.atan2(z, p * (1 - E2));
        for (int i = 0; i < 10; i++) {
            double s = Math.sin(lat);
            double n = A_METRES / Math.sqrt(1 - E2 * s * s);
            double h = p / Math.cos(lat) - n;
            double next = Math.atan2(z, p * (1 - E2 * n / (n + h)));
            if (Math.abs(next - lat) < 1e-15) {
                lat = next;
                break;
            }
            lat = next;
        }
        double s = Math.sin(lat);
        double c = Math.cos(lat);
        double n = A_METRES / Math.sqrt(1 - E2 * s * s);
        // Height from the better-conditioned projection (avoids 1/cos near the poles).
        double h = p * c + z * s - A_METRES * A_METRES / n;
        return new double[] {Math.toDegrees(lat), Math.toDegrees(lon), h};
    }
}
