package dempano.util;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import org.junit.jupiter.api.Test;

class ThreadsTest {
    @Test
    void anotherThreadsFailureIsThrownAgainAsItWas() {
        IllegalArgumentException unchecked = new IllegalArgumentException("bad");
        assertSame(unchecked, Threads.unchecked(unchecked));
        OutOfMemoryError error = new OutOfMemoryError("heap");
        assertSame(error, assertThrows(OutOfMemoryError.class, () -> Threads.unchecked(error)));
        IOException checked = new IOException("disk");
        assertSame(checked, Threads.unchecked(checked).getCause());
    }

    @Test
    void aResultIsWaitedForThroughAnInterruptWhichIsKept() throws Exception {
        CompletableFuture<String> task = new CompletableFuture<>();
        Thread completer = new Thread(() -> {
            try {
                Thread.sleep(200);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            task.complete("done");
        });
        Thread.currentThread().interrupt(); // interrupted before and while waiting: get() alone would throw at once
        completer.start();
        try {
            assertEquals("done", Threads.getUninterruptibly(task));
            assertTrue(Thread.interrupted(), "the interrupt is restored (and cleared here)");
        } finally {
            Thread.interrupted();
            completer.join();
        }
        CompletableFuture<String> failed = CompletableFuture.failedFuture(new IOException("disk"));
        assertEquals("disk", assertThrows(ExecutionException.class, () -> Threads.getUninterruptibly(failed)).getCause().getMessage());
    }
}
