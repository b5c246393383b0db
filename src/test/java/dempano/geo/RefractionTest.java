package dempano.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class RefractionTest {
    /** The series against Math.asin (within 1 ulp of the truth) over the whole series range, on a log sweep. */
    @Test
    void halfChordSeriesIsWithinTwoUlpsOfAsin() {
        double worstUlps = 0;
        for (double x = 1e-12; x < Refraction.SERIES_LIMIT; x *= 1.0007) {
            for (double s : new double[] {x, -x}) {
                double series = Refraction.asinOfHalfChord(s), exact = Math.asin(s);
                worstUlps = Math.max(worstUlps, Math.abs(series - exact) / Math.ulp(exact));
            }
        }
        assertTrue(worstUlps <= 2, "worst difference " + worstUlps + " ulp");
        // Just below the limit, where the truncated terms are largest.
        double edge = Math.nextDown(Refraction.SERIES_LIMIT);
        assertEquals(Math.asin(edge), Refraction.asinOfHalfChord(edge), 2 * Math.ulp(Math.asin(edge)));
    }

    @Test
    void halfChordAsinEdgeCases() {
        assertEquals(0.0, Refraction.asinOfHalfChord(0.0));
        assertTrue(Double.isNaN(Refraction.asinOfHalfChord(Double.NaN)));
        assertEquals(Math.asin(0.05), Refraction.asinOfHalfChord(0.05)); // from the limit on: Math.asin itself
        assertEquals(Math.PI / 2, Refraction.asinOfHalfChord(1.0));
    }

    /** A closed form: a chord of 2R sin(d/2R) is the ground distance d on the mean sphere, to 1e-9 m at 1 m … 600 km. */
    @Test
    void groundDistanceInvertsTheChordOfTheMeanSphere() {
        double r = Ellipsoid.MEAN_RADIUS_METRES;
        for (double d : new double[] {1, 90, 1e3, 1e4, 1e5, 3e5, 6e5}) {
            double chord = 2 * r * Math.sin(d / (2 * r));
            assertEquals(d, Refraction.groundDistanceFromChordMetres(chord), 1e-9 + 1e-15 * d, "d = " + d);
        }
        // Beyond the sphere's diameter the chord is clamped: half the circumference.
        assertEquals(Math.PI * r, Refraction.groundDistanceFromChordMetres(3 * r), 1e-6);
    }
}
