package dempano.orient;

import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;

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
        double fl = Math.floor(x);
        int c0 = (int) fl;
        double t = x - fl;
        int n = elevationDeg.length;
        double a = elevationDeg[Math.floorMod(c0, n)], b = elevationDeg[Math.floorMod(c0 + 1, n)];
        return a + t * (b - a);
    }
}
