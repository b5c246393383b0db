package dempano.camera;

/**
 * A photograph whose metadata cannot be read (missing, unreadable or corrupt file) or does not give what a
 * camera needs; the message names the file and says what to do, and is meant to be shown as it is.
 */
public class PhotoMetadataException extends RuntimeException {
    public PhotoMetadataException(String message) {
        super(message);
    }

    public PhotoMetadataException(String message, Throwable cause) {
        super(message, cause);
    }
}
