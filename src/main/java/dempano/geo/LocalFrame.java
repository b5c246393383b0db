package dempano.geo;

/**
 * A local east-north-up (ENU) frame tangent to the WGS84 ellipsoid at an origin, in double
 * precision. Up is the ellipsoid normal at the origin; north is toward the pole along the meridian.
 * Immutable and thread-safe.
 */
public final class LocalFrame {
    private final double originLatDeg;
    private final double originLonDeg;
    private final double originHeightMetres;
    private final double[] originEcef = new double[3];
    // Rows of the ECEF→ENU rotation.
    private final double ex, ey, ez; // east
    private final double nx, ny, nz; // north
    private final double ux, uy, uz; // up

    /** @param originHeightMetres height of the origin above the ellipsoid, metres */
    public LocalFrame(double originLatDeg, double originLonDeg, double originHeightMetres) {
        if (!(originLatDeg >= -90 && originLatDeg <= 90) || !Double.isFinite(originLonDeg)
                || !Double.isFinite(originHeightMetres)) {
            throw new IllegalArgumentException("bad frame origin: lat " + originLatDeg + ", lon "
                    + originLonDeg + ", height " + originHeightMetres);
        }
        this.originLatDeg = originLatDeg;
        this.originLonDeg = originLonDeg;
        this.originHeightMetres = originHeightMetres;
        Ellipsoid.toEcef(originLatDeg, originLonDeg, originHeightMetres, originEcef);
        double phi = Math.toRadians(originLatDeg);
        double lam = Math.toRadians(originLonDeg);
        double sp = Math.sin(phi), cp = Math.cos(phi), sl = Math.sin(lam), cl = Math.cos(lam);
        ex = -sl;
        ey = cl;
        ez = 0;
        nx = -sp * cl;
        ny = -sp * sl;
        nz = cp;
        ux = cp * cl;
        uy = cp * sl;
        uz = sp;
    }

    public double originLatDeg() {
        return originLatDeg;
    }

    public double originLonDeg() {
        return originLonDeg;
    }

    public double originHeightMetres() {
        return originHeightMetres;
    }

    /** ECEF (metres) to ENU (metres, relative to the origin). */
    public void ecefToEnu(double x, double y, double z, double[] out) {
        double dx = x - originEcef[0], dy = y - originEcef[1], dz = z - originEcef[2];
        out[0] = ex * dx + ey * dy + ez * dz;
        out[1] = nx * dx + ny * dy + nz * dz;
        out[2] = ux * dx + uy * dy + uz * dz;
    }

    /** Geodetic to ENU. @param out receives east, north, up in metres */
    public void toEnu(double latDeg, double lonDeg, double heightMetres, double[] out) {
        Ellipsoid.toEcef(latDeg, lonDeg, heightMetres, out);
        ecefToEnu(out[0], out[1], out[2], out);
    }

    /** ENU (metres) to ECEF (metres). */
    public void enuToEcef(double e, double n, double u, double[] out) {
        out[0] = originEcef[0] + ex * e + nx * n + ux * u;
        out[1] = originEcef[1] + ey * e + ny * n + uy * u;
        out[2] = originEcef[2] + ez * e + nz * n + uz * u;
    }

    /** A direction (or any vector) from ENU to ECEF axes: the rotation alone. */
    public void enuDirectionToEcef(double e, double n, double u, double[] out) {
        out[0] = ex * e + nx * n + ux * u;
        out[1] = ey * e + ny * n + uy * u;
        out[2] = ez * e + nz * n + uz * u;
    }

    /** ENU (metres) to geodetic: {latDeg, lonDeg, heightMetres}. */
    public double[] toGeodetic(double e, double n, double u) {
        double[] ecef = new double[3];
        enuToEcef(e, n, u, ecef);
        return Ellipsoid.toGeodetic(ecef[0], ecef[1], ecef[2]);
    }
}
