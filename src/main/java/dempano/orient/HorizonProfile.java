package dempano.orient;

import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.util.Floors;

/**
 * The skyline of a 360° panorama as a function of azimuth: per column, the elevation of the boundary between
 * the sky above and the first terrain below (the top edge of the column's topmost finite-distance pixel).
 * Pure arithmetic on the distance map; immutable.
 */
public final class HorizonProfile {
    private final double[] elevationDeg;
    private final double pixelsPerDegree;

    /**
     * @param elevationDeg    skyline elevation per column, degrees; column c's centre at azimuth (c + 0.5)/ppd;
     *                        NaN where the column has no terrain
     * @param pixelsPerDegree columns per degree of azimuth (length = 360·ppd)
     */
    public HorizonProfile(double[] elevationDeg, double pixelsPerDegree) {
        if (elevationDeg.length < 4 || Math.abs(elevationDeg.length - 360 * pixelsPerDegree) > 1e-6 * elevationDeg.length) {
            throw new IllegalArgumentException("a horizon profile needs 360·ppd columns, got " + elevationDeg.length
                    + " at " + pixelsPerDegree + " ppd");
        }
        this.elevationDeg = elevationDeg.clone();
        this.pixelsPerDegree = pixelsPerDegree;
    }

    /** The skyline of a panorama's distance map (sky = +∞). */
    public static HorizonProfile of(Panorama panorama) {
        return of(panorama.distanceArray(), panorama.geometry());
    }

    /** The skyline of a distance map (row-major, row 0 on top, sky +∞ or NaN) in a panorama layout. */
    public static HorizonProfile of(float[] distanceMetres, PanoramaGeometry geometry) {
        int w = geometry.widthPx(), h = geometry.heightPx();
        double[] el = new double[w];
        for (int c = 0; c < w; c++) {
            el[c] = Double.NaN;
            for (int r = 0; r < h; r++) {
                if (Float.isFinite(distanceMetres[r * w + c])) {
                    el[c] = geometry.topElevationDeg() - r / geometry.pixelsPerDegree();
                    break;
                }
            }
        }
        return new HorizonProfile(el, geometry.pixelsPerDegree());
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
            double a0 = az[c], a1 = az[c] + (((az[c + 1] - az[c]) % 360 + 540) % 360 - 180);
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
