package dempano.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.Synthetic;
import dempano.dem.MissingTilePolicy;
import dempano.dem.Mosaic;
import dempano.dem.TileSelection;
import dempano.geo.Ellipsoid;
import dempano.geo.EllipsoidRay;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.geo.Viewpoint;
import java.util.Random;
import org.junit.jupiter.api.Test;

class TerrainRayProbeTest {
    /** A 1°×1° plane DEM at 500 m around 46.5 N 8.5 E, eye 1500 m above it. */
    private static TerrainRayProbe planeProbe(double eyeOffsetMetres, Refraction refraction, double rangeMetres) {
        Mosaic mosaic = Mosaic.of(Synthetic.dem((lat, lon) -> 500, 46, 8, 1, 1),
                TileSelection.around(46.5, 8.5, rangeMetres), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 46.5, 8.5, eyeOffsetMetres, 0);
        return new TerrainRayProbe(mosaic, eye, refraction, rangeMetres);
    }

    @Test
    void closedFormGeodeticAgreesWithTheIterativeConversion() {
        TerrainRayProbe probe = planeProbe(1500, Refraction.STANDARD, 30_000);
        Random random = new Random(7);
        double worst = 0;
        for (int i = 0; i < 20_000; i++) {
            double az = random.nextDouble() * 2 * Math.PI, el = Math.toRadians(-20 + 25 * random.nextDouble());
            double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
            double t = 10 + random.nextDouble() * 25_000;
            double fast = probe.clearance(e, n, u, t);
            double[] ecef = new double[3];
            new LocalFrame(46.5, 8.5, 2000).enuToEcef(t * e, t * n, t * u, ecef);
            double slow = probe.clearanceNearPole(ecef[0], ecef[1], ecef[2]);
            if (Double.isNaN(slow)) {
                assertTrue(Double.isNaN(fast), "off the mosaic for one, not the other");
                continue;
            }
            worst = Math.max(worst, Math.abs(fast - slow));
        }
        assertTrue(worst < 1e-6, "closed form vs iterative height above the surface differ by " + worst + " m");
    }

    @Test
    void hitsAFlatDemWhereTheRayMeetsTheEllipsoidLiftedToItsHeight() {
        // With k = 0 the plane DEM at 500 m is the ellipsoid raised by 500 m along the normal, which
        // is not an ellipsoid; but within 20 km the two differ by far less than a millimetre at these
        // incidences, so the ray against an ellipsoid with a and b each 500 m larger is the truth.
        double range = 40_000;
        TerrainRayProbe probe = planeProbe(1500, new Refraction(0), range);
        LocalFrame frame = new LocalFrame(46.5, 8.5, 2000);
        double[] origin = new double[3];
        frame.enuToEcef(0, 0, 0, origin);
        for (double elDeg : new double[] {-45, -10, -5, -4, -3}) {
            for (double azDeg = 0; azDeg < 360; azDeg += 45) {
                double el = Math.toRadians(elDeg), az = Math.toRadians(azDeg);
                double e = Math.cos(el) * Math.sin(az), n = Math.cos(el) * Math.cos(az), u = Math.sin(el);
                double[] dir = new double[3];
                EllipsoidRay.enuDirectionToEcef(frame, origin, e, n, u, new double[3], dir);
                double truth = EllipsoidRay.distanceMetres(origin, dir, Ellipsoid.A_METRES + 500, Ellipsoid.B_METRES + 500);
                // jME axes: east, up, south.
                double probed = probe.firstHitMetres(e, u, -n, 0.5 * truth, 2 * truth, false);
                assertEquals(truth, probed, 2e-6 * truth, "elevation " + elDeg + "°, azimuth " + azDeg + "°");
            }
        }
    }

    @Test
    void fineStepsFindACrestThatCoarseStepsStepOver() {
        // A plane at 500 m with a crest one sample row wide (800 m) 5.0 km north of the eye, cells
        // of 1/600° (185 m north–south, 128 m east–west). A ray aimed 150 m under the crest's top
        // is below the surface for about 185 m around 5.0 km; coarse steps from 4.7 km (×1.1: to
        // 5.17 km) step over it and meet the plane far behind, fine steps do not.
        double crestLat = 46.5 + 3000 / 600.0 / 100; // a sample row, 0.05° north
        Mosaic mosaic = Mosaic.of(Synthetic.dem((lat, lon) -> Math.abs(lat - crestLat) < 1e-6 ? 800 : 500, 46, 8, 1, 1),
                TileSelection.around(46.5, 8.5, 30_000), MissingTilePolicy.AUTO);
        Viewpoint eye = Viewpoint.onDem(mosaic, 46.5, 8.5, 300, 0); // eye at 800 m
        TerrainRayProbe probe = new TerrainRayProbe(mosaic, eye, new Refraction(0), 30_000);
        double crestMetres = 0.05 * Math.PI / 180 * 6_367_000; // meridian arc to the crest, ±0.1 %
        double el = Math.atan2(-150, crestMetres);
        double e = 0, n = Math.cos(el), u = Math.sin(el);
        double coarse = probe.firstHitMetres(e, u, -n, 4700, 20_000, false);
        double fine = probe.firstHitMetres(e, u, -n, 4700, 20_000, true);
        assertTrue(coarse > 5500, "coarse steps stepped over the crest: " + coarse);
        assertEquals(crestMetres, fine, 200, "fine steps meet the crest");
        assertEquals(0, probe.clearance(e, n, u, fine), 1e-3, "on the surface");
    }
}
