package dempano.render;

/**
 * The GL thread failed (out of memory, a driver error, or it ended): this render is lost, and the
 * renderer that ran it is closed; a new {@code PanoramaRenderer.open} gets a fresh GL context.
 */
public final class RenderFailedException extends RuntimeException {
    public RenderFailedException(String message, Throwable cause) {
        super(message, cause);
    }
}
