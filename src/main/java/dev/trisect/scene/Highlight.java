package dev.trisect.scene;

/**
 * How a view marks a node while the pointer is over it (see {@link Node#setHoverHighlight}): the
 * node's pixels tinted toward a colour, or outlined in it. Drawn over the frame after it is filled,
 * from the frame's own record of which object each pixel shows: textures and materials are untouched,
 * and the frame is not drawn twice.
 *
 * @param rgb     the colour, 0xRRGGBB
 * @param outline true for a one-pixel outline along the node's visible edge (its pixels next to a
 *                pixel of anything else), false for a tint of all its pixels (half way to {@code rgb})
 */
public record Highlight(int rgb, boolean outline) {
    /**
     * The highlight as given, colour reduced to 0xRRGGBB.
     *
     * @param rgb     the colour, 0xRRGGBB
     * @param outline true for an outline, false for a tint
     */
    public Highlight {
        rgb &= 0xFFFFFF;
    }

    /**
     * A tint: each of the node's pixels half way to {@code rgb}.
     *
     * @param rgb the colour, 0xRRGGBB
     * @return the highlight
     */
    public static Highlight tint(int rgb) {
        return new Highlight(rgb, false);
    }

    /**
     * An outline: the node's pixels along its visible edge in {@code rgb}.
     *
     * @param rgb the colour, 0xRRGGBB
     * @return the highlight
     */
    public static Highlight outline(int rgb) {
        return new Highlight(rgb, true);
    }
}
