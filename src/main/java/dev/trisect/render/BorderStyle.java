package dev.trisect.render;

import java.util.Locale;

/**
 * How the border overlay colours each outline, and whether it fades outlines where pieces are dense.
 *
 * @param colouring yellow, by split depth, or by error bound (fallback pieces are magenta in all three)
 * @param fade      draw the outlines of small pieces translucent, by the radius of their inscribed circle
 *                  (the raster overlay's {@code fadeAlpha}), so that
 *                  near the horizon, where pieces are a few pixels across, the texture still shows
 *                  through instead of a solid band of lines
 * @param onlyFallback outline the fallback pieces alone (magenta): the demo's highlight of the
 *                  triangles a cap stopped short, while it warns of them with the borders off
 */
public record BorderStyle(Colouring colouring, boolean fade, boolean onlyFallback) {
    /** What an outline's colour says. */
    public enum Colouring {
        /** Every piece yellow. */
        YELLOW,
        /** The piece's split level: cyan (never split) through green and yellow to red (the depth cap). */
        DEPTH,
        /**
         * The piece's worst edge's affine error bound over the Max error threshold: green (far within),
         * yellow (at it), red (above it). In the span path the outlines stay yellow and the knot ticks
         * take the bound of their segments instead.
         */
        BOUND;

        /**
         * The name on the command line: yellow, depth or bound.
         *
         * @return the lower-case name
         */
        public String id() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * A style outlining every piece.
     *
     * @param colouring yellow, by split depth, or by error bound
     * @param fade      draw the outlines of small pieces translucent
     */
    public BorderStyle(Colouring colouring, boolean fade) {
        this(colouring, fade, false);
    }

    /**
     * Only the fallback pieces, in magenta.
     *
     * @return the style
     */
    public static BorderStyle fallbackOnly() {
        return new BorderStyle(Colouring.YELLOW, false, true);
    }

    /**
     * Checks that a colouring is given.
     *
     * @param colouring    yellow, by split depth, or by error bound
     * @param fade         draw the outlines of small pieces translucent
     * @param onlyFallback outline the fallback pieces alone
     * @throws IllegalArgumentException when {@code colouring} is null
     */
    public BorderStyle {
        if (colouring == null) {
            throw new IllegalArgumentException("a border style needs a colouring");
        }
    }

    /**
     * Plain yellow, no fading: the overlay as it always was.
     *
     * @return the style
     */
    public static BorderStyle plain() {
        return new BorderStyle(Colouring.YELLOW, false);
    }
}
