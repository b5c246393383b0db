package dempano.dem;

/** What to do when the range of sight needs a tile the DEM source does not have. */
public enum MissingTilePolicy {
    /** Treat the tile as sea level (0 m) and warn, naming the tile. The default: SRTM has no tiles over sea. */
    SEA_LEVEL,
    /** Fail with a {@link DemException} naming the tile. */
    ERROR
}
