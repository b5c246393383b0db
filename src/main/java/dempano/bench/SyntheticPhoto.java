package dempano.bench;

import dempano.camera.CameraIntrinsics;
import dempano.camera.CameraOrientation;
import dempano.camera.CameraView;
import dempano.dem.TileId;
import dempano.panorama.Layer;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Random;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Synthetic photos for the orientation benchmark: a pinhole camera's view resampled (bilinear) from a CPU
 * reference panorama (colour and distance), made harder in cumulative steps.
 */
final class SyntheticPhoto {
    /** Difficulty steps; each adds to the ones before. */
    enum Step {
        CLEAR("clear"),
        HAZE("+ haze, sky gradient"),
        NOISE_JPEG("+ noise σ 6, JPEG q70"),
        OCCLUDERS("+ 30 % of skyline hidden"),
        CLOUDS("+ clouds on the ridges");

        final String label;

        Step(String label) {
            this.label = label;
        }
    }

    /** Haze: terrain colour pulled toward the haze colour by 1 − exp(−d / this), metres. */
    static final double HAZE_METRES = 25_000;

    private SyntheticPhoto() {
    }

    /** The photo of a pose at one step; {@code seed} fixes the occluders, clouds and noise (same for every step). */
    static BufferedImage render(Panorama ref, int w, int h, CameraOrientation o, double hfovDeg, Step step, long seed) {
        PanoramaGeometry g = ref.geometry();
        CameraView view = new CameraView(CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg), o);
        float[] dist = ref.distanceArray();
        int pw = g.widthPx(), ph = g.heightPx();
        double ppd = g.pixelsPerDegree();
        boolean haze = step.ordinal() >= Step.HAZE.ordinal();
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        boolean[] sky = new boolean[w * h];
        int[] skyline = new int[w];
        java.util.Arrays.fill(skyline, -1);
        double[] ray = new double[3];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                view.rayOf(i, j, ray);
                double az = Math.toDegrees(Math.atan2(ray[0], ray[1]));
                double el = Math.toDegrees(Math.atan2(ray[2], Math.hypot(ray[0], ray[1])));
                double x = dempano.geo.Angles.wrap360(az) * ppd - 0.5, y = (g.topElevationDeg() - el) * ppd - 0.5;
                int x0 = (int) Math.floor(x), y0 = (int) Math.floor(y);
                double tx = x - x0, ty = y - y0;
                double r = 0, gg = 0, b = 0;
                for (int k = 0; k < 4; k++) {
                    int xx = Math.floorMod(x0 + (k & 1), pw), yy = Math.max(0, Math.min(ph - 1, y0 + (k >> 1)));
                    double wk = ((k & 1) == 1 ? tx : 1 - tx) * ((k >> 1) == 1 ? ty : 1 - ty);
                    int c = ref.argb(xx, yy);
                    double d = dist[yy * pw + xx];
                    double cr = (c >> 16) & 0xff, cg = (c >> 8) & 0xff, cb = c & 0xff;
                    if (haze) {
                        if (!Double.isFinite(d)) {
                            double s = Math.max(0, Math.min(1, el / 40));
                            cr = 205 - 135 * s;
                            cg = 218 - 98 * s;
                            cb = 232 - 32 * s;
                        } else {
                            double a = 1 - Math.exp(-d / HAZE_METRES);
                            cr += (200 - cr) * a;
                            cg += (210 - cg) * a;
                            cb += (224 - cb) * a;
                        }
                    }
                    r += wk * cr;
                    gg += wk * cg;
                    b += wk * cb;
                }
                int nx = Math.floorMod((int) Math.round(x), pw), ny = Math.max(0, Math.min(ph - 1, (int) Math.round(y)));
                sky[j * w + i] = !Float.isFinite(dist[ny * pw + nx]);
                if (!sky[j * w + i] && skyline[i] < 0) {
                    skyline[i] = j;
                }
                img.setRGB(i, j, ((int) r << 16) | ((int) gg << 8) | (int) b);
            }
        }
        Random rnd = new Random(seed);
        if (step.ordinal() >= Step.CLOUDS.ordinal()) {
            clouds(img, sky, skyline, new Random(seed * 31 + 7));
        }
        if (step.ordinal() >= Step.OCCLUDERS.ordinal()) {
            occluders(img, skyline, new Random(seed * 17 + 3));
        }
        if (step.ordinal() >= Step.NOISE_JPEG.ordinal()) {
            img = jpeg(noise(img, rnd, 6), 0.7f);
        }
        return img;
    }

    /** Share of columns where the photo shows sky at the top and land at the bottom (the skyline crosses them). */
    static double skylineShare(Panorama ref, int w, int h, CameraOrientation o, double hfovDeg) {
        CameraView view = new CameraView(CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg), o);
        int crossing = 0;
        double[] ray = new double[3];
        for (int i = 0; i < w; i += 4) {
            view.rayOf(i, 0, ray);
            boolean topSky = !Double.isFinite(sample(ref, ray));
            view.rayOf(i, h - 1, ray);
            boolean bottomLand = Double.isFinite(sample(ref, ray));
            crossing += topSky && bottomLand ? 1 : 0;
        }
        return crossing / Math.ceil(w / 4.0);
    }

    /** How far (degrees of latitude and of longitude) terrain shown must stay from a missing tile. */
    static final double MISSING_DATA_MARGIN_DEG = 0.01;

    /**
     * Where the reference panorama's terrain lies on missing DEM data. A missing tile is drawn as sea level, so
     * a photo that sees it shows the data's edge (a cliff down to a plain), not the landscape.
     */
    static final class MissingData {
        private final Panorama ref;
        private final float[] distance, lat, lon;
        private final java.util.function.Predicate<TileId> present;

        /**
         * @param ref     the reference panorama, with its {@link Layer#LATITUDE} and {@link Layer#LONGITUDE} layers
         * @param present whether a tile has data
         */
        MissingData(Panorama ref, java.util.function.Predicate<TileId> present) {
            this.ref = ref;
            this.distance = ref.distanceArray();
            this.lat = ref.layer(Layer.LATITUDE);
            this.lon = ref.layer(Layer.LONGITUDE);
            this.present = present;
        }

        /**
         * Share of a photo's columns (every 4th) that show terrain on missing data: a sample of the terrain
         * seen (the column's first terrain pixel, the skyline, and every 8th pixel below it) lying in a missing
         * tile or within {@value SyntheticPhoto#MISSING_DATA_MARGIN_DEG}° (about 1 km) of one.
         */
        double share(int w, int h, CameraOrientation o, double hfovDeg) {
            CameraView view = new CameraView(CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg), o);
            double[] ray = new double[3];
            int columns = 0, onMissing = 0;
            for (int i = 0; i < w; i += 4) {
                columns++;
                boolean skyline = true;
                for (int j = 0; j < h; j++) {
                    view.rayOf(i, j, ray);
                    int k = pixelOf(ref, ray);
                    if (k < 0 || !Float.isFinite(distance[k])) {
                        continue;
                    }
                    if (skyline || j % 8 == 0) {
                        skyline = false;
                        if (nearMissing(lat[k], lon[k], present)) {
                            onMissing++;
                            break;
                        }
                    }
                }
            }
            return onMissing / (double) columns;
        }
    }

    private static boolean nearMissing(double latDeg, double lonDeg, java.util.function.Predicate<TileId> present) {
        double m = MISSING_DATA_MARGIN_DEG;
        for (double dLat = -m; dLat <= m; dLat += m) {
            for (double dLon = -m; dLon <= m; dLon += m) {
                if (!present.test(TileId.containing(latDeg + dLat, lonDeg + dLon))) { // (containing wraps the longitude)
                    return true;
                }
            }
        }
        return false;
    }

    /** {@link #pixelOf} of a ray above the panorama's top row, and below its bottom row. */
    private static final int ABOVE = -1, BELOW = -2;

    /** The panorama pixel (row-major index) a ray falls on; {@link #ABOVE} or {@link #BELOW} outside the panorama. */
    private static int pixelOf(Panorama ref, double[] ray) {
        double az = Math.toDegrees(Math.atan2(ray[0], ray[1]));
        double el = Math.toDegrees(Math.atan2(ray[2], Math.hypot(ray[0], ray[1])));
        PanoramaGeometry g = ref.geometry();
        int c = Math.floorMod((int) Math.floor(g.columnOf(az)), g.widthPx());
        int r = (int) Math.floor(g.rowOf(el));
        return r < 0 ? ABOVE : r >= g.heightPx() ? BELOW : r * g.widthPx() + c;
    }

    /** The distance a ray sees: +∞ above the panorama (sky), 0 below it (the ground at the camera's feet). */
    private static double sample(Panorama ref, double[] ray) {
        int k = pixelOf(ref, ray);
        return k == ABOVE ? Double.POSITIVE_INFINITY : k == BELOW ? 0 : ref.distanceMetres(k % ref.widthPx(), k / ref.widthPx());
    }

    /**
     * Median distance of the skyline's terrain over the photo's columns (every 4th), metres: per column, the distance
     * of the first terrain pixel from the top. A near skyline (a slope the camera stands on) is a smooth line with
     * nothing to match; columns without terrain are left out; NaN when none has any.
     */
    static double skylineDistanceMetres(Panorama ref, int w, int h, CameraOrientation o, double hfovDeg) {
        CameraView view = new CameraView(CameraIntrinsics.fromHorizontalFov(w, h, hfovDeg), o);
        java.util.List<Double> d = new java.util.ArrayList<>();
        double[] ray = new double[3];
        for (int i = 0; i < w; i += 4) {
            for (int j = 0; j < h; j++) {
                view.rayOf(i, j, ray);
                double v = sample(ref, ray);
                if (Double.isFinite(v)) {
                    d.add(v);
                    break;
                }
            }
        }
        if (d.isEmpty()) {
            return Double.NaN;
        }
        java.util.Collections.sort(d);
        return d.get(d.size() / 2);
    }

    /** Foreground shapes over 30 % of the columns (3 of 10 slots), reaching 8–45 px above the skyline. */
    private static void occluders(BufferedImage img, int[] skyline, Random rnd) {
        int w = img.getWidth(), h = img.getHeight();
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        java.util.List<Integer> slots = new java.util.ArrayList<>();
        for (int s = 0; s < 10; s++) {
            slots.add(s);
        }
        java.util.Collections.shuffle(slots, rnd);
        for (int k = 0; k < 3; k++) {
            int x0 = slots.get(k) * w / 10, x1 = (slots.get(k) + 1) * w / 10;
            int top = h;
            for (int x = x0; x < x1; x++) {
                top = Math.min(top, skyline[x] < 0 ? h : skyline[x]);
            }
            top = Math.max(2, top - 8 - rnd.nextInt(38));
            boolean tree = rnd.nextBoolean();
            g.setColor(tree ? new Color(28 + rnd.nextInt(20), 55 + rnd.nextInt(30), 25 + rnd.nextInt(15))
                    : new Color(80 + rnd.nextInt(40), 78 + rnd.nextInt(30), 75 + rnd.nextInt(30)));
            if (tree) {
                g.fill(new RoundRectangle2D.Double(x0, top, x1 - x0, h - top + 20, x1 - x0, x1 - x0));
                g.fill(new Ellipse2D.Double(x0 - 3, top + 5, x1 - x0 + 6, (x1 - x0) * 0.8));
            } else {
                g.fillRect(x0, top, x1 - x0, h - top);
            }
        }
        g.dispose();
    }

    /** 2–4 clouds on the skyline, painted on sky pixels only (so that they sit behind the ridges, touching them). */
    private static void clouds(BufferedImage img, boolean[] sky, int[] skyline, Random rnd) {
        int w = img.getWidth(), h = img.getHeight();
        int n = 2 + rnd.nextInt(3);
        float[] alpha = new float[w * h];
        for (int c = 0; c < n; c++) {
            int cx = rnd.nextInt(w);
            int base = skyline[cx] < 0 ? h / 2 : skyline[cx];
            for (int blob = 0; blob < 5; blob++) {
                double bx = cx + rnd.nextGaussian() * w * 0.04, by = base - 5 - rnd.nextDouble() * 20;
                double rx = w * (0.03 + 0.05 * rnd.nextDouble()), ry = rx * (0.4 + 0.3 * rnd.nextDouble());
                for (int y = Math.max(0, (int) (by - ry)); y < Math.min(h, by + ry); y++) {
                    for (int x = Math.max(0, (int) (bx - rx)); x < Math.min(w, bx + rx); x++) {
                        double q = Math.pow((x - bx) / rx, 2) + Math.pow((y - by) / ry, 2);
                        if (q < 1) {
                            alpha[y * w + x] = Math.max(alpha[y * w + x], (float) Math.min(0.92, 1.6 * (1 - q)));
                        }
                    }
                }
            }
        }
        for (int i = 0; i < w * h; i++) {
            if (sky[i] && alpha[i] > 0) {
                int c = img.getRGB(i % w, i / w);
                double a = alpha[i], v = 236;
                int r = (int) (((c >> 16) & 0xff) * (1 - a) + v * a), gg = (int) (((c >> 8) & 0xff) * (1 - a) + v * a),
                        b = (int) ((c & 0xff) * (1 - a) + (v + 6) * a);
                img.setRGB(i % w, i / w, (r << 16) | (gg << 8) | Math.min(255, b));
            }
        }
    }

    private static BufferedImage noise(BufferedImage img, Random rnd, double sigma) {
        int w = img.getWidth(), h = img.getHeight();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int c = img.getRGB(x, y), v = 0;
                for (int s = 16; s >= 0; s -= 8) {
                    int ch = (int) Math.round(((c >> s) & 0xff) + sigma * rnd.nextGaussian());
                    v |= Math.max(0, Math.min(255, ch)) << s;
                }
                out.setRGB(x, y, v);
            }
        }
        return out;
    }

    static BufferedImage jpeg(BufferedImage img, float quality) {
        try {
            ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            try (MemoryCacheImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
                writer.setOutput(out);
                ImageWriteParam p = writer.getDefaultWriteParam();
                p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                p.setCompressionQuality(quality);
                writer.write(null, new IIOImage(img, null, null), p);
            }
            writer.dispose();
            return ImageIO.read(new ByteArrayInputStream(bytes.toByteArray()));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
