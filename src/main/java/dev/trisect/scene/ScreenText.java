package dev.trisect.scene;

import dev.trisect.texture.internal.GlyphAtlas;
import java.awt.Font;
import java.util.Objects;

/**
 * Text over the frame, anchored to a corner of the screen, whatever the camera: a heads-up line, a
 * legend. Drawn after everything else, on top, from the same glyph textures as {@link Label}s (an AWT
 * font rasterized once, no antialiasing), never fogged. Lines split at {@code '\n'} are aligned on the
 * corner's side. Its sizes in pixels (font, margin) are a picture's pixels, or a view's logical pixels
 * (on a high-density screen, the screen's scale times as many device pixels, as Swing's text).
 * Immutable; show it with {@link Scene#setScreenText}.
 *
 * <pre>{@code
 * scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, "60 fps"),
 *         ScreenText.of(ScreenText.Corner.BOTTOM_RIGHT, "x red\ny green\nz blue").withBackground(0x80000000)));
 * }</pre>
 */
public final class ScreenText {
    /** The corner of the screen text is anchored to. */
    public enum Corner {
        /** Top left. */
        TOP_LEFT,
        /** Top right. */
        TOP_RIGHT,
        /** Bottom left. */
        BOTTOM_LEFT,
        /** Bottom right. */
        BOTTOM_RIGHT
    }

    /** Pixels from the corner to the text unless given. */
    public static final int DEFAULT_MARGIN = 8;

    private final Corner corner;
    private final String text;
    private final Font font;
    private final int colour;
    private final int background;
    private final int margin;

    private ScreenText(Corner corner, String text, Font font, int colour, int background, int margin) {
        this.corner = Objects.requireNonNull(corner, "corner is null");
        this.text = Objects.requireNonNull(text, "text is null");
        this.font = Objects.requireNonNull(font, "font is null");
        this.colour = colour & 0xFFFFFF;
        this.background = background;
        if (margin < 0) {
            throw new IllegalArgumentException("margin must be at least 0 pixels, got " + margin);
        }
        this.margin = margin;
    }

    /**
     * White text in {@link Label#DEFAULT_FONT}, {@link #DEFAULT_MARGIN} pixels from the corner, without
     * a backdrop.
     *
     * @param corner the corner
     * @param text   the text; {@code '\n'} starts a line
     * @return the screen text
     */
    public static ScreenText of(Corner corner, String text) {
        return new ScreenText(corner, text, Label.DEFAULT_FONT, 0xFFFFFF, 0, DEFAULT_MARGIN);
    }

    /**
     * The same in other words.
     *
     * @param text the text
     * @return a copy with that text
     */
    public ScreenText withText(String text) {
        return new ScreenText(corner, text, font, colour, background, margin);
    }

    /**
     * The same in another font.
     *
     * @param font the font; its size is the glyphs' size in pixels, 1 to 512
     * @return a copy in that font
     * @throws NullPointerException     when {@code font} is null
     * @throws IllegalArgumentException for a size outside 1 to 512 pixels
     */
    public ScreenText withFont(Font font) {
        return new ScreenText(corner, text, GlyphAtlas.checkFont(font), colour, background, margin);
    }

    /**
     * The same in another colour.
     *
     * @param rgb 0xRRGGBB
     * @return a copy in that colour
     */
    public ScreenText withColour(int rgb) {
        return new ScreenText(corner, text, font, rgb, background, margin);
    }

    /**
     * The same over a backdrop: a rectangle around the text, 2 pixels wider on each side, blended behind
     * the glyphs (0 for none).
     *
     * @param argb 0xAARRGGBB, alpha its opacity
     * @return a copy with that backdrop
     */
    public ScreenText withBackground(int argb) {
        return new ScreenText(corner, text, font, colour, argb, margin);
    }

    /**
     * The same at another distance from its corner.
     *
     * @param pixels pixels from each of the corner's two sides, at least 0
     * @return a copy with that margin
     */
    public ScreenText withMargin(int pixels) {
        return new ScreenText(corner, text, font, colour, background, pixels);
    }

    /**
     * The corner.
     *
     * @return the corner
     */
    public Corner corner() {
        return corner;
    }

    /**
     * The text.
     *
     * @return the text
     */
    public String text() {
        return text;
    }

    /**
     * The font.
     *
     * @return the font
     */
    public Font font() {
        return font;
    }

    /**
     * The colour of the glyphs.
     *
     * @return 0xRRGGBB
     */
    public int colour() {
        return colour;
    }

    /**
     * The backdrop.
     *
     * @return 0xAARRGGBB, 0 for none
     */
    public int background() {
        return background;
    }

    /**
     * Pixels from the corner.
     *
     * @return the margin
     */
    public int margin() {
        return margin;
    }

    /**
     * Whether {@code o} is a screen text with the same corner, text, font, colour, backdrop and margin:
     * set again, an equal text is no change to the scene.
     *
     * @param o another object
     * @return true for an equal screen text
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof ScreenText t && corner == t.corner && text.equals(t.text) && font.equals(t.font)
                && colour == t.colour && background == t.background && margin == t.margin;
    }

    /**
     * A hash of the values {@link #equals} compares.
     *
     * @return the hash
     */
    @Override
    public int hashCode() {
        return Objects.hash(corner, text, font, colour, background, margin);
    }
}
