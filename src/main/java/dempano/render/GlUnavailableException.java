package dempano.render;

/** No OpenGL context could be created; the message says what is missing and how to get it. */
public class GlUnavailableException extends RuntimeException {
    public GlUnavailableException(String message, Throwable cause) {
        super(message, cause);
    }
}
