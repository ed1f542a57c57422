package dev.trisect.view.internal;

import java.util.concurrent.Callable;

/** Test support: a render loop on its own thread, without a window, polled until it has what a test waits for. */
final class LoopRun {
    private LoopRun() {
    }

    /**
     * Runs a loop over {@code state} into {@code buffers} until {@code poll} answers non-null (bounded: up to
     * about 30 s, 1500 polls 20 ms apart), then stops it and returns the answer.
     */
    static <T> T until(ViewState state, TripleBuffer buffers, int threads, String what, Callable<T> poll)
            throws Exception {
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, threads);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            for (int i = 0; i < 1500; i++) {
                T answer = poll.call();
                if (answer != null) {
                    return answer;
                }
                Thread.sleep(20);
            }
            throw new AssertionError("no " + what + " within 30 s");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }
}
