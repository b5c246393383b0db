package dempano.geo;

import dempano.dem.Mosaic;
import java.util.Locale;

/**
 * The two automatic corrections of a viewpoint the 90 m DEM needs on summits and ridges, as pure
 * functions of the DEM grid (no rendering):
 * <ul>
 *   <li>{@link #highestWithin snapping} to the highest DEM sample within a radius (a surveyed summit
 *       lies beside the DEM's own, rounded-off summit, which then walls off part of the view);</li>
 *   <li>{@link #clearViewEyeAltitudeMetres raising the eye} until no terrain within a radius rises
 *       above the eye's horizontal, refraction and earth curvature taken into account.</li>
 * </ul>
 * Horizontal distances are on a local sphere of {@link Ellipsoid#MEAN_RADIUS_METRES} (east distance
 * scaled by the cosine of the latitude): exact to a fraction of a metre within the few hundred
 * metres these radii cover.
 */
public final class ViewpointAdjustment {
    /** Margin the clear-view eye keeps above the highest apparent terrain within the radius, metres. */
    public static final double CLEAR_VIEW_MARGIN_METRES = 0.5;
    /** Largest radius either correction accepts, metres. */
    public static final double MAX_RADIUS_METRES = 10_000;

    private ViewpointAdjustment() {
    }

    /**
     * A DEM grid sample.
     *
     * @param latDeg         latitude of the sample, degrees
     * @param lonDeg         longitude of the sample, degrees in [-180, 180)
     * @param heightMetres   the sample's height, metres above sea level
     * @param distanceMetres horizontal distance from the point asked about, metres
     */
    public record GridPoint(double latDeg, double lonDeg, double heightMetres, double distanceMetres) {
    }

    /**
     * The highest DEM grid sample within {@code radiusMetres} of a coordinate (the bilinear surface
     * is highest at a sample, so this is the highest point of the DEM surface inside the circle up
     * to the cells the circle cuts). Ties go to the nearest sample. When no sample in the circle is
     * higher than the DEM surface at the coordinate itself, the coordinate is returned (distance 0):
     * the viewpoint already stands on the local top.
     *
     * @throws IllegalArgumentException for a radius outside (0, {@value #MAX_RADIUS_METRES}] m or no DEM height at the coordinate
     */
    public static GridPoint highestWithin(Mosaic mosaic, double latDeg, double lonDeg, double radiusMetres) {
        checkRadius(radiusMetres, "--snap-to-summit-m");
        double here = Viewpoint.groundAt(mosaic, latDeg, lonDeg);
        GridPoint best = new GridPoint(latDeg, lonDeg, here, 0);
        Scan s = new Scan(mosaic, latDeg, lonDeg, radiusMetres);
        for (int r = s.r0; r <= s.r1; r++) {
            for (int c = s.c0; c <= s.c1; c++) {
                double d = s.distance(r, c);
                float h = mosaic.sample(r, c);
                if (d > radiusMetres || Float.isNaN(h)) {
                    continue;
                }
                if (h > best.heightMetres() || (h == best.heightMetres() && d < best.distanceMetres())) {
                    best = new GridPoint(mosaic.latOfRow(r), Angles.wrap180(mosaic.lonOfCol(c)), h, d);
                }
            }
        }
        return best;
    }

    /**
     * Apparent drop of terrain at a horizontal distance below the eye's horizontal plane, metres:
     * earth curvature d²/2R less the refraction lift k·d²/2R.
     */
    public static double curvatureDropMetres(double distanceMetres, Refraction refraction) {
        return distanceMetres * distanceMetres / (2 * Ellipsoid.MEAN_RADIUS_METRES) - refraction.liftMetres(distanceMetres);
    }

    /**
     * The least eye altitude (metres above sea level) from which no DEM sample within
     * {@code radiusMetres} of the coordinate rises above the eye's horizontal: the largest
     * height − {@link #curvatureDropMetres apparent drop} over the samples in the circle (and the DEM
     * surface at the coordinate), plus {@value #CLEAR_VIEW_MARGIN_METRES} m.
     *
     * @throws IllegalArgumentException for a radius outside (0, {@value #MAX_RADIUS_METRES}] m or no DEM height at the coordinate
     */
    public static double clearViewEyeAltitudeMetres(Mosaic mosaic, double latDeg, double lonDeg, double radiusMetres,
                                                    Refraction refraction) {
        checkRadius(radiusMetres, "--clear-view-m");
        double top = Viewpoint.groundAt(mosaic, latDeg, lonDeg);
        Scan s = new Scan(mosaic, latDeg, lonDeg, radiusMetres);
        for (int r = s.r0; r <= s.r1; r++) {
            for (int c = s.c0; c <= s.c1; c++) {
                double d = s.distance(r, c);
                float h = mosaic.sample(r, c);
                if (d <= radiusMetres && !Float.isNaN(h)) {
                    top = Math.max(top, h - curvatureDropMetres(d, refraction));
                }
            }
        }
        return top + CLEAR_VIEW_MARGIN_METRES;
    }

    /**
     * A viewpoint with the requested corrections applied, and the move (null when neither option was given).
     *
     * @param eye  the viewpoint to render from
     * @param move where it moved from and to, or null
     */
    public record Adjusted(Viewpoint eye, ViewpointMove move) {
    }

    /**
     * Applies the corrections to a requested viewpoint: first the snap to the highest DEM sample within
     * {@code snapRadiusMetres} (the offset or absolute altitude kept), then the lift of the standing
     * altitude to {@link #clearViewEyeAltitudeMetres} for {@code clearRadiusMetres} when the eye is
     * lower. A radius of NaN leaves that correction out.
     */
    public static Adjusted apply(Mosaic mosaic, Viewpoint requested, double snapRadiusMetres, double clearRadiusMetres,
                                 Refraction refraction) {
        boolean snap = !Double.isNaN(snapRadiusMetres), clear = !Double.isNaN(clearRadiusMetres);
        if (!snap && !clear) {
            return new Adjusted(requested, null);
        }
        Viewpoint v = requested;
        double shift = 0;
        StringBuilder reason = new StringBuilder();
        if (snap) {
            GridPoint top = highestWithin(mosaic, v.latDeg(), v.lonDeg(), snapRadiusMetres);
            shift = top.distanceMetres();
            reason.append(String.format(Locale.ROOT, "--snap-to-summit-m %s: highest DEM sample %.0f m",
                    trim(snapRadiusMetres), top.heightMetres()));
            if (shift > 0) {
                v = Double.isNaN(v.offsetMetres())
                        ? Viewpoint.atAltitude(mosaic, top.latDeg(), top.lonDeg(), v.standingAltitudeMetres(), v.eyeHeightMetres())
                        : Viewpoint.onDem(mosaic, top.latDeg(), top.lonDeg(), v.offsetMetres(), v.eyeHeightMetres());
            }
        }
        double lift = 0;
        if (clear) {
            double needed = clearViewEyeAltitudeMetres(mosaic, v.latDeg(), v.lonDeg(), clearRadiusMetres, refraction);
            lift = Math.max(0, needed - v.eyeAltitudeMetres());
            reason.append(reason.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT,
                    "--clear-view-m %s: terrain within it needs the eye at %.1f m", trim(clearRadiusMetres), needed));
            if (lift > 0) {
                v = new Viewpoint(v.latDeg(), v.lonDeg(), v.groundElevationMetres(),
                        Double.isNaN(v.offsetMetres()) ? Double.NaN : v.offsetMetres() + lift,
                        v.standingAltitudeMetres() + lift, v.eyeHeightMetres());
            }
        }
        return new Adjusted(v, new ViewpointMove(requested.latDeg(), requested.lonDeg(), requested.eyeAltitudeMetres(),
                v.latDeg(), v.lonDeg(), v.eyeAltitudeMetres(), shift, lift, reason.toString()));
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v);
    }

    /** The grid window around a coordinate that covers a circle, and distances to its samples. */
    private static final class Scan {
        final int r0, r1, c0, c1;
        final double rowCentre, colCentre, metresPerRow, metresPerCol;

        Scan(Mosaic m, double latDeg, double lonDeg, double radiusMetres) {
            int n = m.intervalsPerDegree();
            metresPerRow = Ellipsoid.MEAN_RADIUS_METRES * Math.toRadians(1.0 / n);
            metresPerCol = metresPerRow * Math.cos(Math.toRadians(latDeg));
            rowCentre = m.rowOf(latDeg);
            colCentre = m.colOf(lonDeg);
            int dr = (int) Math.ceil(radiusMetres / metresPerRow) + 1;
            int dc = (int) Math.ceil(radiusMetres / Math.max(metresPerCol, 1e-3)) + 1;
            r0 = Math.max(0, (int) Math.floor(rowCentre) - dr);
            r1 = Math.min(m.rows() - 1, (int) Math.ceil(rowCentre) + dr);
            c0 = Math.max(0, (int) Math.floor(colCentre) - dc);
            c1 = Math.min(m.cols() - 1, (int) Math.ceil(colCentre) + dc);
        }

        double distance(int r, int c) {
            return Math.hypot((r - rowCentre) * metresPerRow, (c - colCentre) * metresPerCol);
        }
    }

    private static void checkRadius(double radiusMetres, String option) {
        if (!(radiusMetres > 0 && radiusMetres <= MAX_RADIUS_METRES)) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "%s: the radius must be in (0, %.0f] metres, got %s",
                    option, MAX_RADIUS_METRES, radiusMetres));
        }
    }
}
