package dempano.summits;

import dempano.geo.Ellipsoid;
import dempano.geo.Geodesy;
import dempano.geo.LocalFrame;
import dempano.geo.Refraction;
import dempano.panorama.Panorama;
import dempano.panorama.PanoramaGeometry;
import dempano.panorama.PanoramaMetadata;
import java.util.ArrayList;
import java.util.List;

/**
 * Projects surveyed summits into a rendered panorama with the renderer's own geometry (WGS84 ENU
 * from the eye, refraction lift k·d²/2R) and decides which are seen.
 *
 * <p>Visibility tolerance. A survey and a DEM disagree: SRTM3 flattens summits (tens of metres
 * lower; where a void on the summit was filled by interpolation, up to ~200 m lower), and surveyed
 * positions are off by up to a cell or two. So around the summit's pixel a window is searched:
 * ±{@link #POSITION_TOLERANCE_METRES} sideways, {@link #HEIGHT_TOLERANCE_UP_METRES} up and
 * {@link #HEIGHT_TOLERANCE_DOWN_METRES} down, converted to pixels at the summit's distance (at
 * least one pixel each way). In each column of the window the first terrain pixel at or below the
 * window's top is what a person sees at the summit; the summit is visible when, in some column,
 * that terrain lies within max({@link #DISTANCE_TOLERANCE_METRES}, {@link #DISTANCE_TOLERANCE_FRACTION}
 * × distance) of the summit's slant distance. A summit hidden behind nearer terrain shows that
 * terrain instead, at a shorter distance; summits beyond the panorama's range or outside its
 * elevation range are not visible.
 */
public final class SummitProjector {
    public static final double POSITION_TOLERANCE_METRES = 150;
    public static final double HEIGHT_TOLERANCE_UP_METRES = 30;
    public static final double HEIGHT_TOLERANCE_DOWN_METRES = 200;
    public static final double DISTANCE_TOLERANCE_METRES = 300;
    public static final double DISTANCE_TOLERANCE_FRACTION = 0.02;
    /** A summit less than this far from the eye, horizontally, metres, has no direction: see {@link #atTheEye}. */
    public static final double AT_EYE_METRES = 1;

    private SummitProjector() {
    }

    /**
     * Every summit of the list within range that lies on a camera's image (or within a pixel of its edge), in
     * list order, placed with the same geometry as {@link #project(Panorama, SummitList)} and the camera's own
     * model ({@link dempano.camera.CameraView#pixelOf}): {@link SummitSighting#pixelX()} and {@code pixelY} are
     * OpenCV pixel coordinates, pixel (i, j)'s centre at (i, j), as the camera's P.json declares them (they were
     * half a pixel off that, in the panorama's convention: read as OpenCV, a distance lookup hit the neighbouring
     * pixel for two summits in three). The
     * visibility window is as the panorama's, in image columns and rows at the camera's focal length.
     *
     * @throws IllegalStateException when the image was rendered without distances
     */
    public static List<SummitSighting> project(dempano.CameraImage image, SummitList list) {
        if (!image.hasDistance()) {
            throw new IllegalStateException("summit visibility is decided from distances: this view was rendered"
                    + " without them (colour only)");
        }
        PanoramaMetadata m = image.metadata();
        dempano.camera.CameraView view = image.view();
        LocalFrame eye = new LocalFrame(m.latDeg(), m.lonDeg(), m.eyeAltitudeMetres());
        Refraction refraction = new Refraction(m.refractionCoefficient());
        double[] eyeFoot = new double[3];
        Ellipsoid.toEcef(m.latDeg(), m.lonDeg(), 0, eyeFoot);
        int w = image.widthPx(), h = image.heightPx();
        float[] distance = image.distanceArray();
        // Image pixels per degree near the axis (the window is a tolerance, not a measurement).
        double ppd = view.intrinsics().fxPx() * Math.PI / 180;
        List<SummitSighting> out = new ArrayList<>();
        double[] foot = new double[3], enu = new double[3], px = new double[2];
        for (Summit s : list.summits()) {
            if (Double.isNaN(s.elevationMetres())) {
                continue;
            }
            Ellipsoid.toEcef(s.latDeg(), s.lonDeg(), 0, foot);
            if (!inRange(foot, eyeFoot, m)) {
                continue;
            }
            double chordGround = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
            eye.toEnu(s.latDeg(), s.lonDeg(), s.elevationMetres() + refraction.liftMetres(chordGround), enu);
            double horizontal = Math.hypot(enu[0], enu[1]);
            if (horizontal > m.rangeMetres() || horizontal < AT_EYE_METRES) {
                continue; // beyond the range, or the eye stands on it (atTheEye)
            }
            view.pixelOf(enu[0], enu[1], enu[2], px);
            if (Double.isNaN(px[0]) || px[0] < -1.5 || px[0] > w + 0.5 || px[1] < -1.5 || px[1] > h + 0.5) {
                continue; // behind the camera or off the image
            }
            double az = Math.toDegrees(Math.atan2(enu[0], enu[1]));
            if (az < 0) {
                az += 360;
            }
            double el = Math.toDegrees(Math.atan2(enu[2], horizontal));
            double slant = Math.sqrt(horizontal * horizontal + enu[2] * enu[2]);
            int col = (int) Math.round(px[0]), row = (int) Math.round(px[1]);
            boolean inside = view.contains(px[0], px[1]);
            double atPixel = inside ? distance[row * w + col] : Double.NaN;
            int dc = Math.max(1, (int) Math.ceil(Math.toDegrees(Math.atan(POSITION_TOLERANCE_METRES / horizontal)) * ppd));
            int up = Math.max(1, (int) Math.ceil(Math.toDegrees(Math.atan(HEIGHT_TOLERANCE_UP_METRES / horizontal)) * ppd));
            int down = Math.max(1, (int) Math.ceil(Math.toDegrees(Math.atan(HEIGHT_TOLERANCE_DOWN_METRES / horizontal)) * ppd));
            double tolerance = Math.max(DISTANCE_TOLERANCE_METRES, DISTANCE_TOLERANCE_FRACTION * slant);
            double seen = Double.NaN;
            if (inside) {
                for (int c = Math.max(0, col - dc); c <= Math.min(w - 1, col + dc); c++) {
                    for (int r = Math.max(0, row - up); r <= Math.min(h - 1, row + down); r++) {
                        float d = distance[r * w + c];
                        if (Float.isFinite(d)) {
                            if (Double.isNaN(seen) || Math.abs(d - slant) < Math.abs(seen - slant)) {
                                seen = d;
                            }
                            break; // the first terrain pixel of this column
                        }
                    }
                }
            }
            boolean visible = !Double.isNaN(seen) && Math.abs(seen - slant) <= tolerance;
            double ground = Geodesy.distanceMetres(m.latDeg(), m.lonDeg(), s.latDeg(), s.lonDeg());
            out.add(new SummitSighting(s, az, el, px[0], px[1], slant, ground, atPixel, seen, visible));
        }
        return out;
    }

    /**
     * Every summit of the list within the panorama's range, in list order.
     *
     * @throws IllegalStateException when the panorama was rendered without distances (colour only):
     *                               visibility is decided from them
     */
    public static List<SummitSighting> project(Panorama p, SummitList list) {
        if (!p.hasDistance()) {
            throw new IllegalStateException("summit visibility is decided from distances: this panorama was rendered"
                    + " without them (colour only)");
        }
        PanoramaMetadata m = p.metadata();
        LocalFrame eye = new LocalFrame(m.latDeg(), m.lonDeg(), m.eyeAltitudeMetres());
        Refraction refraction = new Refraction(m.refractionCoefficient());
        double[] eyeFoot = new double[3];
        Ellipsoid.toEcef(m.latDeg(), m.lonDeg(), 0, eyeFoot);
        PanoramaGeometry g = p.geometry();
        float[] distance = p.distanceArray();
        List<SummitSighting> out = new ArrayList<>();
        double[] foot = new double[3], enu = new double[3];
        for (Summit s : list.summits()) {
            if (Double.isNaN(s.elevationMetres())) {
                continue; // no height: cannot be placed in elevation
            }
            Ellipsoid.toEcef(s.latDeg(), s.lonDeg(), 0, foot);
            if (!inRange(foot, eyeFoot, m)) {
                continue;
            }
            double chordGround = Refraction.groundDistanceBetweenFeetMetres(foot, eyeFoot);
            eye.toEnu(s.latDeg(), s.lonDeg(), s.elevationMetres() + refraction.liftMetres(chordGround), enu);
            double horizontal = Math.hypot(enu[0], enu[1]);
            if (horizontal > m.rangeMetres() || horizontal < AT_EYE_METRES) {
                continue; // beyond the range, or the eye stands on it (atTheEye)
            }
            double az = Math.toDegrees(Math.atan2(enu[0], enu[1]));
            if (az < 0) {
                az += 360;
            }
            double el = Math.toDegrees(Math.atan2(enu[2], horizontal));
            double slant = Math.sqrt(horizontal * horizontal + enu[2] * enu[2]);
            double x = g.columnOf(az), y = g.rowOf(el);
            int col = Math.floorMod((int) Math.floor(x), g.widthPx()), row = (int) Math.floor(y);
            boolean inside = row >= 0 && row < g.heightPx();
            double atPixel = inside ? distance[row * g.widthPx() + col] : Double.NaN;
            double ppd = g.pixelsPerDegree();
            int dc = (int) Math.ceil(Math.toDegrees(Math.atan(POSITION_TOLERANCE_METRES / horizontal)) * ppd);
            int up = Math.max(1, (int) Math.ceil(Math.toDegrees(Math.atan(HEIGHT_TOLERANCE_UP_METRES / horizontal)) * ppd));
            int down = Math.max(1, (int) Math.ceil(Math.toDegrees(Math.atan(HEIGHT_TOLERANCE_DOWN_METRES / horizontal)) * ppd));
            dc = Math.max(1, dc);
            double tolerance = Math.max(DISTANCE_TOLERANCE_METRES, DISTANCE_TOLERANCE_FRACTION * slant);
            double seen = Double.NaN;
            if (inside) {
                for (int c = -dc; c <= dc; c++) {
                    int cc = Math.floorMod(col + c, g.widthPx());
                    for (int r = Math.max(0, row - up); r <= Math.min(g.heightPx() - 1, row + down); r++) {
                        float d = distance[r * g.widthPx() + cc];
                        if (Float.isFinite(d)) {
                            if (Double.isNaN(seen) || Math.abs(d - slant) < Math.abs(seen - slant)) {
                                seen = d;
                            }
                            break; // the first terrain pixel of this column
                        }
                    }
                }
            }
            boolean visible = !Double.isNaN(seen) && Math.abs(seen - slant) <= tolerance;
            double ground = Geodesy.distanceMetres(m.latDeg(), m.lonDeg(), s.latDeg(), s.lonDeg());
            out.add(new SummitSighting(s, az, el, x, y, slant, ground, atPixel, seen, visible));
        }
        return out;
    }

    /**
     * The sightings with the DEM's height at each summit and whether it lies in a filled void
     * ({@link SummitSighting#demHeightMetres()}, {@link SummitSighting#inFilledVoid()}), looked up in
     * {@code dem} at the summit's surveyed position. A summit on a tile the DEM does not have gets NaN
     * and {@code false}.
     *
     * @throws dempano.dem.DemException if a tile exists but cannot be read
     */
    public static List<SummitSighting> withDem(List<SummitSighting> sightings, dempano.dem.DemSource dem) {
        DemLookup lookup = new DemLookup(dem);
        List<SummitSighting> out = new ArrayList<>(sightings.size());
        for (SummitSighting s : sightings) {
            double lat = s.summit().latDeg(), lon = s.summit().lonDeg();
            out.add(lookup.tileAt(lat, lon).map(t -> s.withDem(t.heightAt(lat, lon), inFilledVoid(t, lat, lon))).orElse(s));
        }
        return out;
    }

    /**
     * The list with every summit that has no elevation placed at the DEM's height at its position (bilinear between
     * the four samples around it; {@link Summit#elevationFromDem()} true), so that it is projected rather than left
     * out. Summits with an elevation, and those on a tile the DEM does not have (or an entirely void one), are kept
     * as they are. The DEM's height is that of the terrain drawn there, so such a summit sits on the rendered
     * surface; SRTM3 comes out some 40 m below a surveyed summit on valid data. Only summits within the range of
     * {@code around} are looked up (as {@link #project} takes them), so a world list reads no tiles beyond it.
     *
     * @param around the render the summits will be projected into (its viewpoint and range)
     * @throws dempano.dem.DemException if a tile exists but cannot be read
     */
    public static SummitList placedOnDem(SummitList list, dempano.dem.DemSource dem, PanoramaMetadata around) {
        if (list.summits().stream().noneMatch(s -> Double.isNaN(s.elevationMetres()))) {
            return list;
        }
        DemLookup lookup = new DemLookup(dem);
        double[] eyeFoot = new double[3], foot = new double[3];
        Ellipsoid.toEcef(around.latDeg(), around.lonDeg(), 0, eyeFoot);
        List<Summit> out = new ArrayList<>(list.size());
        for (Summit s : list.summits()) {
            Ellipsoid.toEcef(s.latDeg(), s.lonDeg(), 0, foot);
            double height = Double.isNaN(s.elevationMetres()) && inRange(foot, eyeFoot, around)
                    ? lookup.tileAt(s.latDeg(), s.lonDeg()).map(t -> t.heightAt(s.latDeg(), s.lonDeg())).orElse(Double.NaN)
                    : Double.NaN;
            out.add(Double.isNaN(height) ? s : new Summit(s.name(), s.latDeg(), s.lonDeg(), height, true));
        }
        return list.withSummits(out);
    }

    /**
     * The summits of the list that stand where the eye does (less than {@link #AT_EYE_METRES} from it horizontally):
     * {@link #project} leaves them out, since they have no direction from the eye; a user who gave a summit's own
     * coordinates as the viewpoint is told so.
     */
    public static List<Summit> atTheEye(PanoramaMetadata m, SummitList list) {
        LocalFrame eye = new LocalFrame(m.latDeg(), m.lonDeg(), m.eyeAltitudeMetres());
        double[] enu = new double[3];
        List<Summit> out = new ArrayList<>();
        for (Summit s : list.summits()) {
            eye.toEnu(s.latDeg(), s.lonDeg(), Double.isNaN(s.elevationMetres()) ? 0 : s.elevationMetres(), enu);
            if (Math.hypot(enu[0], enu[1]) < AT_EYE_METRES) {
                out.add(s);
            }
        }
        return out;
    }

    /**
     * What a user should be told before the list is projected into a render, one sentence each without a
     * "warning:" prefix: the list's own {@link SummitList#warnings()}, the summits within the render's range that
     * still have no height (no DEM tile under them, or before {@link #placedOnDem}), which are left out, and each
     * summit {@link #atTheEye}.
     */
    public static List<String> warnings(SummitList list, PanoramaMetadata render) {
        List<String> out = new ArrayList<>(list.warnings());
        double[] eyeFoot = new double[3], foot = new double[3];
        Ellipsoid.toEcef(render.latDeg(), render.lonDeg(), 0, eyeFoot);
        List<Summit> unplaced = new ArrayList<>();
        for (Summit s : list.summits()) {
            Ellipsoid.toEcef(s.latDeg(), s.lonDeg(), 0, foot);
            if (Double.isNaN(s.elevationMetres()) && inRange(foot, eyeFoot, render)) {
                unplaced.add(s);
            }
        }
        if (!unplaced.isEmpty()) {
            out.add(unplaced.size() + " of them within range " + (unplaced.size() == 1 ? "has" : "have")
                    + " no DEM height either and " + (unplaced.size() == 1 ? "is" : "are") + " left out (e.g. "
                    + unplaced.get(0).name() + ")");
        }
        atTheEye(render, list).forEach(s -> out.add("summit " + s.name() + " is where the eye stands: it has no"
                + " direction from there and is left out"));
        return out;
    }

    /** Whether a summit's foot lies within the render's range of the eye's (as {@link #project} takes them). */
    private static boolean inRange(double[] summitFoot, double[] eyeFoot, PanoramaMetadata render) {
        return Refraction.groundDistanceBetweenFeetMetres(summitFoot, eyeFoot) <= render.rangeMetres() * 1.01 + 1000;
    }

    /** The DEM's tiles, each read once, for the lookups of one list. */
    private static final class DemLookup {
        private final dempano.dem.DemSource dem;
        private final java.util.Map<dempano.dem.TileId, java.util.Optional<dempano.dem.HgtTile>> tiles = new java.util.HashMap<>();

        DemLookup(dempano.dem.DemSource dem) {
            this.dem = dem;
        }

        /** The tile with data at a position; empty for no tile or an entirely void one. */
        java.util.Optional<dempano.dem.HgtTile> tileAt(double latDeg, double lonDeg) {
            return tiles.computeIfAbsent(dempano.dem.TileId.containing(latDeg, lonDeg), dem::tile)
                    .filter(t -> !t.entirelyVoid());
        }
    }

    /** True if one of the four samples around a position (those bilinear interpolation uses) is a filled void. */
    static boolean inFilledVoid(dempano.dem.HgtTile t, double latDeg, double lonDeg) {
        int n = t.samplesPerSide();
        double row = (t.id().latSouthDeg() + 1 - latDeg) * t.intervalsPerDegree();
        double col = (lonDeg - t.id().lonWestDeg()) * t.intervalsPerDegree();
        int r = Math.max(0, Math.min(n - 2, (int) Math.floor(row)));
        int c = Math.max(0, Math.min(n - 2, (int) Math.floor(col)));
        return t.isFilledVoid(r, c) || t.isFilledVoid(r, c + 1) || t.isFilledVoid(r + 1, c) || t.isFilledVoid(r + 1, c + 1);
    }
}
