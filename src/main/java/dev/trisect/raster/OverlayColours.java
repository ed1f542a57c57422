package dev.trisect.raster;

import dev.trisect.render.BorderStyle;
import dev.trisect.tessellate.EdgeBound;

/**
 * The colours the border overlay draws a triangle's outline in, chosen in this one place: yellow, by
 * split depth, or by error bound ({@link BorderStyle.Colouring}); a fallback piece is magenta in each.
 */
public final class OverlayColours {
    /** An ordinary piece (or triangle): yellow, #FFFF00. */
    public static final int PIECE = 0xFFFFFF00;
    /**
     * A piece a cap stopped short of its split policy, filled per pixel by the fallback: magenta,
     * #FF00FF, which no ordinary outline uses and which stands out on most textures.
     */
    public static final int FALLBACK = 0xFFFF00FF;
    /** Colour of a piece whose bound exceeds the threshold: red. */
    public static final int OVER_BOUND = 0xFFFF2020;

    private OverlayColours() {
    }

    /** The outline colour of triangle {@code tri}, plain yellow style, ARGB with opaque alpha. */
    static int of(ScreenTriangles triangles, int tri) {
        return triangles.perPixel()[tri] ? FALLBACK : PIECE;
    }

    /**
     * The outline colour of triangle {@code tri} in a style.
     *
     * @param maxLevel the depth cap (the level drawn red in {@link BorderStyle.Colouring#DEPTH})
     * @param maxError the Max error threshold, pixels (the bound drawn yellow in {@link BorderStyle.Colouring#BOUND})
     */
    static int of(ScreenTriangles triangles, int tri, BorderStyle.Colouring colouring, int maxLevel, double maxError) {
        if (triangles.perPixel()[tri]) {
            return FALLBACK;
        }
        return switch (colouring) {
            case YELLOW -> PIECE;
            case DEPTH -> depth(triangles.levels()[tri], maxLevel);
            case BOUND -> bound(worstBound(triangles, tri) / maxError);
        };
    }

    /** Split-level colour: hue from cyan at level 0 through green and yellow to red at {@code maxLevel}. */
    public static int depth(int level, int maxLevel) {
        double f = maxLevel <= 0 ? 1 : Math.min(1, (double) level / maxLevel);
        return hue(0.5 * (1 - f));
    }

    /**
     * Bound colour for the ratio of a piece's worst edge bound to the threshold: green at 0, yellow at
     * 1 (the threshold), red above it.
     */
    public static int bound(double ratio) {
        if (!(ratio <= 1)) {
            return OVER_BOUND;
        }
        double f = Math.max(0, ratio);
        return hue(1.0 / 3 - f / 6);
    }

    /**
     * The largest affine error bound of the triangle's three edges, pixels: {@link EdgeBound} of each
     * edge's screen length and its end depths (w = 1 / q).
     */
    static double worstBound(ScreenTriangles triangles, int tri) {
        double[] sc = triangles.screen();
        double[] at = triangles.attributes();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        int a = tri * triangles.attributeStride();
        int cs = triangles.cornerStride();
        double worst = 0;
        for (int e = 0; e < 3; e++) {
            int f = (e + 1) % 3;
            double length = Math.hypot(sc[s + 2 * e] - sc[s + 2 * f], sc[s + 2 * e + 1] - sc[s + 2 * f + 1]);
            worst = Math.max(worst, EdgeBound.affineError(length, 1 / at[a + cs * e], 1 / at[a + cs * f]));
        }
        return worst;
    }

    /** A fully saturated, full-brightness colour of hue {@code h} in turns (0 red, 1/6 yellow, 1/3 green, 1/2 cyan). */
    static int hue(double h) {
        double x = (h - Math.floor(h)) * 6;
        int sector = (int) x;
        int rise = (int) Math.round((x - sector) * 255);
        int fall = 255 - rise;
        int rgb = switch (sector) {
            case 0 -> 0xFF0000 | rise << 8;
            case 1 -> fall << 16 | 0x00FF00;
            case 2 -> 0x00FF00 | rise;
            case 3 -> fall << 8 | 0x0000FF;
            case 4 -> rise << 16 | 0x0000FF;
            default -> 0xFF0000 | fall;
        };
        return 0xFF000000 | rgb;
    }
}
