package dempano.panorama;

import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import java.util.EnumMap;
import java.util.Map;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * Per-pixel layers from each pixel's ray and distance: the point seen is eye + distance·ray in the
 * eye's east-north-up frame; its geodetic position follows exactly; its terrain elevation is its
 * height minus the refraction lift the renderer added.
 */
public final class LayerComputer {
    private LayerComputer() {
    }

    public static Map<Layer, float[]> compute(Set<Layer> wanted, PanoramaGeometry g, float[] distance, LocalFrame eye,
                                              Refraction refraction) {
        Map<Layer, float[]> out = new EnumMap<>(Layer.class);
        if (wanted.isEmpty()) {
            return out;
        }
        int w = g.widthPx(), n = w * g.heightPx();
        for (Layer l : wanted) {
            out.put(l, new float[n]);
        }
        float[] elev = out.get(Layer.ELEVATION), lat = out.get(Layer.LATITUDE), lon = out.get(Layer.LONGITUDE),
                ground = out.get(Layer.GROUND_DISTANCE);
        double[] eyeFoot = new double[3];
        Ellipsoid.toEcef(eye.originLatDeg(), eye.originLonDeg(), 0, eyeFoot);
        IntStream.range(0, g.heightPx()).parallel().forEach(row -> {
            double el = Math.toRadians(g.elevationOfRow(row));
            double[] foot = new double[3];
            for (int col = 0; col < w; col++) {
                int i = row * w + col;
                double d = distance[i];
                if (!Double.isFinite(d)) {
                    for (float[] a : new float[][] {elev, lat, lon, ground}) {
                        if (a != null) {
                            a[i] = Float.NaN;
                        }
                    }
                    continue;
                }
                double az = Math.toRadians(g.azimuthOfColumn(col));
                double e = d * Math.cos(el) * Math.sin(az), nn = d * Math.cos(el) * Math.cos(az), u = d * Math.sin(el);
                double[] geo = eye.toGeodetic(e, nn, u);
                if (lat != null) {
                    lat[i] = (float) geo[0];
                }
                if (lon != null) {
                    lon[i] = (float) geo[1];
                }
                if (elev != null) {
                    Ellipsoid.toEcef(geo[0], geo[1], 0, foot);
                    elev[i] = (float) (geo[2] - refraction.liftMetres(Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot)));
                }
                if (ground != null) {
                    ground[i] = (float) Geodesy.distanceMetres(eye.originLatDeg(), eye.originLonDeg(), geo[0], geo[1]);
                }
            }
        });
        return out;
    }
}
