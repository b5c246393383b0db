package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dempano.camera.CameraOrientation;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** Matching a photo as the photo command does, on photos drawn here from an analytic horizon with known poses. */
class PhotoOrientationTest {
    static final int SKY = 0x6ea0e6, LAND = 0x5a503c;

    /** A photo of the horizon: sky above the exact skyline, land below, the pixel it crosses blended by its share. */
    static BufferedImage photo(int w, int h, CameraOrientation o, double hfovDeg) {
        Skyline sky = SyntheticSkyline.project(SyntheticSkyline::ridge, w, h, o, hfovDeg);
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] column = new int[h];
        for (int x = 0; x < w; x++) {
            double edge = sky.row(x) + 0.5; // pixel rows span [y, y + 1); the skyline's row is a centre coordinate
            for (int y = 0; y < h; y++) {
                double skyShare = Double.isNaN(edge) ? 0 : Math.max(0, Math.min(1, edge - y));
                column[y] = blend(skyShare);
            }
            img.setRGB(x, 0, 1, h, column, 0, 1);
        }
        return img;
    }

    private static int blend(double skyShare) {
        int c = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            double v = skyShare * (SKY >> shift & 0xff) + (1 - skyShare) * (LAND >> shift & 0xff);
            c |= (int) Math.round(v) << shift;
        }
        return c;
    }

    /**
     * A large photo (3000 × 2000 px of 30°: 100 px/°, as a 6000 px photo of 60°) against a panorama profile with rows
     * 0.1° apart, as rendered: matched at full size a panorama row is 10 photo pixels, and only 83 % of the samples
     * of the correct pose fit within the 3 px truncation (a real 6000 × 4000 photo against the OpenGL panorama: 31 %,
     * flagged UNSURE); matched scaled to the benchmark's size, as the photo command does, every sample fits.
     */
    @Test
    void aLargePhotoIsMatchedAtTheBenchmarksScaleAndConfidently() {
        HorizonProfile profile = SyntheticSkyline.renderedProfile(SyntheticSkyline::ridge, PhotoOrientation.PANORAMA_PPD, 45);
        double heading = 123.4, pitch = 1.5, roll = -2, hfov = 30;
        BufferedImage big = photo(3000, 2000, new CameraOrientation(heading, pitch, roll), hfov);
        PhotoOrientation.Result r = PhotoOrientation.match(big, profile, null, OrientationPriors.NONE);
        OrientationEstimate e = r.estimate();
        assertTrue(OrientationEstimator.headingGap(e.headingDeg(), heading) < 0.1, e.summary());
        assertEquals(pitch, e.pitchDeg(), 0.1, e.summary());
        assertEquals(roll, e.rollDeg(), 0.15, e.summary());
        assertEquals(hfov, e.hfovDeg(), 0.01 * hfov, e.summary());
        assertFalse(e.unsure(), e.summary());
        assertTrue(e.inlierShare() > 0.95, e.summary());
        assertEquals(480, r.matchedWidthPx());
        assertEquals(320, r.matchedHeightPx());
        assertEquals(480, r.overlay().getWidth());
        // The residual is reported in the photo's pixels: 6.25 of them per matched pixel.
        PhotoOrientation.Result small = PhotoOrientation.match(photo(480, 320, new CameraOrientation(heading, pitch, roll),
                hfov), profile, null, OrientationPriors.NONE);
        assertEquals(6.25 * small.estimate().residualPx(), e.residualPx(), 2 * small.estimate().residualPx() + 0.5,
                e.summary() + " against " + small.estimate().summary());
    }
}
