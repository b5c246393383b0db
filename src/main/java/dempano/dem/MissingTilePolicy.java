package dempano.dem;

import java.util.ArrayList;
import java.util.List;

/** What to do when the range of sight needs a tile the DEM source does not have. */
public enum MissingTilePolicy {
    /**
     * The default. Missing neighbouring tiles are sea level (0 m) with a warning naming them (SRTM has
     * no tiles over sea, so coasts need this). But it is an error ({@link DemException}) when none of
     * the needed tiles is present (wrong folder, open sea, off the data's coverage), and when the tile
     * under the viewpoint is missing and no absolute altitude was given (the eye would silently stand
     * on "sea"). See {@link #checkData}.
     */
    AUTO,
    /** Explicit sea: every missing tile is sea level (0 m), never an error; still a warning naming them. */
    SEA_LEVEL,
    /** Fail with a {@link DemException} listing every missing tile. */
    ERROR;

    /** The value of {@code --missing-tiles} that asks for this policy. */
    public String flagValue() {
        return switch (this) {
            case AUTO -> "auto";
            case SEA_LEVEL -> "sea";
            case ERROR -> "error";
        };
    }

    /**
     * The checks of {@link #AUTO} that need the whole request: call after {@link Mosaic#around}.
     *
     * @param mosaic         the tiles around the viewpoint, loaded under this policy
     * @param latDeg         viewpoint latitude
     * @param lonDeg         viewpoint longitude
     * @param altitudeMetres absolute altitude requested, NaN when the eye stands on the DEM
     * @throws DemException under {@link #AUTO} when no needed tile is present, or the viewpoint's own
     *                      tile is missing and no altitude was given; the message names the tile(s),
     *                      the DEM folder and the ways out
     */
    public void checkData(Mosaic mosaic, double latDeg, double lonDeg, double altitudeMetres) {
        if (this != AUTO || mosaic.tilesMissing().isEmpty()) {
            return;
        }
        String where = mosaic.sourceDescription();
        // Tiles there but without one valid sample count as missing: say so, not that they are absent.
        List<String> allVoid = mosaic.warnings().stream().filter(w -> w.contains(ENTIRELY_VOID)).toList();
        String unread = mosaic.warnings().stream().filter(w -> w.contains(Mosaic.NOT_READ)).map(w -> "; " + w)
                .findFirst().orElse("");
        if (mosaic.tilesUsed().isEmpty()) {
            throw new DemException("no DEM data around " + latDeg + ", " + lonDeg + ": none of the tiles needed within range "
                    + mosaic.tilesMissing() + (allVoid.isEmpty() ? " is in " + where + " (wrong DEM folder, or open sea?)"
                    : " has data in " + where + " (" + String.join("; ", allVoid) + ")") + unread
                    + "; add the tiles, or give --missing-tiles sea to render sea level");
        }
        if (Double.isNaN(altitudeMetres)) {
            List<TileId> under = tilesUnder(latDeg, lonDeg);
            if (mosaic.tilesMissing().containsAll(under)) {
                throw new DemException("tile " + (under.size() == 1 ? under.get(0) : under.toString())
                        + " under the viewpoint " + latDeg + ", " + lonDeg + (allVoid.isEmpty() ? " is not in " + where
                        : " has no data in " + where + " (" + String.join("; ", allVoid) + ")") + unread
                        + ": the eye would stand on sea level (0 m); add the tile, give the eye's altitude with "
                        + "--altitude-m, or --missing-tiles sea if the viewpoint is at sea");
            }
        }
    }

    /** How {@link Mosaic} words the warning for a tile with no valid sample, which then counts as missing. */
    static final String ENTIRELY_VOID = "has no valid sample at all";

    /** The tiles whose closed squares hold a point (2 or 4 on an edge or corner). */
    private static List<TileId> tilesUnder(double latDeg, double lonDeg) {
        List<TileId> out = new ArrayList<>();
        TileId c = TileId.containing(latDeg, lonDeg);
        boolean southEdge = latDeg == c.latSouthDeg() && latDeg > -90, westEdge = lonDeg == Math.floor(lonDeg);
        out.add(c);
        if (southEdge) {
            out.add(TileId.of(c.latSouthDeg() - 1, c.lonWestDeg()));
        }
        if (westEdge) {
            out.add(TileId.of(c.latSouthDeg(), c.lonWestDeg() - 1));
            if (southEdge) {
                out.add(TileId.of(c.latSouthDeg() - 1, c.lonWestDeg() - 1));
            }
        }
        return out;
    }
}
