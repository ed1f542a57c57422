package dev.trisect.render;

/**
 * A linear colour, r, g, b: 0 is none, 1 full intensity. A light's colour may exceed 1 (OpenGL clamps
 * only the lit result); a material's colours are factors, 1 keeping its texture as it is.
 *
 * <pre>{@code
 * Colour warm = new Colour(1, 0.85, 0.6);
 * Colour dim = Colour.grey(0.2);
 * Colour sky = Colour.of(0x9DB8D3);
 * }</pre>
 *
 * @param r red, finite and at least 0
 * @param g green, finite and at least 0
 * @param b blue, finite and at least 0
 */
public record Colour(double r, double g, double b) {
    /** 1, 1, 1. */
    public static final Colour WHITE = new Colour(1, 1, 1);
    /** 0, 0, 0. */
    public static final Colour BLACK = new Colour(0, 0, 0);

    /**
     * Checks the channels.
     *
     * @param r red
     * @param g green
     * @param b blue
     * @throws IllegalArgumentException for a negative or non-finite channel
     */
    public Colour {
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) {
            throw new IllegalArgumentException("a colour needs finite channels >= 0, not " + r + "," + g + "," + b);
        }
    }

    /**
     * A grey.
     *
     * @param level every channel's value
     * @return the colour (level, level, level)
     */
    public static Colour grey(double level) {
        return new Colour(level, level, level);
    }

    /**
     * A colour from 0xRRGGBB, each channel divided by 255.
     *
     * @param rgb the colour as 0xRRGGBB (any alpha bits are ignored)
     * @return the colour
     */
    public static Colour of(int rgb) {
        return new Colour(((rgb >> 16) & 0xFF) / 255.0, ((rgb >> 8) & 0xFF) / 255.0, (rgb & 0xFF) / 255.0);
    }

    /**
     * The colour as 0xRRGGBB, each channel clamped to [0, 1] and rounded to the nearest of 255 steps.
     *
     * @return 0xRRGGBB
     */
    public int rgb() {
        return (channel(r) << 16) | (channel(g) << 8) | channel(b);
    }

    private static int channel(double v) {
        return (int) Math.round(Math.min(v, 1) * 255);
    }
}
