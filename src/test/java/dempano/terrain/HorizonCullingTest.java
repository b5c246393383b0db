package dempano.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.terrain.HorizonCulling.Bounds;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Culling by bounds: a table of walls and what lies behind them, and the angle bounds against a scan. */
class HorizonCullingTest {
    static final Bounds WALL = new Bounds(10, 20, 1000, 2000, 1000, 1000); // 1 km high, 1–2 km away

    static boolean hiddenBehindWall(Bounds p, double eyeAltitude, double bottomDeg) {
        return HorizonCulling.hidden(List.of(WALL, p), eyeAltitude, 0.13, bottomDeg, HorizonCulling.DEFAULT_MARGIN_DEG)[1];
    }

    @Test
    void tableOfPatchesBehindAWall() {
        Object[][] table = {
                // patch, eye altitude, bottom of the picture, hidden?, why
                {new Bounds(12, 18, 5000, 6000, 0, 500), 0.0, -90.0, true, "low and wholly behind"},
                {new Bounds(12, 18, 5000, 6000, 0, 5000), 0.0, -90.0, false, "rises above the wall (45° > 26.6°)"},
                {new Bounds(5, 18, 5000, 6000, 0, 500), 0.0, -90.0, false, "sticks out sideways"},
                {new Bounds(372, 378, 5000, 6000, 0, 500), 0.0, -90.0, true, "azimuths taken modulo 360"},
                {new Bounds(12, 18, 1500, 6000, 0, 500), 0.0, -90.0, false, "not wholly behind the wall"},
                {new Bounds(12, 18, 5000, 6000, 0, 500), 3000.0, -90.0, false, "the eye looks over the wall"},
                {new Bounds(200, 210, 1000, 1500, 0, 10), 1000.0, -30.0, true, "below the picture (−42°)"},
                {new Bounds(200, 210, 1000, 1500, 0, 10), 1000.0, -60.0, false, "inside the picture"},
                {new Bounds(0, 360, 0, 500, 0, 5000), 0.0, -90.0, false, "around the eye: never culled"},
        };
        for (Object[] row : table) {
            assertEquals(row[3], hiddenBehindWall((Bounds) row[0], (Double) row[1], (Double) row[2]), (String) row[4]);
        }
    }

    @Test
    void theEarthsCurvatureHidesFarSeaBehindANearIsland() {
        // An island 20 m high 10–12 km away; from 2 m, sea level at 100 km lies 700 m below the line of sight.
        Bounds island = new Bounds(40, 50, 10_000, 12_000, 20, 20);
        Bounds farSea = new Bounds(42, 48, 100_000, 101_000, 0, 0);
        Bounds farMountain = new Bounds(42, 48, 100_000, 101_000, 0, 1500);
        boolean[] h = HorizonCulling.hidden(List.of(island, farSea, farMountain), 2, 0.13, -90, HorizonCulling.DEFAULT_MARGIN_DEG);
        assertTrue(h[1], "the sea beyond the island");
        assertEquals(false, h[2], "a 1500 m mountain at 100 km shows above a 20 m island at 10 km");
    }

    @Test
    void angleBoundsHoldAgainstAScanOverDistance() {
        Random rnd = new Random(11);
        for (int i = 0; i < 2000; i++) {
            double e = rnd.nextDouble() * 4000, h = rnd.nextDouble() * 4000, k = rnd.nextDouble() * 0.3 - 0.1;
            double near = 10 + rnd.nextDouble() * 200_000, far = near + rnd.nextDouble() * 50_000;
            double hi = HorizonCulling.highestAngleDeg(h, e, near, far, k), lo = HorizonCulling.lowestAngleDeg(h, e, near, far, k);
            for (int s = 0; s <= 200; s++) {
                double d = near + (far - near) * s / 200;
                double angle = Math.toDegrees(Math.atan(HorizonCulling.tanElevation(h, e, d, k)));
                assertTrue(angle <= hi + 1e-9 && angle >= lo - 1e-9, "d " + d + ": " + angle + " not in [" + lo + ", " + hi + "]");
            }
        }
    }

    @Test
    void aRingOfRidgesHidesOnlyWhatIsLowerBehindIt() {
        // 36 ridge patches 5–6 km away, 800 m high; behind each, one lower and one higher patch.
        List<Bounds> patches = new ArrayList<>();
        for (int a = 0; a < 360; a += 10) {
            patches.add(new Bounds(a, a + 10, 5000, 6000, 800, 800));
            patches.add(new Bounds(a + 2, a + 8, 20_000, 21_000, 0, 2000));  // 5.4° < 7.6°: hidden
            patches.add(new Bounds(a + 2, a + 8, 20_000, 21_000, 0, 4000));  // 11° > 7.6°: seen
        }
        boolean[] h = HorizonCulling.hidden(patches, 0, 0.13, -90, HorizonCulling.DEFAULT_MARGIN_DEG);
        for (int i = 0; i < patches.size(); i += 3) {
            assertEquals(false, h[i]);
            assertEquals(true, h[i + 1], "behind ridge " + i / 3);
            assertEquals(false, h[i + 2]);
        }
    }
}
