package dempano.util;

/** Small thread helpers. Stateless. */
public final class Threads {
    private Threads() {
    }

    /**
     * What an interrupted wait ends a render (or another cancellable piece of work) with: a
     * {@link java.util.concurrent.CancellationException} saying "interrupted while {@code what}" (an IllegalStateException,
     * which a caller can tell from a closed renderer's), the thread's interrupt flag set again.
     */
    public static java.util.concurrent.CancellationException interrupted(String what, InterruptedException cause) {
        Thread.currentThread().interrupt();
        java.util.concurrent.CancellationException e = new java.util.concurrent.CancellationException("interrupted while " + what);
        e.initCause(cause);
        return e;
    }

    /**
     * Waits for a thread to end even when interrupted meanwhile (the work it does must not be abandoned half-way:
     * a file being written, a scene being drawn); the interrupt flag is restored afterwards.
     */
    public static void joinUninterruptibly(Thread thread) {
        boolean interrupted = false;
        while (true) {
            try {
                thread.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Waits for a task's result even when interrupted meanwhile (as {@link #joinUninterruptibly}); the interrupt flag
     * is restored afterwards.
     *
     * @throws java.util.concurrent.ExecutionException what the task threw
     */
    public static <T> T getUninterruptibly(java.util.concurrent.Future<T> task) throws java.util.concurrent.ExecutionException {
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    return task.get();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /**
     * What another thread threw, to throw again here as it was: an Error is thrown at once, an unchecked exception
     * returned, a checked one returned wrapped (the caller has taken out those it declares).
     */
    public static RuntimeException unchecked(Throwable cause) {
        if (cause instanceof Error err) {
            throw err;
        }
        return cause instanceof RuntimeException r ? r : new IllegalStateException(cause);
    }
}
