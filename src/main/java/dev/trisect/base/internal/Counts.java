package dev.trisect.base.internal;

/**
 * A number with its noun, singular for one: "1 frame", "2 frames". For the messages the command line,
 * the readers and the demo print, where a count of one is common ({@code --frames 1}, {@code --threads 1},
 * an OBJ of one material) and "1 frames" reads as a slip.
 */
public final class Counts {
    private Counts() {
    }

    /** {@code n} and {@code noun}, with an "s" added unless {@code n} is 1. */
    public static String of(long n, String noun) {
        return n + " " + (n == 1 ? noun : noun + "s");
    }
}
