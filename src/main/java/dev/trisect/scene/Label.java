package dev.trisect.scene;

import dev.trisect.math.Vec3;
import dev.trisect.texture.internal.GlyphAtlas;
import java.awt.Font;
import java.util.Objects;

/**
 * Text at a point of the scene, facing the camera, its letters a fixed size on screen: a label. Its
 * glyphs come from an AWT font rasterized once, without antialiasing, into a glyph texture (any
 * character the font has), and are drawn alpha-tested, each texel on one pixel, in the label's colour.
 * The text is centred on the point horizontally and sits on it: the bottom of its last line (the
 * font's descent below the baseline) is on the point. Lines are split at {@code '\n'} and centred.
 * It is depth-tested at the point's depth unless {@link #onTop()}. It is not fogged by the scene's fog:
 * an annotation stays legible at any distance (text that is part of the scene is a {@link TextPanel},
 * fogged as any object). Its pixels are a picture's pixels, or a view's logical pixels (on a
 * high-density screen, the screen's scale times as many device pixels, as Swing's text). Immutable; give an object its labels with {@link SceneObject#setLabels}.
 *
 * <pre>{@code
 * cube.setLabels(List.of(Label.of("crate", new Vec3(0, 0.7, 0)).withColour(0xFFFF00)));
 * }</pre>
 */
public final class Label {
    /** The font of a label unless given: AWT's logical sans-serif, plain, 16 pixels. */
    public static final Font DEFAULT_FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 16);

    private final String text;
    private final Vec3 at;
    private final Font font;
    private final int colour;
    private final int background;
    private final boolean onTop;

    private Label(String text, Vec3 at, Font font, int colour, int background, boolean onTop) {
        this.text = Objects.requireNonNull(text, "text is null");
        this.at = Objects.requireNonNull(at, "position is null");
        if (!at.isFinite()) {
            throw new IllegalArgumentException("a label's position must be finite, not " + at);
        }
        this.font = Objects.requireNonNull(font, "font is null");
        this.colour = colour & 0xFFFFFF;
        this.background = background;
        this.onTop = onTop;
    }

    /**
     * A white label in {@link #DEFAULT_FONT}, without a backdrop, depth-tested.
     *
     * @param text the text; {@code '\n'} starts a line
     * @param at   the point it stands on, in its object's space
     * @return the label
     * @throws NullPointerException     when {@code text} or {@code at} is null
     * @throws IllegalArgumentException when {@code at} is not finite
     */
    public static Label of(String text, Vec3 at) {
        return new Label(text, at, DEFAULT_FONT, 0xFFFFFF, 0, false);
    }

    /**
     * This label in another font.
     *
     * @param font the font; its size is the glyphs' size in pixels, 1 to 512
     * @return a copy in that font
     * @throws NullPointerException     when {@code font} is null
     * @throws IllegalArgumentException for a size outside 1 to 512 pixels
     */
    public Label withFont(Font font) {
        return new Label(text, at, GlyphAtlas.checkFont(font), colour, background, onTop);
    }

    /**
     * This label in another colour.
     *
     * @param rgb 0xRRGGBB
     * @return a copy in that colour
     */
    public Label withColour(int rgb) {
        return new Label(text, at, font, rgb, background, onTop);
    }

    /**
     * This label over a backdrop: a rectangle around the text, 2 pixels wider on each side, blended
     * behind the glyphs (0 for none).
     *
     * @param argb 0xAARRGGBB, alpha its opacity
     * @return a copy with that backdrop
     */
    public Label withBackground(int argb) {
        return new Label(text, at, font, colour, argb, onTop);
    }

    /**
     * This label drawn over everything, neither depth-tested nor writing depth.
     *
     * @return a copy drawn on top
     */
    public Label onTop() {
        return new Label(text, at, font, colour, background, true);
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
     * The point it stands on, in its object's space.
     *
     * @return the point
     */
    public Vec3 at() {
        return at;
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
     * Whether it is drawn over everything.
     *
     * @return true after {@link #onTop()}
     */
    public boolean isOnTop() {
        return onTop;
    }

    @Override
    public String toString() {
        return "Label(" + text + ")";
    }

    /**
     * Whether {@code o} is a label with the same text, point, font, colour, backdrop and placing: set
     * again, an equal label is no change to its object.
     *
     * @param o another object
     * @return true for an equal label
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Label l && text.equals(l.text) && at.equals(l.at) && font.equals(l.font)
                && colour == l.colour && background == l.background && onTop == l.onTop;
    }

    /**
     * A hash of the values {@link #equals} compares.
     *
     * @return the hash
     */
    @Override
    public int hashCode() {
        return Objects.hash(text, at, font, colour, background, onTop);
    }
}
