package dempano.terrain;

import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.IntStream;

/**
 * Decides cheaply, from bounds alone, which terrain patches no ray of the panorama can reach: those
 * lying wholly below the horizon that nearer patches already raise, and those wholly below the
 * panorama's bottom edge. Pure arithmetic, no GL.
 *
 * <p>Why it is safe: a patch's footprint is convex, so every vertical ray plane whose azimuth lies
 * within the footprint's azimuth extent crosses it, and the terrain drawn there (interpolating the
 * patch's samples) is nowhere lower than the lowest sample. A ray of that azimuth whose elevation
 * angle is below that terrain's angle hits it (or something nearer) before going farther. So, per
 * azimuth bin, the largest such lower bound over patches wholly nearer than a patch P is a horizon no
 * ray under it passes; if P's upper bound on elevation angle lies under that horizon throughout P's
 * azimuth extent, P is hidden. Angles use the spherical earth (R = 6371 km) with refraction's apparent
 * lift; the margin covers the ellipsoid's departure from it.
 */
public final class HorizonCulling {
    /** Azimuth bins per degree. */
    static final int BINS_PER_DEGREE = 10;
    /** Default safety margin on elevation angles, degrees (the spherical model's error is below 0.03°). */
    public static final double DEFAULT_MARGIN_DEG = 0.1;
    private static final double EARTH_RADIUS_METRES = 6_371_000;
    /** Azimuth slack, degrees: patch edges are not quite straight lines on the ground. */
    private static final double AZIMUTH_SLACK_DEG = 0.02;

    private HorizonCulling() {
    }

    /**
     * Bounds of one patch.
     *
     * @param azimuthMinDeg start of its azimuth extent (clockwise from north), degrees
     * @param azimuthMaxDeg end of the extent, degrees, ≥ start (may exceed 360); an extent of 180° or
     *                      more (the eye inside or beside it) is never culled nor used to cull
     * @param nearMetres    lower bound on the ground distance of its points from the eye
     * @param farMetres     upper bound on that distance
     * @param lowMetres     lower bound on the height of the surface drawn there
     * @param highMetres    upper bound on that height
     */
    public record Bounds(double azimuthMinDeg, double azimuthMaxDeg, double nearMetres, double farMetres, double lowMetres,
                         double highMetres) {
        boolean usable() {
            return azimuthMaxDeg - azimuthMinDeg < 180 && nearMetres > 0 && farMetres >= nearMetres;
        }
    }

    /**
     * Tangent of the elevation angle, seen from an eye at {@code eyeAltitudeMetres}, of a point at
     * ground distance {@code d} and height {@code h}: (h − e − (1 − k)·d²/2R) / d.
     */
    static double tanElevation(double h, double eyeAltitudeMetres, double d, double refractionK) {
        return (h - eyeAltitudeMetres - (1 - refractionK) * d * d / (2 * EARTH_RADIUS_METRES)) / d;
    }

    /** Upper bound on the elevation angle (degrees) of points at heights ≤ h and distances in [near, far]. */
    static double highestAngleDeg(double h, double e, double near, double far, double k) {
        double best = Math.max(tanElevation(h, e, near, k), tanElevation(h, e, far, k));
        double a = h - e, b = (1 - k) / (2 * EARTH_RADIUS_METRES);
        if (a < 0 && b > 0) {
            // (a − b·d²)/d peaks at d* = √(−a/b) when a < 0.
            double peak = Math.sqrt(-a / b);
            if (peak > near && peak < far) {
                best = Math.max(best, tanElevation(h, e, peak, k));
            }
        }
        return Math.toDegrees(Math.atan(best));
    }

    /** Lower bound on the elevation angle (degrees) of points at heights ≥ h and distances in [near, far]. */
    static double lowestAngleDeg(double h, double e, double near, double far, double k) {
        // The function has no interior minimum (it is monotone or peaks inside): the ends bound it.
        return Math.toDegrees(Math.atan(Math.min(tanElevation(h, e, near, k), tanElevation(h, e, far, k))));
    }

    /**
     * Which patches are hidden.
     *
     * @param eyeAltitudeMetres eye altitude, in the heights' datum
     * @param refractionK       refraction coefficient (as the renderer applies it)
     * @param bottomDeg         the panorama's bottom edge, degrees (−90 = none)
     * @param marginDeg         safety margin on angles, degrees
     * @return per patch, true when no ray of the panorama can reach it
     */
    public static boolean[] hidden(List<Bounds> patches, double eyeAltitudeMetres, double refractionK, double bottomDeg,
                                   double marginDeg) {
        int n = patches.size();
        boolean[] hidden = new boolean[n];
        double[] high = new double[n], low = new double[n];
        IntStream.range(0, n).parallel().forEach(i -> {
            Bounds b = patches.get(i);
            high[i] = highestAngleDeg(b.highMetres(), eyeAltitudeMetres, Math.max(b.nearMetres(), 1e-3), b.farMetres(), refractionK);
            low[i] = lowestAngleDeg(b.lowMetres(), eyeAltitudeMetres, Math.max(b.nearMetres(), 1e-3), b.farMetres(), refractionK);
        });
        Integer[] byNear = IntStream.range(0, n).boxed().toArray(Integer[]::new);
        Integer[] byFar = byNear.clone();
        Arrays.sort(byNear, Comparator.comparingDouble(i -> patches.get(i).nearMetres()));
        Arrays.sort(byFar, Comparator.comparingDouble(i -> patches.get(i).farMetres()));
        int bins = 360 * BINS_PER_DEGREE;
        double[] horizon = new double[bins];
        Arrays.fill(horizon, -90);
        int nextOccluder = 0;
        for (int i : byNear) {
            Bounds p = patches.get(i);
            // Raise the horizon by every patch wholly nearer than this one.
            while (nextOccluder < n && patches.get(byFar[nextOccluder]).farMetres() < p.nearMetres()) {
                int q = byFar[nextOccluder++];
                Bounds o = patches.get(q);
                if (!o.usable()) {
                    continue;
                }
                int from = (int) Math.ceil((o.azimuthMinDeg() + AZIMUTH_SLACK_DEG) * BINS_PER_DEGREE);
                int to = (int) Math.floor((o.azimuthMaxDeg() - AZIMUTH_SLACK_DEG) * BINS_PER_DEGREE); // exclusive
                for (int b = from; b < to; b++) {
                    int k = Math.floorMod(b, bins);
                    horizon[k] = Math.max(horizon[k], low[q]);
                }
            }
            if (high[i] + marginDeg < bottomDeg) {
                hidden[i] = true; // wholly below the picture
                continue;
            }
            if (!p.usable()) {
                continue;
            }
            int from = (int) Math.floor((p.azimuthMinDeg() - AZIMUTH_SLACK_DEG) * BINS_PER_DEGREE);
            int to = (int) Math.floor((p.azimuthMaxDeg() + AZIMUTH_SLACK_DEG) * BINS_PER_DEGREE); // inclusive
            boolean below = true;
            for (int b = from; b <= to && below; b++) {
                below = horizon[Math.floorMod(b, bins)] > high[i] + marginDeg;
            }
            hidden[i] = below;
        }
        return hidden;
    }
}
