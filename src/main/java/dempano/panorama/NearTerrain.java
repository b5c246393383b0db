package dempano.panorama;

import java.util.Locale;
import java.util.Optional;

/**
 * How much of the view at and above the horizontal is taken by terrain right beside the eye: the
 * signature of a viewpoint beside the DEM's own summit or ridge (a surveyed summit the 90 m grid
 * rounds off), where a slope a few metres from the eye walls off the distant landscape.
 *
 * @param nearMetres            what counts as near: terrain closer than this, metres
 * @param blockedColumnShare    share of the panorama's columns (azimuths) in which near terrain rises
 *                              {@link #WALL_ELEVATION_DEG} or more above the horizontal, [0, 1]
 * @param blockedPixelShare     share of the pixels at or above the horizontal (row centre elevation
 *                              ≥ 0°) that show near terrain, [0, 1]
 * @param nearestMetres         distance of the nearest terrain pixel at or above the horizontal, metres
 *                              (+∞ when none)
 * @param highestElevationDeg   highest elevation angle of a near terrain pixel, degrees (NaN when none)
 * @param highestAboveEyeMetres height above the eye of that highest near pixel (distance · sin elevation), metres
 * @param spanFromAzimuthDeg    where the longest run of blocked columns starts, degrees clockwise from north (NaN when none)
 * @param spanToAzimuthDeg      where it ends, degrees (may be less than the start when the run crosses north)
 */
public record NearTerrain(double nearMetres, double blockedColumnShare, double blockedPixelShare, double nearestMetres,
                          double highestElevationDeg, double highestAboveEyeMetres, double spanFromAzimuthDeg,
                          double spanToAzimuthDeg) {
    /** Terrain nearer than this is "near", metres. */
    public static final double DEFAULT_NEAR_METRES = 50;
    /**
     * A column is blocked where near terrain rises this far above the horizontal, degrees: a gentle
     * slope a few tens of metres away (the demo scene's viewpoint has one at +1°) hides a sliver of the
     * horizon, a wall beside the eye (+20° at the Dammastock) hides the landscape behind it.
     */
    public static final double WALL_ELEVATION_DEG = 3;
    /**
     * Warn when near terrain blocks at least this share of the azimuths. Measured: 0 at the demo scene's
     * viewpoint, Mt Washington's summit and Nice; 0.35 at the Dammastock's surveyed position beside the
     * DEM's summit, 0 once snapped onto it.
     */
    public static final double WARN_BLOCKED_COLUMN_SHARE = 0.10;

    /** Measures a rendered distance map (row-major, +∞ = sky) on its geometry. */
    public static NearTerrain measure(PanoramaGeometry g, float[] distance, double nearMetres) {
        int w = g.widthPx(), h = g.heightPx();
        double ppd = g.pixelsPerDegree();
        boolean[] blocked = new boolean[w];
        long above = 0, nearPixels = 0;
        int blockedColumns = 0;
        double nearest = Double.POSITIVE_INFINITY, highestEl = Double.NaN, highestUp = Double.NaN;
        for (int r = 0; r < h; r++) {
            double el = g.topElevationDeg() - (r + 0.5) / ppd;
            if (el < 0) {
                break;
            }
            for (int c = 0; c < w; c++) {
                above++;
                float d = distance[r * w + c];
                if (!Float.isFinite(d)) {
                    continue;
                }
                nearest = Math.min(nearest, d);
                if (d < nearMetres) {
                    nearPixels++;
                    blocked[c] |= el >= WALL_ELEVATION_DEG;
                    if (!(el <= highestEl)) {
                        highestEl = el;
                        highestUp = d * Math.sin(Math.toRadians(el));
                    }
                }
            }
        }
        int bestStart = -1, bestLength = 0;
        for (int c = 0; c < w; c++) {
            if (blocked[c]) {
                blockedColumns++;
            }
            if (blocked[c] && !blocked[(c + w - 1) % w]) { // a run starts here
                int length = 0;
                while (length < w && blocked[(c + length) % w]) {
                    length++;
                }
                if (length > bestLength) {
                    bestStart = c;
                    bestLength = length;
                }
            }
        }
        if (blockedColumns == w) {
            bestStart = 0;
            bestLength = w;
        }
        double from = bestStart < 0 ? Double.NaN : PanoramaGeometry.LEFT_AZIMUTH_DEG + bestStart / ppd;
        double to = bestStart < 0 ? Double.NaN : (PanoramaGeometry.LEFT_AZIMUTH_DEG + (bestStart + bestLength) / ppd) % 360;
        return new NearTerrain(nearMetres, w == 0 ? 0 : blockedColumns / (double) w,
                above == 0 ? 0 : nearPixels / (double) above, nearest, highestEl, highestUp, from, to);
    }

    /** Narrowest azimuth bin a camera's view is measured in, degrees (a panorama's columns are its own). */
    static final double CAMERA_AZIMUTH_BIN_DEG = 0.1;

    /**
     * The azimuth bin width for a camera, degrees: {@link #CAMERA_AZIMUTH_BIN_DEG}, or the angle between the
     * image centre's ray and its right-hand neighbour's where that is wider, rounded up so that a whole number
     * of bins makes 360°. A bin narrower than a pixel is reached at its edges only by a few rows' rays (the top
     * corners' of a pitched camera), which look over the near slope; it would then count as open in a view
     * walled off in every azimuth (measured: 4 of 618 bins in CameraLayersTest's uphill case at 0.1°).
     */
    static double cameraBinDeg(dempano.camera.TargetImage target) {
        double cx = (target.widthPx() - 1) / 2.0, cy = (target.heightPx() - 1) / 2.0;
        double[] a = target.rayOf(cx, cy), b = target.rayOf(cx + 1, cy);
        double pixelDeg = Math.toDegrees(Math.acos(Math.min(1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
        double wanted = Double.isFinite(pixelDeg) ? Math.max(CAMERA_AZIMUTH_BIN_DEG, pixelDeg) : CAMERA_AZIMUTH_BIN_DEG;
        return 360.0 / Math.floor(360 / wanted);
    }

    /**
     * Measures a camera's (or any target image's) distance map: each pixel's own ray gives its azimuth and elevation;
     * the azimuths are binned ({@link #cameraBinDeg}) and {@code blockedColumnShare} is the share of the
     * bins the view covers at or above the horizontal in which near terrain rises {@link #WALL_ELEVATION_DEG} or
     * more. {@code blockedPixelShare} counts the view's pixels at or above the horizontal.
     *
     * @param distance metres per pixel, row-major, +∞ sky, NaN without a ray
     */
    public static NearTerrain measure(dempano.camera.TargetImage target, float[] distance, double nearMetres) {
        double binDeg = cameraBinDeg(target);
        int w = target.widthPx(), h = target.heightPx(), bins = (int) Math.round(360 / binDeg);
        boolean[] covered = new boolean[bins], blocked = new boolean[bins];
        long above = 0, nearPixels = 0;
        double nearest = Double.POSITIVE_INFINITY, highestEl = Double.NaN, highestUp = Double.NaN;
        double[] ray = new double[3];
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                target.rayOf(c, r, ray);
                if (Double.isNaN(ray[0]) || ray[2] < 0) {
                    continue;
                }
                double el = Math.toDegrees(Math.atan2(ray[2], Math.hypot(ray[0], ray[1])));
                double az = Math.toDegrees(Math.atan2(ray[0], ray[1]));
                int bin = Math.floorMod((int) Math.floor(az / binDeg), bins);
                covered[bin] = true;
                above++;
                float d = distance[r * w + c];
                if (!Float.isFinite(d)) {
                    continue;
                }
                nearest = Math.min(nearest, d);
                if (d < nearMetres) {
                    nearPixels++;
                    blocked[bin] |= el >= WALL_ELEVATION_DEG;
                    if (!(el <= highestEl)) {
                        highestEl = el;
                        highestUp = d * Math.sin(Math.toRadians(el));
                    }
                }
            }
        }
        // The covered bins in azimuth order, starting after the widest gap between them (a camera's view does not
        // wrap unless it covers north); between columns' rays lie uncovered bins, which neither end nor make a run.
        int[] order = new int[bins];
        int coveredBins = 0, blockedBins = 0;
        for (int b = 0; b < bins; b++) {
            if (covered[b]) {
                order[coveredBins++] = b;
                blockedBins += blocked[b] ? 1 : 0;
            }
        }
        int first = 0, widestGap = -1;
        for (int k = 0; k < coveredBins; k++) {
            int gap = Math.floorMod(order[(k + 1) % coveredBins] - order[k], bins);
            if (gap > widestGap) {
                widestGap = gap;
                first = (k + 1) % coveredBins;
            }
        }
        int bestStart = -1, bestEnd = -1, runStart = -1, bestLength = 0;
        for (int k = 0; k < coveredBins; k++) {
            int b = order[(first + k) % coveredBins];
            if (!blocked[b]) {
                runStart = -1;
                continue;
            }
            if (runStart < 0) {
                runStart = b;
            }
            int length = Math.floorMod(b - runStart, bins) + 1;
            if (length > bestLength) {
                bestLength = length;
                bestStart = runStart;
                bestEnd = b;
            }
        }
        double from = bestStart < 0 ? Double.NaN : bestStart * binDeg;
        double to = bestStart < 0 ? Double.NaN : ((bestEnd + 1) * binDeg) % 360;
        return new NearTerrain(nearMetres, coveredBins == 0 ? 0 : blockedBins / (double) coveredBins,
                above == 0 ? 0 : nearPixels / (double) above, nearest, highestEl, highestUp, from, to);
    }

    /**
     * The warning for a camera (its azimuths, not all 360°; the panorama's viewpoint options do not apply to a
     * camera's pose), when near terrain blocks at least {@link #WARN_BLOCKED_COLUMN_SHARE} of them; empty otherwise.
     */
    public Optional<String> cameraWarning() {
        if (!(blockedColumnShare >= WARN_BLOCKED_COLUMN_SHARE)) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT,
                "terrain nearer than %.0f m rises %.0f° or more above the horizontal in %.0f %% of the camera's azimuths"
                        + " (longest run %.1f°–%.1f°) and fills %.1f %% of its view above the horizontal: the nearest is %.1f m"
                        + " from the eye, rising to %+.1f° (%.1f m above the eye). The camera probably stands beside the"
                        + " DEM's own summit or ridge (a surveyed position the 90 m grid rounds off): raise it"
                        + " (--offset-m, --altitude-m) or move it onto the DEM's summit",
                nearMetres, WALL_ELEVATION_DEG, 100 * blockedColumnShare, spanFromAzimuthDeg, spanToAzimuthDeg,
                100 * blockedPixelShare, nearestMetres, highestElevationDeg, highestAboveEyeMetres));
    }

    /**
     * The warning for the user when near terrain blocks at least {@link #WARN_BLOCKED_COLUMN_SHARE}
     * of the azimuths, with the figures and the options that move the eye; empty otherwise.
     */
    public Optional<String> warning() {
        if (!(blockedColumnShare >= WARN_BLOCKED_COLUMN_SHARE)) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT,
                "terrain nearer than %.0f m rises %.0f° or more above the horizontal in %.0f %% of the azimuths"
                        + " (longest run %.0f°–%.0f°) and fills %.1f %% of the view above the horizontal: the nearest is %.1f m"
                        + " from the eye, rising to %+.1f° (%.1f m above the eye). The viewpoint is probably beside"
                        + " the DEM's own summit or ridge: --snap-to-summit-m R moves it to the highest DEM point"
                        + " within R metres, --clear-view-m R raises the eye above the terrain within R metres,"
                        + " --offset-m raises it by hand",
                nearMetres, WALL_ELEVATION_DEG, 100 * blockedColumnShare, spanFromAzimuthDeg, spanToAzimuthDeg, 100 * blockedPixelShare,
                nearestMetres, highestElevationDeg, highestAboveEyeMetres));
    }
}
