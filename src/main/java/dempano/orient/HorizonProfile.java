package dempano.orient;

import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.util.Floors;

/**
 * The skyline of a 360° panorama as a function of azimuth: per column, the elevation of the boundary between
 * the sky above and the first terrain below (the top edge of the column's topmost finite-distance pixel), and that
 * pixel's distance (for the skyline seen from a higher or lower eye, {@link #raised}).
 * Pure arithmetic on the distance map; immutable.
 */
public final class HorizonProfile {
    private final double[] elevationDeg;
    /** Per column, the straight-line distance of the skyline's terrain from the eye, metres; NaN where unknown. */
    private final double[] distanceMetres;
    private final double pixelsPerDegree;

    /**
     * @param elevationDeg    skyline elevation per column, degrees; column c's centre at azimuth (c + 0.5)/ppd;
     *                        NaN where the column has no terrain
     * @param pixelsPerDegree columns per degree of azimuth (length = 360·ppd)
     */
    public HorizonProfile(double[] elevationDeg, double pixelsPerDegree) {
        this(elevationDeg, null, pixelsPerDegree);
    }

    /**
     * @param distanceMetres per column, the distance of the skyline's terrain from the eye (straight line), metres,
     *                       NaN where unknown; null = unknown everywhere (then {@link #raised} changes nothing)
     */
    public HorizonProfile(double[] elevationDeg, double[] distanceMetres, double pixelsPerDegree) {
        if (elevationDeg.length < 4 || Math.abs(elevationDeg.length - 360 * pixelsPerDegree) > 1e-6 * elevationDeg.length) {
            throw new IllegalArgumentException("a horizon profile needs 360·ppd columns, got " + elevationDeg.length
                    + " at " + pixelsPerDegree + " ppd");
        }
        if (distanceMetres != null && distanceMetres.length != elevationDeg.length) {
            throw new IllegalArgumentException("a distance per column is needed, got " + distanceMetres.length + " for "
                    + elevationDeg.length + " columns");
        }
        this.elevationDeg = elevationDeg.clone();
        this.pixelsPerDegree = pixelsPerDegree;
        if (distanceMetres == null) {
            this.distanceMetres = new double[elevationDeg.length];
            java.util.Arrays.fill(this.distanceMetres, Double.NaN);
        } else {
            this.distanceMetres = distanceMetres.clone();
        }
    }

    /** Whether any column knows its skyline's distance (what {@link #raised} needs). */
    public boolean hasDistances() {
        for (double d : distanceMetres) {
            if (d > 0 && d < Double.POSITIVE_INFINITY) {
                return true;
            }
        }
        return false;
    }

    /**
     * The skyline seen from an eye {@code metres} higher (negative: lower), to first order in the shift of the
     * skyline's terrain: each column's skyline point, at distance d and elevation e, is seen at
     * atan2(d·sin e − Δh, d·cos e). The skyline terrain itself is taken as staying the same point (for a rounded
     * crest the tangent point moves, but its elevation changes alike to first order). Columns whose distance is
     * unknown keep their elevation.
     */
    public HorizonProfile raised(double metres) {
        double[] el = elevationDeg.clone();
        for (int c = 0; c < el.length; c++) {
            double d = distanceMetres[c];
            if (d > 0 && d < Double.POSITIVE_INFINITY && !Double.isNaN(el[c])) {
                double e = Math.toRadians(el[c]);
                el[c] = Math.toDegrees(Math.atan2(d * Math.sin(e) - metres, d * Math.cos(e)));
            }
        }
        return new HorizonProfile(el, distanceMetres, pixelsPerDegree);
    }

    /** The skyline of a panorama's distance map (sky = +∞). */
    public static HorizonProfile of(Panorama panorama) {
        return of(panorama.distanceArray(), panorama.geometry());
    }

    /** The skyline of a distance map (row-major, row 0 on top, sky +∞ or NaN) in a panorama layout. */
    public static HorizonProfile of(float[] distanceMetres, PanoramaGeometry geometry) {
        int w = geometry.widthPx(), h = geometry.heightPx();
        double[] el = new double[w], d = new double[w];
        for (int c = 0; c < w; c++) {
            el[c] = Double.NaN;
            d[c] = Double.NaN;
            for (int r = 0; r < h; r++) {
                if (Float.isFinite(distanceMetres[r * w + c])) {
                    el[c] = geometry.topElevationDeg() - r / geometry.pixelsPerDegree();
                    d[c] = distanceMetres[r * w + c];
                    break;
                }
            }
        }
        return new HorizonProfile(el, d, geometry.pixelsPerDegree());
    }

    /**
     * The skyline of a camera render as a profile over azimuth: per rendered column, the top edge of its topmost
     * finite-distance pixel (row r's top edge lies at y = r − 0.5, pixel centres on integers), turned into azimuth
     * and elevation by the render's own rays, then interpolated linearly onto profile columns of
     * {@code pixelsPerDegree}. Columns whose top row is already terrain (the skyline above the frame) or that show
     * no terrain are unknown, and so is every azimuth outside the render: NaN there.
     *
     * @param distanceMetres  the render's distances, row-major, row 0 on top, sky +∞ or NaN
     * @param view            the render's pixel grid and orientation
     * @param pixelsPerDegree the profile's resolution; 360 × it must be a whole number of columns
     */
    public static HorizonProfile ofCamera(float[] distanceMetres, dempano.camera.TargetImage view, double pixelsPerDegree) {
        int w = view.widthPx(), h = view.heightPx();
        if (distanceMetres.length != w * h) {
            throw new IllegalArgumentException("a camera skyline needs width × height distances, got "
                    + distanceMetres.length + " for " + w + " × " + h);
        }
        double[] az = new double[w], el = new double[w], ray = new double[3];
        for (int c = 0; c < w; c++) {
            az[c] = Double.NaN;
            el[c] = Double.NaN;
            int top = -1;
            for (int r = 0; r < h; r++) {
                if (Float.isFinite(distanceMetres[r * w + c])) {
                    top = r;
                    break;
                }
            }
            if (top <= 0) {
                continue;
            }
            view.rayOf(c, top - 0.5, ray);
            az[c] = Math.toDegrees(Math.atan2(ray[0], ray[1]));
            el[c] = Math.toDegrees(Math.atan2(ray[2], Math.hypot(ray[0], ray[1])));
        }
        int n = (int) Math.round(360 * pixelsPerDegree);
        double ppd = n / 360.0;
        double[] out = new double[n];
        java.util.Arrays.fill(out, Double.NaN);
        for (int c = 0; c + 1 < w; c++) {
            if (Double.isNaN(el[c]) || Double.isNaN(el[c + 1])) {
                continue;
            }
            double a0 = az[c], a1 = az[c] + dempano.geo.Angles.wrap180(az[c + 1] - az[c]);
            double lo = Math.min(a0, a1), hi = Math.max(a0, a1);
            if (hi - lo > 5) {
                continue;
            }
            // Profile column k's centre is at azimuth (k + 0.5)/ppd.
            for (long k = (long) Math.ceil(lo * ppd - 0.5); (k + 0.5) / ppd <= hi; k++) {
                double a = (k + 0.5) / ppd, t = hi > lo ? (a - a0) / (a1 - a0) : 0;
                out[(int) Math.floorMod(k, (long) n)] = el[c] + t * (el[c + 1] - el[c]);
            }
        }
        return new HorizonProfile(out, ppd);
    }

    public double pixelsPerDegree() {
        return pixelsPerDegree;
    }

    public int columns() {
        return elevationDeg.length;
    }

    /** Skyline elevation of one column, degrees (NaN: no terrain). */
    public double columnElevationDeg(int column) {
        return elevationDeg[Math.floorMod(column, elevationDeg.length)];
    }

    /** Skyline elevation at any azimuth (degrees, any wrapping), linear between column centres; NaN if unknown. */
    public double elevationDeg(double azimuthDeg) {
        double x = azimuthDeg * pixelsPerDegree - 0.5;
        // Floors.floorInt, not Math.floor, which the client compiler (the start script's) calls: the coarse search asks
        // this some 20 million times a photo. The same values wherever the int range holds the column.
        double fl = Math.abs(x) < 1e9 ? Floors.floorInt(x) : Math.floor(x);
        int c0 = (int) fl;
        double t = x - fl;
        int n = elevationDeg.length;
        double a = elevationDeg[Math.floorMod(c0, n)], b = elevationDeg[Math.floorMod(c0 + 1, n)];
        return a + t * (b - a);
    }
}
