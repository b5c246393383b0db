package dempano;

/**
 * A request would need more Java heap than the JVM may use; thrown before rendering, with the
 * estimate and the way out in the message (see {@link MemoryEstimate}).
 */
public final class InsufficientMemoryException extends RuntimeException {
    private final MemoryEstimate estimate;

    public InsufficientMemoryException(String message, MemoryEstimate estimate) {
        super(message);
        this.estimate = estimate;
    }

    /** The estimate that did not fit. */
    public MemoryEstimate estimate() {
        return estimate;
    }
}
