package dempano.util;

/** Small thread helpers. Stateless. */
public final class Threads {
    private Threads() {
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
}
