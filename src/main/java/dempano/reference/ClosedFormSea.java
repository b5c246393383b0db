package dempano.reference;

import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.LocalFrame;
import dempano.panorama.PanoramaGeometry;
import java.util.stream.IntStream;

/**
 * The truth of a sea scene in closed form: a DEM of zeros seen without refraction is the WGS84
 * ellipsoid, so every pixel centre's distance is the straight ray's intersection with it
 * ({@link EllipsoidRay}); no DEM, triangles or sweep involved.
 *
 * @param distanceMetres per pixel (row-major, row 0 on top), metres; +∞ where the ray misses (sky)
 * @param incidenceDeg   per pixel, angle between ray and the ellipsoid's tangent plane at the point
 *                       met, degrees in [0, 90]; NaN for sky
 */
public record ClosedFormSea(float[] distanceMetres, float[] incidenceDeg) {
    /**
     * The sea panorama for an eye.
     *
     * @param eye the eye's frame (origin = the eye, above the ellipsoid)
     * @param g   the panorama's pixel layout
     */
    public static ClosedFormSea of(LocalFrame eye, PanoramaGeometry g) {
        int w = g.widthPx(), h = g.heightPx();
        float[] distance = new float[w * h], incidence = new float[w * h];
        double[] origin = new double[3];
        eye.enuToEcef(0, 0, 0, origin);
        IntStream.range(0, h).parallel().forEach(row -> {
            double el = Math.toRadians(g.elevationOfRow(row));
            double[] scratch = new double[3], dir = new double[3], hit = new double[3];
            for (int col = 0; col < w; col++) {
                double az = Math.toRadians(g.azimuthOfColumn(col));
                EllipsoidRay.enuDirectionToEcef(eye, origin, Math.cos(el) * Math.sin(az), Math.cos(el) * Math.cos(az),
                        Math.sin(el), scratch, dir);
                double d = EllipsoidRay.distanceToWgs84Metres(origin, dir);
                int i = row * w + col;
                distance[i] = (float) d;
                if (Double.isFinite(d)) {
                    for (int k = 0; k < 3; k++) {
                        hit[k] = origin[k] + d * dir[k];
                    }
                    incidence[i] = (float) EllipsoidRay.incidenceDeg(hit, dir, Ellipsoid.A_METRES, Ellipsoid.B_METRES);
                } else {
                    incidence[i] = Float.NaN;
                }
            }
        });
        return new ClosedFormSea(distance, incidence);
    }
}
