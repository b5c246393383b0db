package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.geo.Ellipsoid;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.util.Random;
import net.sf.geographiclib.Geodesic;
import net.sf.geographiclib.GeodesicData;
import org.junit.jupiter.api.Test;

/** {@link EyePlacement} against the reference's local frame, GeographicLib's geodesics and closed forms (no GL). */
class EyePlacementTest {
    private static final Viewpoint EYE = new Viewpoint(46.55, 7.98, 3000, 0, 3000, 2);

    /** ECEF, ellipsoid normal and height of a geodetic point. */
    private static double[][] vertex(double latDeg, double lonDeg, double heightMetres) {
        double[] ecef = new double[3];
        Ellipsoid.toEcef(latDeg, lonDeg, heightMetres, ecef);
        double phi = Math.toRadians(latDeg), lam = Math.toRadians(lonDeg);
        double[] up = {Math.cos(phi) * Math.cos(lam), Math.cos(phi) * Math.sin(lam), Math.sin(phi)};
        return new double[][] {ecef, up, {heightMetres}};
    }

    @Test
    void withoutRefractionAVertexIsWhereTheLocalFrameOfTheEyePutsIt() {
        EyePlacement placement = new EyePlacement(EYE, Refraction.NONE);
        dempano.geo.LocalFrame frame = EYE.eyeFrame();
        double[] enu = new double[3];
        Random random = new Random(7);
        double[] out = new double[3];
        for (int i = 0; i < 200; i++) {
            double lat = EYE.latDeg() + (random.nextDouble() - 0.5) * 1.8, lon = EYE.lonDeg() + (random.nextDouble() - 0.5) * 2.6;
            double h = -100 + random.nextDouble() * 4900;
            double[][] v = vertex(lat, lon, h);
            placement.place(v[0], v[1], v[2][0], out, 0);
            frame.toEnu(lat, lon, h, enu);
            // jME axes: x east, y up, z south
            assertEquals(enu[0], out[0], 1e-6, "east");
            assertEquals(enu[2], out[1], 1e-6, "up");
            assertEquals(-enu[1], out[2], 1e-6, "south");
            // and the direction as the geodesic leaves the eye (normal section and geodesic part by under 1e-5° here)
            GeodesicData g = Geodesic.WGS84.Inverse(EYE.latDeg(), EYE.lonDeg(), lat, lon);
            double azimuthDeg = Math.toDegrees(Math.atan2(out[0], -out[2]));
            assertEquals(0, dempano.geo.Angles.wrap180(azimuthDeg - g.azi1), 1e-4, "azimuth");
        }
    }

    @Test
    void refractionLiftsAVertexAlongItsVerticalByKTimesTheGroundDistanceSquaredOverTwoR() {
        Refraction k = new Refraction(0.13);
        EyePlacement bent = new EyePlacement(EYE, k), straight = new EyePlacement(EYE, Refraction.NONE);
        double[] a = new double[3], b = new double[3];
        for (double[] target : new double[][] {{46.9, 8.4}, {46.0, 7.1}, {47.5, 9.9}, {46.56, 7.99}}) {
            double[][] v = vertex(target[0], target[1], 1500);
            bent.place(v[0], v[1], 1500, a, 0);
            straight.place(v[0], v[1], 1500, b, 0);
            GeodesicData g = Geodesic.WGS84.Inverse(EYE.latDeg(), EYE.lonDeg(), target[0], target[1]);
            double expected = k.liftMetres(g.s12);
            double lifted = Math.sqrt(Math.pow(a[0] - b[0], 2) + Math.pow(a[1] - b[1], 2) + Math.pow(a[2] - b[2], 2));
            // the chord-based ground distance is within 0.5 % of the geodesic: the lift within 1 %
            assertEquals(expected, lifted, 0.01 * expected + 1e-9, "lift at " + target[0] + ", " + target[1]);
            // along the vertical at the vertex, turned into the eye's frame
            double[] upThere = new double[3];
            straight.place(new double[] {v[0][0] + v[1][0], v[0][1] + v[1][1], v[0][2] + v[1][2]}, v[1], 1501, upThere, 0);
            for (int axis = 0; axis < 3; axis++) {
                assertEquals((upThere[axis] - b[axis]) * lifted, a[axis] - b[axis], 1e-6 * lifted + 1e-9);
            }
        }
    }

    @Test
    void theBoundHoldsEveryPointOfTheHullAsPlaced() {
        EyePlacement placement = new EyePlacement(EYE, new Refraction(0.13));
        Random random = new Random(11);
        double[] out = new double[3];
        for (int trial = 0; trial < 50; trial++) {
            double lat0 = EYE.latDeg() + (random.nextDouble() - 0.5) * 1.6, lon0 = EYE.lonDeg() + (random.nextDouble() - 0.5) * 2.4;
            double[] hull = new double[24];
            double[][][] corners = new double[8][][];
            for (int c = 0; c < 8; c++) {
                corners[c] = vertex(lat0 + (c & 1) * 0.05, lon0 + (c >> 1 & 1) * 0.07, (c >> 2) * 3000);
                System.arraycopy(corners[c][0], 0, hull, 3 * c, 3);
            }
            double[] box = placement.bound(hull);
            for (double[][] v : corners) {
                placement.place(v[0], v[1], v[2][0], out, 0);
                for (int axis = 0; axis < 3; axis++) {
                    assertTrue(box[axis] <= out[axis] && out[axis] <= box[3 + axis],
                            "axis " + axis + ": " + out[axis] + " outside " + box[axis] + " … " + box[3 + axis]);
                }
            }
        }
    }

    @Test
    void theShadersUniformsCarryTheEyeInDoubleSingleFormAndTheFrameAsOrthonormalRows() {
        EyePlacement placement = new EyePlacement(EYE, new Refraction(0.13));
        EyePlacement.Uniforms u = placement.uniforms();
        double[] eye = new double[3], foot = new double[3];
        Ellipsoid.toEcef(EYE.latDeg(), EYE.lonDeg(), EYE.eyeAltitudeMetres(), eye);
        Ellipsoid.toEcef(EYE.latDeg(), EYE.lonDeg(), 0, foot);
        for (int a = 0; a < 3; a++) {
            assertEquals(eye[a], (double) u.eyeHigh()[a] + u.eyeLow()[a], 1e-7, "eye, axis " + a);
            assertEquals(foot[a] - eye[a], u.eyeFoot()[a], 1e-3, "foot, axis " + a);
        }
        float[] r = u.ecefToEye();
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double dot = r[3 * i] * r[3 * j] + r[3 * i + 1] * r[3 * j + 1] + r[3 * i + 2] * r[3 * j + 2];
                assertEquals(i == j ? 1 : 0, dot, 1e-6);
            }
        }
        // the up row is the ellipsoid normal at the eye
        double phi = Math.toRadians(EYE.latDeg()), lam = Math.toRadians(EYE.lonDeg());
        assertEquals(Math.cos(phi) * Math.cos(lam), r[3], 1e-7);
        assertEquals(Math.cos(phi) * Math.sin(lam), r[4], 1e-7);
        assertEquals(Math.sin(phi), r[5], 1e-7);
        assertEquals(0.13 / (2 * Ellipsoid.MEAN_RADIUS_METRES), u.liftPerSquareMetre(), 1e-15);
    }
}
