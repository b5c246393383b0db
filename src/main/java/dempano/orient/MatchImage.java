package dempano.orient;

import boofcv.alg.filter.misc.AverageDownSampleOps;
import boofcv.struct.image.GrayU8;
import boofcv.struct.image.Planar;
import java.awt.image.BufferedImage;

/**
 * The photo as its skyline is matched: scaled down, by area averaging (BoofCV's {@link AverageDownSampleOps}), to
 * the smallest size that still covers {@link #MIN_WIDTH_PX} × {@link #MIN_HEIGHT_PX}, the size of the benchmark's
 * photos on which the estimator's pixel thresholds and its UNSURE rule were calibrated. A photo no larger is matched
 * as it is.
 *
 * <p>Why: the estimator's thresholds are in pixels (residual truncation 12 → 6 → 3 px), and the panorama it matches
 * against has rows 1/{@link PhotoOrientation#PANORAMA_PPD}° apart. A 6000 px wide photo of 60° has 100 px/°: a
 * panorama row is 10 photo pixels, so a correct pose left only 31 % of the skyline samples within 3 px and was flagged
 * UNSURE (measured; the same photo scaled to 480 px: 100 % within 3 px, margin 0.28). Scaling also keeps the
 * filters' cost independent of the photo's size.
 *
 * @param image the image to match in (the photo itself when it is not larger than needed)
 * @param scale photo rows per image row, ≥ 1 (1 when not scaled; columns differ from it by the rounding of the width
 *              only): what turns a skyline residual, a difference of rows, into photo pixels
 */
public record MatchImage(BufferedImage image, double scale) {
    /** The matching image covers at least this width, pixels (the benchmark's photos are 480 × 320). */
    public static final int MIN_WIDTH_PX = 480;
    /** ... and at least this height, pixels. */
    public static final int MIN_HEIGHT_PX = 320;
    /** Photo rows converted at a time (bounds the temporary ARGB buffer for large photos). */
    private static final int STRIP_ROWS = 256;

    /** The photo scaled down by the largest factor that keeps it at least {@link #MIN_WIDTH_PX} × {@link #MIN_HEIGHT_PX}. */
    public static MatchImage of(BufferedImage photo) {
        int w = photo.getWidth(), h = photo.getHeight();
        double scale = Math.min((double) w / MIN_WIDTH_PX, (double) h / MIN_HEIGHT_PX);
        if (!(scale > 1)) {
            return new MatchImage(photo, 1);
        }
        int sw = Math.max(1, (int) Math.round(w / scale)), sh = Math.max(1, (int) Math.round(h / scale));
        Planar<GrayU8> full = new Planar<>(GrayU8.class, w, h, 3);
        int[] argb = new int[w * Math.min(h, STRIP_ROWS)];
        byte[] r = full.getBand(0).data, g = full.getBand(1).data, b = full.getBand(2).data;
        for (int y0 = 0; y0 < h; y0 += STRIP_ROWS) {
            int rows = Math.min(STRIP_ROWS, h - y0);
            photo.getRGB(0, y0, w, rows, argb, 0, w);
            for (int i = 0, o = y0 * w; i < rows * w; i++, o++) { // a fresh Planar's bands have stride = width
                int c = argb[i];
                r[o] = (byte) (c >> 16);
                g[o] = (byte) (c >> 8);
                b[o] = (byte) c;
            }
        }
        Planar<GrayU8> small = new Planar<>(GrayU8.class, sw, sh, 3);
        AverageDownSampleOps.down(full, small);
        BufferedImage out = new BufferedImage(sw, sh, BufferedImage.TYPE_INT_RGB);
        int[] row = new int[sw];
        byte[] sr = small.getBand(0).data, sg = small.getBand(1).data, sb = small.getBand(2).data;
        for (int y = 0; y < sh; y++) {
            for (int x = 0, o = y * sw; x < sw; x++, o++) {
                row[x] = (sr[o] & 0xff) << 16 | (sg[o] & 0xff) << 8 | sb[o] & 0xff;
            }
            out.setRGB(0, y, sw, 1, row, 0, sw);
        }
        return new MatchImage(out, (double) h / sh);
    }
}
