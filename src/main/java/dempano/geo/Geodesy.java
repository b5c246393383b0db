package dempano.geo;

import net.sf.geographiclib.Geodesic;
import net.sf.geographiclib.GeodesicData;
import net.sf.geographiclib.GeodesicMask;

/** Geodesics on WGS84 through GeographicLib: distances in metres, azimuths in degrees from north. */
public final class Geodesy {
    private Geodesy() {
    }

    /** Geodesic distance between two points, metres. */
    public static double distanceMetres(double lat1Deg, double lon1Deg, double lat2Deg, double lon2Deg) {
        return Geodesic.WGS84.Inverse(lat1Deg, lon1Deg, lat2Deg, lon2Deg, GeodesicMask.DISTANCE).s12;
    }

    /** Azimuth at point 1 of the geodesic to point 2, degrees clockwise from north in [0, 360). */
    public static double azimuthDeg(double lat1Deg, double lon1Deg, double lat2Deg, double lon2Deg) {
        double az = Geodesic.WGS84.Inverse(lat1Deg, lon1Deg, lat2Deg, lon2Deg, GeodesicMask.AZIMUTH).azi1;
        return az < 0 ? az + 360 : az;
    }

    /** Point at a distance (metres) and azimuth (degrees) from a start: {latDeg, lonDeg}. */
    public static double[] destination(double latDeg, double lonDeg, double azimuthDeg, double distanceMetres) {
        GeodesicData g = Geodesic.WGS84.Direct(latDeg, lonDeg, azimuthDeg, distanceMetres,
                GeodesicMask.LATITUDE | GeodesicMask.LONGITUDE);
        return new double[] {g.lat2, g.lon2};
    }
}
