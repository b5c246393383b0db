package dempano.terrain;

import dempano.dem.Triangulation;

/**
 * Level of detail chosen from the error it causes on screen. A square patch of the mosaic grid may be
 * drawn with every {@code step}-th sample only; the coarse surface then departs from the full one by
 * at most {@link #deviationsMetres deviation(step)} metres vertically, which a viewer at distance
 * {@code d} sees as at most {@code deviation / d} radians. The coarsest step whose angle stays within
 * a bound in pixels is chosen. Pure arithmetic, no GL.
 *
 * <p>The angle alone does not bound the distance: a vertical error δ on a surface that a ray meets at
 * incidence θ moves the hit along the ray by about δ / sin θ, and ground seen from a low eye is seen
 * at grazing incidence. {@link #chooseLevel(double[], Sight, double, double, double)} also bounds the
 * relative distance error δ / (d · sin θ) on level ground, by {@link #DEFAULT_MAX_DISTANCE_ERROR} by
 * default, with θ the {@link #sinIncidenceLowerBound incidence} at which the eye sees the patch's
 * level ground.
 */
public final class LevelOfDetail {
    /** Default bound on the screen error of simplified terrain, panorama pixels. */
    public static final double DEFAULT_MAX_ERROR_PX = 0.5;
    /**
     * Default bound on the relative distance error that simplified ground may cause (a fraction of
     * the distance): 0.002 = 0.2 %, a worst case per pixel (a facet's sag runs from 0 at its corners
     * to its most inside), a fifth of the accuracy targets' 1 % p99. Measured on the open sea from
     * 100 m (20 px/°, refraction 0, rows ≥ 3 below the horizon, against the ray–ellipsoid distance):
     * median 1.4e-4 and p99 1.3e-3 (full resolution: 1.2e-5 and 6.9e-4; the angle alone: 4.0e-3 and
     * 1.1e-2); 0.001 gives 1.3e-4 and 9.2e-4 with 30 % more triangles on the sea, 0.005 gives 5.0e-4
     * and 1.3e-3. On rugged land (Mount Washington, Provence at 100 km) 0.001 to 0.005 draw the same
     * triangles: the patches the bound refines have metres of relief lost at every coarse level.
     */
    public static final double DEFAULT_MAX_DISTANCE_ERROR = 0.002;
    /**
     * The smallest radius of curvature of the WGS84 ellipsoid (meridional, at the equator:
     * a(1 − e²)), metres: the earth curves away from a tangent plane at most this fast.
     */
    static final double MIN_RADIUS_OF_CURVATURE_METRES = 6_335_439;

    private LevelOfDetail() {
    }

    /**
     * The largest vertical deviation, in metres, of the surface drawn with every {@code 2^level}-th
     * sample from the full-resolution surface, measured at the full-resolution samples, for levels
     * 0 (= 0 m) to log2(intervals).
     *
     * @param heights   heights (metres), row-major, {@code stride} samples per row
     * @param row0      first row of the patch in {@code heights}
     * @param col0      first column of the patch
     * @param intervals cells per patch side, a power of two
     */
    public static double[] deviationsMetres(float[] heights, int stride, int row0, int col0, int intervals) {
        if (Integer.bitCount(intervals) != 1) {
            throw new IllegalArgumentException("patch side must be a power of two, got " + intervals);
        }
        int levels = Integer.numberOfTrailingZeros(intervals);
        double[] dev = new double[levels + 1];
        // Coarse cell by coarse cell (a sample on a cell's east or south edge belongs to the next cell, except on
        // the patch's own edge), with the cell's corners and split read once: the same arithmetic, value for
        // value, as Triangulation.height at every sample (the largest of the same numbers), without a division per sample.
        double[] fraction = new double[intervals + 1];
        for (int level = 1; level <= levels; level++) {
            int s = 1 << level, cells = intervals / s;
            for (int k = 0; k <= s; k++) {
                fraction[k] = k / (double) s;
            }
            double worst = 0;
            for (int ci = 0; ci < cells; ci++) {
                int lastA = ci == cells - 1 ? s : s - 1;
                int rn = row0 + ci * s, rs = rn + s;
                for (int cj = 0; cj < cells; cj++) {
                    int lastB = cj == cells - 1 ? s : s - 1;
                    int cw = col0 + cj * s, ce = cw + s;
                    double nw = heights[rn * stride + cw], ne = heights[rn * stride + ce];
                    double sw = heights[rs * stride + cw], se = heights[rs * stride + ce];
                    boolean nwToSe = Triangulation.splitsNorthWestToSouthEast(ci, cj);
                    for (int a = 0; a <= lastA; a++) {
                        double v = fraction[a];
                        int at = (rn + a) * stride + cw;
                        // Triangulation.height's two cases with the split hoisted out of the loop, written out: the
                        // client compiler (a panorama's only one) does not inline that method, and the call made the
                        // deviations 25 % slower (30 → 38 ms for 256 patches of 64 cells). LevelOfDetailTest checks
                        // these against Triangulation.height value for value.
                        if (nwToSe) {
                            for (int b = 0; b <= lastB; b++) {
                                double u = fraction[b];
                                double coarse = u >= v ? nw + u * (ne - nw) + v * (se - ne) : nw + v * (sw - nw) + u * (se - sw);
                                worst = Math.max(worst, Math.abs(heights[at + b] - coarse));
                            }
                        } else {
                            for (int b = 0; b <= lastB; b++) {
                                double u = fraction[b];
                                double coarse = u + v <= 1 ? nw + u * (ne - nw) + v * (sw - nw)
                                        : se + (1 - u) * (sw - se) + (1 - v) * (ne - se);
                                worst = Math.max(worst, Math.abs(heights[at + b] - coarse));
                            }
                        }
                    }
                }
            }
            dev[level] = worst;
        }
        return dev;
    }

    /**
     * How far a flat coarse cell lies from the curved earth it spans: the sag of a chord across the
     * cell's diagonal (√2 · side), d²/8R, with refraction's apparent flattening (R/(1−k)) counted only
     * when it enlarges the sag (k < 0).
     *
     * @param cellSideMetres side of the coarse cell, metres (the longer of its two sides)
     */
    public static double chordSagMetres(double cellSideMetres, double refractionCoefficient) {
        double diagonal = Math.sqrt(2) * cellSideMetres;
        return diagonal * diagonal / (8 * 6_356_000.0) * Math.max(1, 1 - refractionCoefficient);
    }

    /**
     * The level (step = 2^level) to draw a patch with.
     *
     * @param deviationsMetres from {@link #deviationsMetres}
     * @param nearestMetres    distance from the eye to the patch's nearest point
     * @param pixelsPerDegree  panorama resolution
     * @param maxErrorPx       bound on the screen error; 0 or less = always full resolution
     */
    public static int chooseLevel(double[] deviationsMetres, double nearestMetres, double pixelsPerDegree,
                                  double maxErrorPx) {
        if (!(maxErrorPx > 0)) {
            return 0;
        }
        double allowedMetres = maxErrorPx / pixelsPerDegree * Math.PI / 180 * Math.max(nearestMetres, 0);
        int level = 0;
        for (int l = 1; l < deviationsMetres.length; l++) {
            if (deviationsMetres[l] <= allowedMetres) {
                level = l;
            } else {
                break; // finer levels must hold the bound too, so stop at the first that does not
            }
        }
        return level;
    }

    /**
     * How the eye sees a patch, for {@link #chooseLevel(double[], Sight, double, double, double)}.
     * Heights are above sea level (the DEM's datum), distances horizontal, all in metres.
     *
     * @param nearestMetres         horizontal distance from the eye to the patch's nearest point (a lower bound)
     * @param farthestMetres        to its farthest point (an upper bound), ≥ {@code nearestMetres}
     * @param highestMetres         the patch's highest sample
     * @param riseAwayFromEye       a lower bound of how steeply every facet of the patch rises away from the
     *                              eye (the gradient's component along the horizontal direction of the
     *                              line of sight, metres per metre); 0 or less = some facet is level or
     *                              turned away (only a positive rise counts: the patch faces the eye)
     * @param eyeAltitudeMetres     the eye's altitude
     * @param refractionCoefficient k: light bends with the earth, which then looks flatter, radius R/(1 − k)
     */
    public record Sight(double nearestMetres, double farthestMetres, double highestMetres,
                        double riseAwayFromEye, double eyeAltitudeMetres, double refractionCoefficient) {
    }

    /**
     * A lower bound of sin α, α the angle at which a straight ray (with refraction: on the apparent
     * earth of radius R/(1 − k)) from an eye at altitude H descends below the local horizontal of
     * ground at height h at horizontal distance d > 0: the incidence on level ground there.
     * <pre>  sin α ≈ (H − h) / d − d (1 − k) / 2R</pre>
     * The first term is the line of sight's depression below the eye's horizontal; the earth's
     * curvature tilts the ground's horizontal at distance d by d/R the other way, so the ray meets it
     * flatter by that (the eye's depression, (H − h)/d + d/2R, less the tilt d/R). It is 0 at the
     * horizon of that ground and negative beyond it, or where the ground is above the eye (level
     * ground there cannot be seen). R is {@link #MIN_RADIUS_OF_CURVATURE_METRES}, which makes the
     * bound lower still. Exact to second order: d · sin α is the height of the eye above the ground's
     * tangent plane less the ground's drop, (H − h) − d²(1 − k)/2R.
     *
     * @param eyeAltitudeMetres     H
     * @param groundMetres          h
     * @param distanceMetres        d, horizontal; 0 gives +∞ below the eye, −∞ at or above it
     * @param refractionCoefficient k (any value; k ≥ 1 flattens or inverts the apparent curvature)
     */
    public static double sinIncidenceLowerBound(double eyeAltitudeMetres, double groundMetres, double distanceMetres,
                                                double refractionCoefficient) {
        double below = eyeAltitudeMetres - groundMetres;
        if (!(distanceMetres > 0)) {
            return below > 0 ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        }
        return below / distanceMetres
                - distanceMetres * (1 - refractionCoefficient) / (2 * MIN_RADIUS_OF_CURVATURE_METRES);
    }

    /**
     * The least of {@link #sinIncidenceLowerBound} over distances in [near, far] for ground at one
     * height: f(d) = A/d − κd is monotonic, or has its one turning point at √(−A/κ).
     */
    private static double leastOverDistance(double eye, double ground, double near, double far, double k) {
        double least = Math.min(sinIncidenceLowerBound(eye, ground, near, k), sinIncidenceLowerBound(eye, ground, far, k));
        double turn = Math.sqrt(-(eye - ground) / ((1 - k) / (2 * MIN_RADIUS_OF_CURVATURE_METRES)));
        if (turn > near && turn < far) {
            least = Math.min(least, sinIncidenceLowerBound(eye, ground, turn, k));
        }
        return least;
    }

    /**
     * What a vertical error δ becomes along a ray that descends at α below the ground's horizontal,
     * over ground rising at s (tan of the slope along the ray's horizontal direction, away from the
     * eye): the hit moves by δ / (sin α + s cos α), which is δ / sin θ on level ground (θ the
     * incidence; a lateral slope tilts the normal but cancels out). For s ≥ 0 and any α' ≥ α this
     * divisor is at least min(1, sin α + s cos α) (it is concave in α where positive), so the value at
     * the lowest α bounds it below.
     */
    static double divisorLowerBound(double sinAlpha, double rise) {
        double sa = Math.max(-1, Math.min(1, sinAlpha));
        return Math.min(1, sa + Math.max(0, rise) * Math.sqrt(1 - sa * sa));
    }

    /**
     * The vertical deviation, metres, that a patch may have so that the relative distance error
     * δ / (d · (sin α + s cos α)) ({@link #divisorLowerBound}) stays within {@code maxDistanceError}:
     * ε · d_near · q_min, with q_min the divisor's lower bound for the patch's highest sample at the
     * least favourable distance and s the patch's {@linkplain Sight#riseAwayFromEye rise away from the
     * eye} (0 for level or mixed ground, whose worst part is taken as level).
     *
     * <p>Exception near the horizon: ground seen with q below one panorama pixel
     * ({@code sin(1 / pixelsPerDegree degrees)}) is excepted, because there no level of detail can
     * hold the bound (q → 0 at the horizon). A ray a pixel p below the horizon of level ground
     * (depression α_h at the eye) meets it at sin θ = √(α² − α_h²) with α = α_h + p, which is ≥ p:
     * the exception lies within the horizon row. A patch reaching the floor is bound where it is seen
     * above it: by floor · d* (d* where its highest level ground meets the floor; exact for a flat patch
     * such as the sea) or floor · d_near. A patch whose highest sample is seen below the floor already at
     * its nearest point (terrain reaching the eye's altitude that does not face it, or lying beyond its
     * horizon) gets no distance bound (+∞) at all, its lower ground included: mountains around an eye
     * in a valley would otherwise be drawn at full resolution for their grazing parts, which are their
     * silhouettes. The angular bound serves them.
     *
     * <p>Not a strict bound for slopes turned away from the eye within a patch that also holds level
     * ground (they are seen flatter than level ground, down to 0 at their silhouettes, as at the
     * horizon): those too are left to the angular bound.
     *
     * @param maxDistanceError ε, a fraction; 0 or less (or NaN) = no distance bound (+∞)
     * @return metres, ≥ 0, or +∞ where the distance does not constrain the level
     */
    public static double allowedDeviationForDistanceMetres(Sight sight, double pixelsPerDegree, double maxDistanceError) {
        if (!(maxDistanceError > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        double floor = Math.sin(Math.toRadians(1 / pixelsPerDegree));
        double k = sight.refractionCoefficient(), eye = sight.eyeAltitudeMetres(), rise = sight.riseAwayFromEye();
        double near = Math.max(0, sight.nearestMetres()), far = Math.max(near, sight.farthestMetres());
        double high = sight.highestMetres();
        if (!(divisorLowerBound(sinIncidenceLowerBound(eye, high, near, k), rise) >= floor)) {
            return Double.POSITIVE_INFINITY; // its highest ground is grazing from its nearest point on: excepted
        }
        double worst = divisorLowerBound(leastOverDistance(eye, high, near, far, k), rise);
        if (worst >= floor) {
            // The relative error δ / (d · q) at any point of the patch is at most δ / (d_near · q_min).
            return maxDistanceError * near * worst;
        }
        // The patch reaches the grazing floor at d*. Level ground (no rise) below the eye: d · q = (H − h)
        // − κd² falls with d, so d*'s value, floor · d*, bounds the rest; otherwise floor · d_near.
        double kappa = (1 - k) / (2 * MIN_RADIUS_OF_CURVATURE_METRES), above = eye - high;
        double reach = near;
        if (rise <= 0 && above > 0 && kappa > 0) {
            reach = Math.max(near, 2 * above / (floor + Math.sqrt(floor * floor + 4 * kappa * above)));
        }
        return maxDistanceError * reach * floor;
    }

    /**
     * The level (step = 2^level) to draw a patch with: the coarsest whose deviation (raw deviation
     * and chord sag) holds both the angular bound ({@link #chooseLevel(double[], double, double, double)})
     * and the distance bound ({@link #allowedDeviationForDistanceMetres}). With maxErrorPx ≤ 0 the
     * patch is drawn at full resolution; where the distance bound cannot hold even there (the patch
     * under the eye), full resolution is what it gets: the bound is then what it is.
     *
     * @param deviationsMetres  from {@link #deviationsMetres}, with chord sag added per level
     * @param pixelsPerDegree   panorama resolution
     * @param maxErrorPx        bound on the screen error; 0 or less = always full resolution
     * @param maxDistanceError  bound on the relative distance error (a fraction); 0 or less = none
     */
    public static int chooseLevel(double[] deviationsMetres, Sight sight, double pixelsPerDegree, double maxErrorPx,
                                  double maxDistanceError) {
        int angular = chooseLevel(deviationsMetres, sight.nearestMetres(), pixelsPerDegree, maxErrorPx);
        double allowedMetres = allowedDeviationForDistanceMetres(sight, pixelsPerDegree, maxDistanceError);
        int level = 0;
        while (level < angular && deviationsMetres[level + 1] <= allowedMetres) {
            level++;
        }
        return level;
    }

    /**
     * A lower bound of how steeply every facet of a patch rises away from an eye
     * ({@link Sight#riseAwayFromEye}), from bounds of the patch's height steps and the directions from
     * the eye to its corners; 0 where some facet may be level or turned away, or the eye is within
     * the patch. Every facet's gradient (drawn at any level: a coarse facet's steps average fine
     * ones) lies in the box of the steps, so the least rise over box corners and corner directions
     * bounds it (a linear function over a box; over an arc of directions under 180° the least value is
     * at an end, or is negative). The directions are taken in the patch's own east-north plane, which
     * turns by at most a few degrees against the true azimuths within 100s of km; that error is
     * taken off as {@code directionSlackRad} times the steepest gradient.
     *
     * @param eastStepsMetres  least and greatest rise from one sample to its east neighbour, metres
     * @param southStepsMetres least and greatest rise from one sample to its south neighbour, metres
     * @param eastSpacingMetres  sample spacing east-west at the patch, metres (an upper bound)
     * @param northSpacingMetres sample spacing north-south, metres (an upper bound)
     * @param cornersEastNorthMetres the patch's four corners relative to the eye, (east, north) pairs, metres
     */
    public static double riseAwayFromEye(double[] eastStepsMetres, double[] southStepsMetres, double eastSpacingMetres,
                                         double northSpacingMetres, double[] cornersEastNorthMetres,
                                         double directionSlackRad) {
        double minE = Double.POSITIVE_INFINITY, maxE = Double.NEGATIVE_INFINITY;
        double minN = Double.POSITIVE_INFINITY, maxN = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < 8; i += 2) {
            minE = Math.min(minE, cornersEastNorthMetres[i]);
            maxE = Math.max(maxE, cornersEastNorthMetres[i]);
            minN = Math.min(minN, cornersEastNorthMetres[i + 1]);
            maxN = Math.max(maxN, cornersEastNorthMetres[i + 1]);
        }
        if (minE <= 0 && maxE >= 0 && minN <= 0 && maxN >= 0) {
            return 0; // the eye is over the patch: directions all around
        }
        double least = Double.POSITIVE_INFINITY, steepest = 0;
        for (double eastStep : eastStepsMetres) {
            for (double southStep : southStepsMetres) {
                double ge = eastStep / eastSpacingMetres, gn = -southStep / northSpacingMetres;
                steepest = Math.max(steepest, Math.hypot(ge, gn));
                for (int i = 0; i < 8; i += 2) {
                    double e = cornersEastNorthMetres[i], n = cornersEastNorthMetres[i + 1], len = Math.hypot(e, n);
                    least = Math.min(least, (ge * e + gn * n) / len);
                }
            }
        }
        return Math.max(0, least - directionSlackRad * steepest);
    }
}
