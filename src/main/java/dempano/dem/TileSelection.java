package dempano.dem;

import dempano.geo.Geodesy;
import java.util.ArrayList;
import java.util.List;

/**
 * Which one-degree tiles a range-of-sight circle touches. The circle is geodesic (WGS84): a tile is
 * needed when some point of it lies within {@code rangeMetres} of the viewpoint.
 *
 * @param latSouthDeg   southern edge of the bounding block of tiles, degrees
 * @param lonWestDeg    western edge of the block, degrees, unwrapped: may lie outside [-180, 180)
 *                      when the block crosses the antimeridian, the block then continuing eastward
 * @param tilesNorthSouth rows of tiles in the block
 * @param tilesEastWest   columns of tiles in the block
 * @param touched       for each block tile (row 0 = north), whether the circle touches it
 */
public record TileSelection(int latSouthDeg, int lonWestDeg, int tilesNorthSouth, int tilesEastWest,
                            boolean[][] touched) {
    /** Largest range accepted, metres (a 10 km high eye sees about 360 km; summits beyond add a little). */
    public static final double MAX_RANGE_METRES = 1_000_000;
    // Slack for the boundary sampling (1/64° steps) in the touch test, metres.
    private static final double TOUCH_SLACK_METRES = 1000;

    /** Tiles touched by the circle of {@code rangeMetres} around a viewpoint. */
    public static TileSelection around(double latDeg, double lonDeg, double rangeMetres) {
        checkCoordinates(latDeg, lonDeg);
        if (!(rangeMetres > 0 && rangeMetres <= MAX_RANGE_METRES)) {
            throw new IllegalArgumentException("range must be in (0, " + MAX_RANGE_METRES / 1000 + "] km, got "
                    + rangeMetres / 1000 + " km");
        }
        double toPole = Math.min(Geodesy.distanceMetres(latDeg, lonDeg, 90, lonDeg),
                Geodesy.distanceMetres(latDeg, lonDeg, -90, lonDeg));
        if (toPole <= rangeMetres + TOUCH_SLACK_METRES) {
            throw new IllegalArgumentException("the range circle of " + rangeMetres / 1000 + " km around " + latDeg
                    + ", " + lonDeg + " reaches a pole; polar views are not supported");
        }
        double north = Geodesy.destination(latDeg, lonDeg, 0, rangeMetres)[0];
        double south = Geodesy.destination(latDeg, lonDeg, 180, rangeMetres)[0];
        double minDLon = 0, maxDLon = 0;
        for (int az = 0; az < 360; az += 1) {
            double[] p = Geodesy.destination(latDeg, lonDeg, az, rangeMetres);
            double d = dempano.geo.Angles.wrap180(p[1] - lonDeg);
            minDLon = Math.min(minDLon, d);
            maxDLon = Math.max(maxDLon, d);
        }
        // Sampled every degree of azimuth: widen by the chord sag of a 1° step (≈ range·(1 − cos 0.5°)).
        double pad = 1e-4 * rangeMetres / 111_000 + 1e-9;
        int latS = (int) Math.floor(south), latN = (int) Math.floor(north);
        int lonW = (int) Math.floor(lonDeg + minDLon - pad), lonE = (int) Math.floor(lonDeg + maxDLon + pad);
        int rows = latN - latS + 1, cols = Math.min(360, lonE - lonW + 1);
        boolean[][] touched = new boolean[rows][cols];
        for (int r = 0; r < rows; r++) {
            int tileLat = latN - r;
            for (int c = 0; c < cols; c++) {
                int tileLon = lonW + c;
                touched[r][c] = distanceToTileMetres(latDeg, lonDeg, tileLat, tileLon) <= rangeMetres + TOUCH_SLACK_METRES;
            }
        }
        return new TileSelection(latS, lonW, rows, cols, touched);
    }

    /** Throws a clear error for coordinates that are not a point on the globe. */
    public static void checkCoordinates(double latDeg, double lonDeg) {
        if (!(latDeg >= -90 && latDeg <= 90)) {
            throw new IllegalArgumentException("latitude must be in [-90, 90] degrees, got " + latDeg);
        }
        if (!(lonDeg >= -180 && lonDeg <= 180)) {
            throw new IllegalArgumentException("longitude must be in [-180, 180] degrees, got " + lonDeg);
        }
    }

    /** The tile at block row r (0 = north), column c. */
    public TileId tile(int r, int c) {
        return TileId.of(latSouthDeg + tilesNorthSouth - 1 - r, lonWestDeg + c);
    }

    /** The touched tiles, north to south, west to east. */
    public List<TileId> touchedTiles() {
        List<TileId> out = new ArrayList<>();
        for (int r = 0; r < tilesNorthSouth; r++) {
            for (int c = 0; c < tilesEastWest; c++) {
                if (touched[r][c]) {
                    out.add(tile(r, c));
                }
            }
        }
        return out;
    }

    /** Geodesic distance (metres) from a point to the nearest point of a tile; 0 inside it. */
    static double distanceToTileMetres(double latDeg, double lonDeg, int tileLatSouth, int tileLonWestUnwrapped) {
        double dLon = dempano.geo.Angles.wrap180(lonDeg - tileLonWestUnwrapped);
        double lonLocal = tileLonWestUnwrapped + dLon; // viewpoint longitude near the tile's
        if (latDeg >= tileLatSouth && latDeg <= tileLatSouth + 1 && lonLocal >= tileLonWestUnwrapped
                && lonLocal <= tileLonWestUnwrapped + 1) {
            return 0;
        }
        double best = Double.POSITIVE_INFINITY;
        int steps = 64;
        for (int i = 0; i <= steps; i++) {
            double t = (double) i / steps;
            best = Math.min(best, Geodesy.distanceMetres(latDeg, lonDeg, tileLatSouth, tileLonWestUnwrapped + t));
            best = Math.min(best, Geodesy.distanceMetres(latDeg, lonDeg, tileLatSouth + 1, tileLonWestUnwrapped + t));
            best = Math.min(best, Geodesy.distanceMetres(latDeg, lonDeg, tileLatSouth + t, tileLonWestUnwrapped));
            best = Math.min(best, Geodesy.distanceMetres(latDeg, lonDeg, tileLatSouth + t, tileLonWestUnwrapped + 1));
        }
        // The nearest point on an edge can lie between samples: clamp the viewpoint onto the tile too.
        double clampLat = Math.max(tileLatSouth, Math.min(tileLatSouth + 1, latDeg));
        double clampLon = Math.max(tileLonWestUnwrapped, Math.min(tileLonWestUnwrapped + 1, lonLocal));
        return Math.min(best, Geodesy.distanceMetres(latDeg, lonDeg, clampLat, clampLon));
    }
}
