package dev.trisect.raster;

import dev.trisect.tessellate.VertexLayout;

/**
 * What the pixel loops do with a material's fragments: a small int per frame material, kept beside
 * its texture ({@link Rasterizer#states}), made of two fields, each one of the constants below:
 * <ul>
 * <li>colour: {@link #TEXEL} (the texel) or {@link #MODULATE} (the texel times the interpolated
 * colour of varyings 2..4, OpenGL 1.x section 3.8.13, table 3.22, GL_MODULATE);</li>
 * <li>write: {@link #OPAQUE} (depth test, then depth, colour and UV output written),
 * {@link #ALPHA_TEST} (as opaque where the texel's alpha is at least 128, nothing written elsewhere:
 * GL_ALPHA_TEST with GL_GEQUAL 0.5, section 4.1.4) or {@link #BLEND} (depth tested, depth not written,
 * colour {@code src * a + dst * (1 - a)} per channel ({@link Blend}), GL_SRC_ALPHA,
 * GL_ONE_MINUS_SRC_ALPHA, section 4.1.7; the UV output not written, so it keeps the surface behind).</li>
 * </ul>
 * A state is one of each, joined by {@code |}: {@code MODULATE | BLEND}. State 0 is
 * {@code TEXEL | OPAQUE}, every frame's state until a material asks for another. The loop is chosen
 * once per triangle from it (the generated loops' dispatchers, {@link PerPixelLoops#fill}), never per pixel.
 */
public final class PixelState {
    /** Colour: the texel, alpha kept. */
    public static final int TEXEL = 0;
    /** Colour: the texel times the interpolated colour r, g, b (varyings 2..4, 0..1); needs a layout of 5 varyings or more. */
    public static final int MODULATE = 1;
    /** Write: depth test, then depth, colour (alpha 255) and UV output. */
    public static final int OPAQUE = 0;
    /** Write: as {@link #OPAQUE} where the fragment's alpha is at least 128, else nothing. */
    public static final int ALPHA_TEST = 1 << 2;
    /** Write: depth test, then colour blended over the frame's; neither depth nor UV output written. */
    public static final int BLEND = 2 << 2;
    /** The first varying slot a {@link #MODULATE} colour reads (r; g and b follow). */
    public static final int COLOUR_SLOT = 2;
    /**
     * The flat value ({@link VertexLayout#flats()}) holding a triangle's one colour in a layout with no
     * colour varyings: what a {@link #MODULATE} colour reads there, as {@link #flatColour} packs it.
     */
    public static final int FLAT_COLOUR = 0;

    /**
     * Colour: the texel times the triangle's one colour, the same at its three corners (flat shading,
     * a face lit evenly) — {@link #MODULATE} with the colour taken once per triangle instead of
     * interpolated per pixel. Not a material's state: {@link Rasterizer} chooses it per triangle for a
     * modulating material.
     */
    static final int CONSTANT = 2;

    private static final int COLOUR_MASK = 3;
    private static final int WRITE_MASK = 3 << 2;

    private PixelState() {
    }

    /** The colour field of {@code state}: {@link #TEXEL} or {@link #MODULATE}. */
    public static int colour(int state) {
        return state & COLOUR_MASK;
    }

    /** The write field of {@code state}: {@link #OPAQUE}, {@link #ALPHA_TEST} or {@link #BLEND}. */
    public static int write(int state) {
        return state & WRITE_MASK;
    }

    /** Whether {@code state} is one colour and one write of the constants above. */
    public static boolean valid(int state) {
        return (state & ~(COLOUR_MASK | WRITE_MASK)) == 0 && colour(state) <= MODULATE && write(state) <= BLEND;
    }

    /**
     * {@code state}, checked.
     *
     * @throws IllegalArgumentException when it is not {@link #valid}
     */
    public static int check(int state) {
        if (!valid(state)) {
            throw new IllegalArgumentException("pixel state " + state + " is not a colour (TEXEL, MODULATE) "
                    + "joined with a write (OPAQUE, ALPHA_TEST, BLEND)");
        }
        return state;
    }

    /** The varyings a triangle's layout needs for {@code state}: s, t, and r, g, b when it modulates. */
    public static int varyingsNeeded(int state) {
        return colour(state) == MODULATE ? COLOUR_SLOT + 3 : COLOUR_SLOT;
    }

    /**
     * Whether triangles of {@code layout} can be filled in {@code state}: a modulating state needs a
     * colour, in varyings ({@link #varyingsNeeded}) or once per triangle in flat value
     * {@link #FLAT_COLOUR}.
     */
    public static boolean carried(int state, VertexLayout layout) {
        return varyingsNeeded(state) <= layout.varyings() || layout.flats() > FLAT_COLOUR;
    }

    /**
     * The flat value {@link #FLAT_COLOUR} of a triangle of colour r, g, b (0..1): the three channels in
     * the 16 fractional bits the modulation takes them in (kept within 0..2<sup>16</sup>, as a
     * {@link #MODULATE} pixel rounds its colour), packed 17 bits each into one integer below
     * 2<sup>51</sup>, which a double holds exactly. One number per triangle instead of three: the
     * geometry copies it, the setup unpacks it with shifts ({@link TriangleSetup}), and it is the key of
     * the triangle's lit copy of its texture ({@link LitTextures}).
     */
    public static double flatColour(double r, double g, double b) {
        return LitTextures.colourKey(Modulate.f16(r), Modulate.f16(g), Modulate.f16(b));
    }

    /**
     * Channel {@code k} (0 red, 1 green, 2 blue) of a {@link #flatColour}, 0..1: the colour a pixel
     * is modulated by, within 2<sup>-17</sup> of the channel packed.
     */
    public static double flatChannel(double flatColour, int k) {
        return LitTextures.channel16((long) flatColour, k) / (double) Modulate.ONE;
    }
}
