package dempano.geo;

/**
 * A viewpoint whose eye would stand below the DEM's surface ({@link Viewpoint}): a bad altitude or offset, which the
 * message names with the point and the depth. An {@link IllegalArgumentException}, so that callers that take any bad
 * argument keep working; callers that tell the altitude apart from other problems catch this one first.
 */
public final class EyeBelowGroundException extends IllegalArgumentException {
    public EyeBelowGroundException(String message) {
        super(message);
    }
}
