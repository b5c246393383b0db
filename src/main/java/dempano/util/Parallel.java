package dempano.util;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import java.util.function.IntSupplier;
import java.util.stream.IntStream;

/**
 * Loops whose iterations cost very different amounts (patches of different levels of detail, rows with and
 * without probed pixels), run on the common fork-join pool with every worker taking the next index not yet taken.
 * A parallel stream over a range splits it into a fixed number of chunks (four with the two cores of a small
 * machine: the common pool's parallelism, 1, times four), so a loop whose costly iterations crowd into one chunk
 * keeps one core busy long after the other is done; taken an index at a time, the workers finish within one
 * iteration of each other. What each index does must not depend on which worker runs it.
 */
public final class Parallel {
    private Parallel() {
    }

    /** Workers for a loop of {@code n} iterations: the common pool's threads and the calling thread, at most n. */
    public static int workers(int n) {
        return Math.max(1, Math.min(n, ForkJoinPool.getCommonPoolParallelism() + 1));
    }

    /** Runs {@code body} for every index in [0, n), in parallel, each worker taking the next index not yet taken. */
    public static void forEachIndex(int n, IntConsumer body) {
        forEachWorker(n, next -> {
            for (int i = next.getAsInt(); i < n; i = next.getAsInt()) {
                body.accept(i);
            }
        });
    }

    /**
     * Runs {@link #workers(int) workers(n)} workers in parallel, each handed the shared source of indices: every call
     * gives the next index of [0, n) not yet taken, then n and above once all are. For loops whose workers keep
     * state of their own (scratch buffers, counters summed at the end).
     */
    public static void forEachWorker(int n, Consumer<IntSupplier> worker) {
        AtomicInteger next = new AtomicInteger();
        IntSupplier source = next::getAndIncrement;
        IntStream.range(0, workers(n)).parallel().forEach(w -> worker.accept(source));
    }
}
