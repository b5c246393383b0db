package dempano.orient;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Inner edge points of drawn images. */
class PhotoEdgesTest {
    static final int W = 240, H = 160;

    /** Sky above row 40, pale far terrain down to a near ridge at row 90 + 10·sin, dark near terrain below. */
    static BufferedImage draw(double noiseSigma) {
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Random rnd = new Random(3);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double ridge = 90 + 10 * Math.sin(x * 0.05);
                int[] c = y < 40 ? new int[]{140, 180, 235} : y < ridge ? new int[]{150, 150, 145} : new int[]{70, 80, 50};
                int rgb = 0;
                for (int k = 0; k < 3; k++) {
                    int v = (int) Math.max(0, Math.min(255, c[k] + noiseSigma * rnd.nextGaussian()));
                    rgb = (rgb << 8) | v;
                }
                img.setRGB(x, y, rgb);
            }
        }
        return img;
    }

    @Test
    void edgePointsLieOnTheInnerRidgeNotOnTheSkyline() {
        BufferedImage img = draw(2);
        Skyline sky = SkylineExtractor.extract(img);
        PhotoEdges e = PhotoEdges.extract(img, sky);
        assertTrue(e.size() > 100, "points: " + e.size());
        int near = 0;
        for (int i = 0; i < e.size(); i++) {
            double off = Math.abs(90 + 10 * Math.sin(e.xPx()[i] * 0.05) - e.yPx()[i]);
            assertTrue(off < 5, "point " + i + " is " + off + " px off the ridge");
            near += off < 1.6 ? 1 : 0;
        }
        assertTrue(near >= 0.95 * e.size(), near + " of " + e.size() + " within 1.6 px");
    }

    @Test
    void noiseAloneGivesNoEdgePoints() {
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Random rnd = new Random(5);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int v = y < 50 ? 230 : (int) Math.max(0, Math.min(255, 90 + 6 * rnd.nextGaussian()));
                img.setRGB(x, y, y < 50 ? 0x8cb4eb : (v << 16) | (v << 8) | v);
            }
        }
        Skyline sky = SkylineExtractor.extract(img);
        assertTrue(sky.foundColumns() > W / 2);
        assertTrue(PhotoEdges.extract(img, sky).size() < 10, "points: " + PhotoEdges.extract(img, sky).size());
    }
}
