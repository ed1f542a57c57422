package dev.trisect.render;

import dev.trisect.render.BorderStyle;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.TextureFilter;

/**
 * How a frame is drawn. Two presets, one for each use, then a {@code with...} for any change:
 * <ul>
 *   <li>{@link #display()}: for looking at a scene — tessellated, trilinear filtering (no shimmer as
 *       things move), a sky-blue background. A new {@code TrisectView} draws with it, and
 *       {@code SceneRenderer.renderImage(scene, camera, width, height)} uses it, so a scene looks the
 *       same in a window and in a picture unless told otherwise.</li>
 *   <li>{@link #defaults()}: OpenGL's defaults, for measuring against OpenGL — nearest sampling on
 *       black. The command line draws with it.</li>
 * </ul>
 *
 * @param mode         texturing path
 * @param tessellation split policy and caps, used by {@link RenderMode#TESSELLATED}
 * @param cull         back-face culling
 * @param background   background colour, 0xRRGGBB
 * @param borders      draw the yellow outline of every piece filled
 * @param filter       texture filter, in every path
 * @param borderStyle  how the outlines are coloured and whether they fade where pieces are dense
 * @param knotError    the span path's knot spacing ({@link RenderMode#SPANS}): the largest displacement
 *                     from true perspective allowed between two knots of a row, screen pixels, &gt; 0. A
 *                     value of its own, apart from the error policy's {@link TessellationSettings#maxError}
 *                     (the command line's {@code --max-error} sets both)
 */
public record RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull,
                             int background, boolean borders, TextureFilter filter,
                             BorderStyle borderStyle, double knotError) {

    /** The background of {@link #display()}, 0xRRGGBB: a light sky blue. */
    public static final int SKY = 0x9DB8D3;

    /** Default knot spacing of the span path, pixels: the same half pixel as the error policy's default. */
    public static final double DEFAULT_KNOT_ERROR = TessellationSettings.DEFAULT_MAX_ERROR;

    /**
     * Checks that every part is given.
     *
     * @param mode         texturing path
     * @param tessellation split policy and caps
     * @param cull         back-face culling
     * @param background   background colour, 0xRRGGBB
     * @param borders      draw the outline of every piece filled
     * @param filter       texture filter
     * @param borderStyle  how the outlines are coloured
     * @param knotError    the span path's knot spacing, screen pixels
     * @throws IllegalArgumentException when one is null, or the knot spacing is not a positive number
     */
    public RenderSettings {
        if (mode == null || tessellation == null || cull == null || filter == null || borderStyle == null) {
            throw new IllegalArgumentException(
                    "render settings need a mode, tessellation settings, a cull mode and a texture filter");
        }
        if (!(knotError > 0) || Double.isInfinite(knotError)) {
            throw new IllegalArgumentException("knot error must be a positive number of pixels, got " + knotError);
        }
    }

    /**
     * Settings with the default knot spacing ({@link #DEFAULT_KNOT_ERROR}).
     *
     * @param mode         texturing path
     * @param tessellation split policy and caps
     * @param cull         back-face culling
     * @param background   background colour, 0xRRGGBB
     * @param borders      draw the outline of every piece filled
     * @param filter       texture filter
     * @param borderStyle  how the outlines are coloured
     */
    public RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull, int background,
                          boolean borders, TextureFilter filter, BorderStyle borderStyle) {
        this(mode, tessellation, cull, background, borders, filter, borderStyle, DEFAULT_KNOT_ERROR);
    }

    /**
     * Settings with plain yellow borders.
     *
     * @param mode         texturing path
     * @param tessellation split policy and caps
     * @param cull         back-face culling
     * @param background   background colour, 0xRRGGBB
     * @param borders      draw the outline of every piece filled
     * @param filter       texture filter
     */
    public RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull, int background,
                          boolean borders, TextureFilter filter) {
        this(mode, tessellation, cull, background, borders, filter, BorderStyle.plain());
    }

    /**
     * Settings with nearest sampling.
     *
     * @param mode         texturing path
     * @param tessellation split policy and caps
     * @param cull         back-face culling
     * @param background   background colour, 0xRRGGBB
     * @param borders      draw the outline of every piece filled
     */
    public RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull, int background,
                          boolean borders) {
        this(mode, tessellation, cull, background, borders, TextureFilter.NEAREST);
    }

    /**
     * OpenGL's defaults, for measuring against OpenGL, as the command line draws: tessellated, default
     * split settings, back-face culling, black, no borders, nearest sampling.
     *
     * @return the default settings
     */
    public static RenderSettings defaults() {
        return new RenderSettings(RenderMode.TESSELLATED, TessellationSettings.defaults(), CullMode.BACK, 0, false);
    }

    /**
     * For looking at a scene, as a new view draws and a picture is taken unless told otherwise:
     * {@link #defaults()} with trilinear filtering, the {@link #SKY} background, and borders (when
     * turned on) faded yellow.
     *
     * @return the display settings
     */
    public static RenderSettings display() {
        return defaults().withFilter(TextureFilter.TRILINEAR).withBackground(SKY)
                .withBorderStyle(new BorderStyle(BorderStyle.Colouring.YELLOW, true));
    }

    /**
     * A copy with another mode.
     *
     * @param m the texturing path
     * @return a copy with that path
     */
    public RenderSettings withMode(RenderMode m) {
        return new RenderSettings(m, tessellation, cull, background, borders, filter, borderStyle, knotError);
    }

    /**
     * A copy with other tessellation settings.
     *
     * @param t the split settings
     * @return a copy with those
     */
    public RenderSettings withTessellation(TessellationSettings t) {
        return new RenderSettings(mode, t, cull, background, borders, filter, borderStyle, knotError);
    }

    /**
     * A copy with another cull mode.
     *
     * @param c the culling
     * @return a copy with that culling
     */
    public RenderSettings withCull(CullMode c) {
        return new RenderSettings(mode, tessellation, c, background, borders, filter, borderStyle, knotError);
    }

    /**
     * A copy with another background.
     *
     * @param rgb the background colour, 0xRRGGBB
     * @return a copy with that background
     */
    public RenderSettings withBackground(int rgb) {
        return new RenderSettings(mode, tessellation, cull, rgb, borders, filter, borderStyle, knotError);
    }

    /**
     * A copy with the border overlay on or off.
     *
     * @param on whether the piece outlines are drawn
     * @return a copy with the borders on or off
     */
    public RenderSettings withBorders(boolean on) {
        return new RenderSettings(mode, tessellation, cull, background, on, filter, borderStyle, knotError);
    }

    /**
     * A copy with another texture filter.
     *
     * @param f the texture filter
     * @return a copy with that filter
     */
    public RenderSettings withFilter(TextureFilter f) {
        return new RenderSettings(mode, tessellation, cull, background, borders, f, borderStyle, knotError);
    }

    /**
     * A copy with another knot spacing for the span path.
     *
     * @param px the largest displacement between two knots, screen pixels, &gt; 0
     * @return a copy with that knot spacing
     */
    public RenderSettings withKnotError(double px) {
        return new RenderSettings(mode, tessellation, cull, background, borders, filter, borderStyle, px);
    }

    /**
     * A copy with another border style.
     *
     * @param b the outlines' style
     * @return a copy with that style
     */
    public RenderSettings withBorderStyle(BorderStyle b) {
        return new RenderSettings(mode, tessellation, cull, background, borders, filter, b, knotError);
    }
}
