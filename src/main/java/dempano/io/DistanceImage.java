package dempano.io;

import dempano.util.Floors;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.Locale;

/**
 * A distance map to look at: log-scaled colours (near = warm, far = cool, sky white) with a legend
 * strip in kilometres below the panorama.
 */
public final class DistanceImage {
    private static final int LEGEND_PX = 48;
    /** Piecewise ramp red → yellow → green → cyan → blue → violet (RGB in [0, 1]). */
    private static final double[][] STOPS = {{0.70, 0.05, 0.05}, {0.95, 0.55, 0.05}, {0.85, 0.85, 0.15},
            {0.25, 0.70, 0.30}, {0.15, 0.65, 0.75}, {0.15, 0.30, 0.80}, {0.35, 0.15, 0.55}};

    private DistanceImage() {
    }

    /**
     * {@link #colour}'s ramp tabulated by the distance's float bits: one entry per relative step of 2⁻¹², each
     * the colour at its step's geometric centre, so that a pixel costs a table look-up instead of a logarithm
     * and three roundings (they were most of the distance picture's time). Within one level per channel of
     * {@link #colour} everywhere (the step moves the ramp's position by at most 3.5e-5 of its length, 0.03 of a
     * level); exact at the clamped ends and for the sky.
     */
    static final class Ramp {
        private static final int SHIFT = 11; // 23 - 11 = 12 mantissa bits kept
        private final int lowBits;
        private final float minM, maxM;
        private final int nearColour, farColour;
        private final int[] table;

        Ramp(double minM, double maxM) {
            this.minM = (float) minM;
            this.maxM = (float) maxM;
            double logMin = Math.log(minM), perLog = 1 / (Math.log(maxM) - logMin);
            nearColour = DistanceImage.colour(minM, minM, maxM, logMin, perLog);
            farColour = DistanceImage.colour(maxM, minM, maxM, logMin, perLog);
            lowBits = Float.floatToRawIntBits(this.minM) >>> SHIFT << SHIFT;
            table = new int[((Float.floatToRawIntBits(this.maxM) - lowBits) >>> SHIFT) + 1];
            for (int k = 0; k < table.length; k++) {
                double lo = Float.intBitsToFloat(lowBits + (k << SHIFT));
                double hi = Float.intBitsToFloat(lowBits + (k << SHIFT) + (1 << SHIFT) - 1);
                table[k] = DistanceImage.colour(Math.sqrt(lo * hi), minM, maxM, logMin, perLog);
            }
        }

        /** The colour (0xRRGGBB) of a distance in metres; white for NaN and +∞ (sky). */
        int colour(float metres) {
            if (!(metres > minM)) {
                return Float.isNaN(metres) || metres == Float.NEGATIVE_INFINITY ? 0xffffff : nearColour;
            }
            if (metres >= maxM) {
                return metres == Float.POSITIVE_INFINITY ? 0xffffff : farColour;
            }
            return table[(Float.floatToRawIntBits(metres) - lowBits) >>> SHIFT];
        }
    }

    /** Colour for a distance in [minM, maxM] on a log scale (a turbo-like ramp). */
    static int colour(double metres, double minM, double maxM) {
        double logMin = Math.log(minM);
        return colour(metres, minM, maxM, logMin, 1 / (Math.log(maxM) - logMin));
    }

    /** As above, with log(minM) and 1 / (log(maxM) − log(minM)) given (they are the same for a whole picture). */
    private static int colour(double metres, double minM, double maxM, double logMin, double perLog) {
        if (!Double.isFinite(metres)) {
            return 0xffffff;
        }
        double t = (Math.log(Math.max(minM, Math.min(maxM, metres))) - logMin) * perLog;
        double x = t * (STOPS.length - 1);
        int i = Math.min(STOPS.length - 2, Floors.floorInt(x));
        double f = x - i;
        int r = Floors.roundNonNegative(255 * (STOPS[i][0] + f * (STOPS[i + 1][0] - STOPS[i][0])));
        int g = Floors.roundNonNegative(255 * (STOPS[i][1] + f * (STOPS[i + 1][1] - STOPS[i][1])));
        int b = Floors.roundNonNegative(255 * (STOPS[i][2] + f * (STOPS[i + 1][2] - STOPS[i][2])));
        return (r << 16) | (g << 8) | b;
    }

    /**
     * The picture of {@code height} rows of {@code width} distances (metres, row-major from the
     * buffer's position; +∞ or NaN = sky, white), coloured from 100 m to {@code maxMetres} (at least
     * 1 km), with the legend strip below. Pixels take {@link Ramp}'s colours: {@link #colour}'s within one
     * level per channel. The image holds bytes R, G, B per pixel (the PNG writer encodes them 15 % faster
     * than packed ints).
     */
    public static BufferedImage render(java.nio.FloatBuffer distance, int width, int height, double maxMetres) {
        double minM = 100, maxM = Math.max(1000, maxMetres);
        Ramp ramp = new Ramp(minM, maxM);
        java.awt.image.ComponentColorModel model = new java.awt.image.ComponentColorModel(
                java.awt.color.ColorSpace.getInstance(java.awt.color.ColorSpace.CS_sRGB), false, false,
                java.awt.Transparency.OPAQUE, java.awt.image.DataBuffer.TYPE_BYTE);
        java.awt.image.WritableRaster raster = java.awt.image.Raster.createInterleavedRaster(
                java.awt.image.DataBuffer.TYPE_BYTE, width, height + LEGEND_PX, 3 * width, 3, new int[] {0, 1, 2}, null);
        BufferedImage img = new BufferedImage(model, raster, false, null);
        byte[] pixels = ((java.awt.image.DataBufferByte) raster.getDataBuffer()).getData();
        int base = distance.position();
        java.util.stream.IntStream.range(0, height).parallel().forEach(r -> {
            for (int c = 0, i = r * width; c < width; c++, i++) {
                int rgb = ramp.colour(distance.get(base + i));
                pixels[3 * i] = (byte) (rgb >> 16);
                pixels[3 * i + 1] = (byte) (rgb >> 8);
                pixels[3 * i + 2] = (byte) rgb;
            }
        });
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, height, width, LEGEND_PX);
        // The caption left of the bar, the unit right of its last label (they overlapped the bar's ends).
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        String caption = "distance (sky white)";
        int barX = 4 + g.getFontMetrics().stringWidth(caption) + 12, barY = height + 6, barH = 14;
        int barW = Math.max(2, Math.min(width - barX - 40, 1200));
        for (int x = 0; x < barW; x++) {
            double m = Math.exp(Math.log(minM) + (Math.log(maxM) - Math.log(minM)) * x / (barW - 1));
            g.setColor(new Color(colour(m, minM, maxM)));
            g.fillRect(barX + x, barY, 1, barH);
        }
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1));
        for (double km : new double[] {0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500}) {
            double m = km * 1000;
            if (m < minM || m > maxM) {
                continue;
            }
            int x = barX + (int) Math.round((Math.log(m) - Math.log(minM)) / (Math.log(maxM) - Math.log(minM)) * (barW - 1));
            g.drawLine(x, barY + barH, x, barY + barH + 4);
            String label = km < 1 ? String.format(Locale.ROOT, "%.1f", km) : String.format(Locale.ROOT, "%.0f", km);
            g.drawString(label, x - g.getFontMetrics().stringWidth(label) / 2, barY + barH + 17);
        }
        g.drawString("km", barX + barW + 18, barY + barH + 17);
        g.drawString(caption, 4, barY + 11);
        g.dispose();
        return img;
    }
}
