package dev.trisect.texture.internal;

import dev.trisect.texture.Texture;

/**
 * Small drawing helpers on raw ARGB buffers ({@code int[]}, row-major, row 0 at the top), shared by the
 * bitmap font and the procedural textures. All integer arithmetic, so results are the same everywhere.
 */
public final class Pixels {
    private Pixels() {
    }

    /**
     * Fills the half-open rectangle {@code [x0, x1) x [y0, y1)} (pixels, y down) with one colour, clipped
     * to the buffer. Coordinates are longs so callers can pass far-off or overflowing positions safely.
     */
    public static void fillRect(int[] argb, int width, int height, long x0, long y0, long x1, long y1, int colour) {
        int left = clamp(x0, width);
        int right = clamp(x1, width);
        int top = clamp(y0, height);
        int bottom = clamp(y1, height);
        for (int y = top; y < bottom; y++) {
            int row = y * width;
            for (int x = left; x < right; x++) {
                argb[row + x] = colour;
            }
        }
    }

    /** {@code value} clamped to {@code 0..limit}; safe for longs far outside the int range. */
    private static int clamp(long value, int limit) {
        return (int) Math.max(0, Math.min(limit, value));
    }

    /**
     * First texel of part {@code k} when {@code size} texels are split into {@code parts} near-equal parts:
     * {@code ceil(k * size / parts)}. Texel {@code t} is in part {@code floor(t * parts / size)}, so this is
     * exactly where that part begins; it works for sizes that are not multiples of {@code parts}.
     */
    public static int partStart(int k, int parts, int size) {
        return (int) (((long) k * size + parts - 1) / parts);
    }

    /** The part ({@code 0..parts-1}) that texel {@code t} of {@code 0..size-1} falls in. */
    public static int partOf(int t, int parts, int size) {
        return (int) ((long) t * parts / size);
    }

    /**
     * A well-mixed 32-bit hash of three integers, for deterministic noise and per-tile variation
     * (a fixed integer function, so every machine produces the same texture).
     */
    public static int hash(int a, int b, int seed) {
        int h = seed * 0x9E3779B9 + a * 0x85EBCA6B + b * 0xC2B2AE35;
        h ^= h >>> 16;
        h *= 0x7FEB352D;
        h ^= h >>> 15;
        h *= 0x846CA68B;
        h ^= h >>> 16;
        return h;
    }

    /** A hash mapped to {@code [-1, 1]}. */
    public static double noise(int a, int b, int seed) {
        return (hash(a, b, seed) & 0xFFFF) / 32767.5 - 1.0;
    }

    /** An opaque colour from 0..255 channels, each clamped. */
    public static int rgb(double r, double g, double b) {
        return 0xFF000000 | channel(r) << 16 | channel(g) << 8 | channel(b);
    }

    /** Multiplies the colour channels of an opaque colour by {@code factor} (clamped to 0..255). */
    public static int shade(int argb, double factor) {
        return rgb(((argb >> 16) & 0xFF) * factor, ((argb >> 8) & 0xFF) * factor, (argb & 0xFF) * factor);
    }

    private static int channel(double value) {
        return (int) Math.max(0, Math.min(255, Math.round(value)));
    }

    /** Checks a texture side given by a caller (texels). */
    public static void requireSide(String what, int side) {
        if (side < 1 || side > Texture.MAX_SIDE) {
            throw new IllegalArgumentException(what + " " + side + " is outside 1.." + Texture.MAX_SIDE);
        }
    }
}
