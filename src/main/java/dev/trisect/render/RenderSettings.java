package dev.trisect.render;

import dev.trisect.render.BorderStyle;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.TextureFilter;

/**
 * How a frame is drawn.
 *
 * @param mode         texturing path
 * @param tessellation split policy and caps, used by {@link RenderMode#TESSELLATED}; its max error also
 *                     spaces the knots of {@link RenderMode#SPANS}
 * @param cull         back-face culling
 * @param background   background colour, 0xRRGGBB
 * @param borders      draw the yellow outline of every piece filled
 * @param filter       texture filter, in every path
 * @param borderStyle  how the outlines are coloured and whether they fade where pieces are dense
 */
public record RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull,
                             int background, boolean borders, TextureFilter filter,
                             BorderStyle borderStyle) {

    public RenderSettings {
        if (mode == null || tessellation == null || cull == null || filter == null || borderStyle == null) {
            throw new IllegalArgumentException(
                    "render settings need a mode, tessellation settings, a cull mode and a texture filter");
        }
    }

    /** Settings with plain yellow borders. */
    public RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull, int background,
                          boolean borders, TextureFilter filter) {
        this(mode, tessellation, cull, background, borders, filter, BorderStyle.plain());
    }

    /** Settings with nearest sampling. */
    public RenderSettings(RenderMode mode, TessellationSettings tessellation, CullMode cull, int background,
                          boolean borders) {
        this(mode, tessellation, cull, background, borders, TextureFilter.NEAREST);
    }

    /** Tessellated, default split settings, back-face culling, black, no borders, nearest sampling. */
    public static RenderSettings defaults() {
        return new RenderSettings(RenderMode.TESSELLATED, TessellationSettings.defaults(), CullMode.BACK, 0, false);
    }

    /** A copy with another mode. */
    public RenderSettings withMode(RenderMode m) {
        return new RenderSettings(m, tessellation, cull, background, borders, filter, borderStyle);
    }

    /** A copy with other tessellation settings. */
    public RenderSettings withTessellation(TessellationSettings t) {
        return new RenderSettings(mode, t, cull, background, borders, filter, borderStyle);
    }

    /** A copy with another cull mode. */
    public RenderSettings withCull(CullMode c) {
        return new RenderSettings(mode, tessellation, c, background, borders, filter, borderStyle);
    }

    /** A copy with another background. */
    public RenderSettings withBackground(int rgb) {
        return new RenderSettings(mode, tessellation, cull, rgb, borders, filter, borderStyle);
    }

    /** A copy with the border overlay on or off. */
    public RenderSettings withBorders(boolean on) {
        return new RenderSettings(mode, tessellation, cull, background, on, filter, borderStyle);
    }

    /** A copy with another texture filter. */
    public RenderSettings withFilter(TextureFilter f) {
        return new RenderSettings(mode, tessellation, cull, background, borders, f, borderStyle);
    }

    /** A copy with another border style. */
    public RenderSettings withBorderStyle(BorderStyle b) {
        return new RenderSettings(mode, tessellation, cull, background, borders, filter, b);
    }
}
