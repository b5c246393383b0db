package dempano.orient;

import boofcv.alg.filter.blur.BlurImageOps;
import boofcv.alg.filter.derivative.DerivativeType;
import boofcv.alg.filter.derivative.GImageDerivativeOps;
import boofcv.struct.border.BorderType;
import boofcv.struct.image.GrayF32;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A photo's strong inner edges: edge points below its skyline, to be matched against the rendered depth edges
 * ({@link SilhouetteField}). BoofCV Gaussian blur and Sobel gradients of the luminance; a pixel is an edge point
 * when its gradient magnitude is a local maximum across the edge (along the gradient, quantised to 4
 * directions), in the top {@link #TOP_SHARE} of the magnitudes below the skyline and at least
 * {@link #NOISE_FACTOR} times their median (so that noise alone gives none). Points less than
 * {@link #SKYLINE_GAP_PX} below the skyline, in columns without one or within {@link #BORDER_PX} of the
 * border are left out: the skyline is matched
 * separately.
 *
 * @param xPx column of each point, pixels (centres at integers)
 * @param yPx row of each point, pixels from the top
 */
public record PhotoEdges(double[] xPx, double[] yPx) {
    static final double BLUR_SIGMA_PX = 1.5;
    static final double TOP_SHARE = 0.08;
    static final double NOISE_FACTOR = 4;
    static final double SKYLINE_GAP_PX = 4;
    /** Points this close to the image border are left out (the blur sees past it), pixels. */
    static final int BORDER_PX = 4;
    /** At most this many points are kept (evenly spread over the candidates). */
    public static final int MAX_POINTS = 400;

    public PhotoEdges {
        if (xPx.length != yPx.length) {
            throw new IllegalArgumentException("edge points need as many columns as rows");
        }
        xPx = xPx.clone();
        yPx = yPx.clone();
    }

    public int size() {
        return xPx.length;
    }

    /** No edge points. */
    public static final PhotoEdges NONE = new PhotoEdges(new double[0], new double[0]);

    /** The edge points of a photo below its skyline. */
    public static PhotoEdges extract(BufferedImage image, Skyline sky) {
        int w = image.getWidth(), h = image.getHeight();
        if (w != sky.widthPx() || h != sky.heightPx()) {
            throw new IllegalArgumentException("the skyline belongs to another image size");
        }
        int[] argb = image.getRGB(0, 0, w, h, null, 0, w);
        GrayF32 lum = new GrayF32(w, h);
        for (int i = 0; i < w * h; i++) {
            int c = argb[i];
            lum.data[i] = (0.299f * ((c >> 16) & 0xff) + 0.587f * ((c >> 8) & 0xff) + 0.114f * (c & 0xff)) / 255f;
        }
        GrayF32 blurred = BlurImageOps.gaussian(lum, null, BLUR_SIGMA_PX, -1, null);
        GrayF32 dx = new GrayF32(w, h), dy = new GrayF32(w, h);
        GImageDerivativeOps.gradient(DerivativeType.SOBEL, blurred, dx, dy, BorderType.EXTENDED);
        float[] mag = new float[w * h];
        boolean[] below = new boolean[w * h];
        int nb = 0;
        int m = BORDER_PX;
        for (int y = m; y < h - m; y++) {
            for (int x = m; x < w - m; x++) {
                double row = sky.row(x);
                if (Double.isNaN(row) || y < row + SKYLINE_GAP_PX) {
                    continue;
                }
                int i = y * w + x;
                mag[i] = (float) Math.hypot(dx.get(x, y), dy.get(x, y));
                below[i] = true;
                nb++;
            }
        }
        if (nb < 100) {
            return NONE;
        }
        float[] vals = new float[nb];
        for (int i = 0, k = 0; i < w * h; i++) {
            if (below[i]) {
                vals[k++] = mag[i];
            }
        }
        Arrays.sort(vals);
        double threshold = Math.max(vals[(int) ((1 - TOP_SHARE) * (nb - 1))], NOISE_FACTOR * vals[nb / 2]);
        if (!(threshold > 1e-4)) {
            return NONE;
        }
        List<int[]> pts = new ArrayList<>();
        for (int y = 1; y < h - 1; y++) {
            for (int x = 1; x < w - 1; x++) {
                int i = y * w + x;
                if (!below[i] || mag[i] < threshold) {
                    continue;
                }
                double gx = dx.get(x, y), gy = dy.get(x, y);
                int ox, oy;
                double ang = Math.abs(Math.atan2(gy, gx));
                if (ang < Math.PI / 8 || ang > 7 * Math.PI / 8) {
                    ox = 1;
                    oy = 0;
                } else if (ang > 3 * Math.PI / 8 && ang < 5 * Math.PI / 8) {
                    ox = 0;
                    oy = 1;
                } else {
                    ox = 1;
                    oy = gx * gy > 0 ? 1 : -1;
                }
                float m1 = mag[(y + oy) * w + x + ox], m2 = mag[(y - oy) * w + x - ox];
                if (mag[i] >= m1 && mag[i] > m2) {
                    pts.add(new int[]{x, y});
                }
            }
        }
        int n = Math.min(MAX_POINTS, pts.size());
        double[] xs = new double[n], ys = new double[n];
        for (int k = 0; k < n; k++) {
            int[] p = pts.get((int) ((k + 0.5) * pts.size() / n));
            xs[k] = p[0];
            ys[k] = p[1];
        }
        return new PhotoEdges(xs, ys);
    }
}
