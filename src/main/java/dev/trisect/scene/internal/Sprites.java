package dev.trisect.scene.internal;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.raster.QuadRaster;
import dev.trisect.scene.Billboard;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Label;
import dev.trisect.scene.Scene;
import dev.trisect.scene.ScreenText;
import dev.trisect.texture.internal.GlyphAtlas;
import java.awt.Font;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * A frame's billboards, labels and screen text laid out as screen-aligned quads ({@link QuadRaster}) for
 * one camera and frame size: each point to clip space by its object's model-view-projection, dropped
 * unless it lies between the near and far planes, then its rectangle in pixels at the point's 1/w.
 *
 * <p>Order (the quads draw in it): the depth-tested billboards and labels farthest first (their
 * points' eye depth, so that blended ones compose over those behind them), then the ones drawn on top,
 * farthest first; then the screen text in its order ({@link #screenText}). Within a label, its backdrop
 * and then its glyphs.
 *
 * <p>Sizes the API gives in pixels (fonts, pixel-sized billboards, backdrops, margins) are multiplied by
 * the frame's pixel scale: frame pixels per pixel of the API, 1 for a picture, a view's screen scale on a
 * high-density screen (a 12-pixel label is then as tall as Swing's 12-pixel text beside it).
 */
public final class Sprites {
    /** Pixels a backdrop reaches beyond its text on each side. */
    static final int PAD = 2;
    /** The texture of a backdrop: one opaque white texel, its colour and alpha from the tint. */
    private static final int[] WHITE = {0xFFFFFFFF};

    /**
     * A label where it was drawn, for the pixel inspector.
     *
     * @param label  the label
     * @param object the name of its object, or null
     * @param left   the first column of its text's box
     * @param top    the first row
     * @param right  one past the last column
     * @param bottom one past the last row
     * @param firstQuad its first quad (backdrop or glyph) in the frame's quads
     * @param endQuad   one past its last quad
     */
    public record Placed(Label label, String object, int left, int top, int right, int bottom, int firstQuad,
                         int endQuad) {
    }

    /** A billboard or label with its point on screen, before sorting. */
    private record Item(Object what, String object, double x, double y, double w, double pixelsPerUnit) {
    }

    private final List<Placed> labels = new ArrayList<>();
    /** Frame pixels per pixel of the API. */
    private final double scale;

    /**
     * Lays out every billboard and label of {@code placed} into {@code quads}.
     *
     * @param placed         the frame's objects
     * @param viewProjection world space to clip space
     * @param camera         the camera, for world sizes
     * @param width          frame width, pixels
     * @param height         frame height, pixels
     * @param scale          frame pixels per pixel of the API, at least 1
     */
    Sprites(List<Scene.Placed> placed, Mat4 viewProjection, Camera camera, int width, int height,
            QuadRaster quads, double scale) {
        this.scale = scale;
        Viewport viewport = new Viewport(width, height);
        // Pixels per world unit at w = 1 (gluPerspective: f = cot(fovY / 2) maps to half the height).
        double focal = height / 2.0 / Math.tan(Math.toRadians(camera.fovY()) / 2);
        List<Item> depthTested = new ArrayList<>();
        List<Item> onTop = new ArrayList<>();
        double[] clip = new double[4];
        for (Scene.Placed o : placed) {
            if (o.billboards().isEmpty() && o.labels().isEmpty()) {
                continue;
            }
            Mat4 mvp = viewProjection.mul(o.world());
            String name = o.object().name();
            for (Billboard b : o.billboards()) {
                Item item = item(b, b.at(), name, mvp, viewport, clip, focal);
                if (item != null) {
                    (b.isOnTop() ? onTop : depthTested).add(item);
                }
            }
            for (Label l : o.labels()) {
                Item item = item(l, l.at(), name, mvp, viewport, clip, focal);
                if (item != null) {
                    (l.isOnTop() ? onTop : depthTested).add(item);
                }
            }
        }
        Comparator<Item> farthestFirst = Comparator.comparingDouble(i -> -i.w());
        depthTested.sort(farthestFirst);
        onTop.sort(farthestFirst);
        for (Item i : depthTested) {
            draw(i, quads, 0);
        }
        for (Item i : onTop) {
            draw(i, quads, QuadRaster.ON_TOP);
        }
    }

    /**
     * Lays out every billboard and label of {@code placed} for {@code camera} and a {@code width x height}
     * frame into {@code quads} (after what they hold).
     *
     * @return the layout, which knows where its labels went
     */
    public static Sprites layOut(List<Scene.Placed> placed, Camera camera, int width, int height, QuadRaster quads) {
        return new Sprites(placed, camera.viewProjection(new Viewport(width, height)), camera, width, height, quads, 1);
    }

    /** The labels drawn, in drawing order, with their boxes. */
    public List<Placed> labels() {
        return labels;
    }

    private static Item item(Object what, Vec3 at, String name, Mat4 mvp, Viewport viewport, double[] clip,
                             double focal) {
        mvp.transformPoint(at.x(), at.y(), at.z(), clip, 0);
        double w = clip[3];
        // Between the near and far planes (-w <= z <= w), in front of the eye; finite.
        if (!(w > 0 && clip[2] >= -w && clip[2] <= w) || !Double.isFinite(clip[0] + clip[1])) {
            return null;
        }
        return new Item(what, name, viewport.screenX(clip[0], w), viewport.screenY(clip[1], w), w, focal / w);
    }

    private void draw(Item i, QuadRaster quads, int onTop) {
        double q = 1 / i.w();
        if (i.what() instanceof Billboard b) {
            double w = b.sizedInPixels() ? b.width() * scale : b.width() * i.pixelsPerUnit();
            double h = b.sizedInPixels() ? b.height() * scale : b.height() * i.pixelsPerUnit();
            // Billboards are scene content, fogged by their depth as OpenGL fogs every fragment; labels and
            // screen text are annotations, never fogged (docs/conventions.md, "Fog").
            int mode = (b.isBlended() ? QuadRaster.BLEND : QuadRaster.TEST) | QuadRaster.FOG | onTop;
            var t = b.texture();
            quads.add(i.x() - w / 2, i.y() - h / 2, i.x() + w / 2, i.y() + h / 2, q, t.argb(), t.width(), 0,
                    t.width(), t.height(), mode, 0xFFFFFFFF, QuadRaster.BILLBOARD);
        } else {
            Label l = (Label) i.what();
            GlyphAtlas atlas = GlyphAtlas.of(scaled(l.font(), scale));
            String[] lines = l.text().split("\n", -1);
            int boxHeight = lines.length * atlas.lineHeight();
            // The box's bottom on the point, centred across it; whole pixels, so texels meet pixels.
            int top = (int) Math.round(i.y()) - boxHeight;
            int boxWidth = widest(atlas, lines);
            int left = (int) Math.round(i.x() - boxWidth / 2.0);
            int first = quads.count();
            text(atlas, lines, left, top, boxWidth, 0.5, q, l.colour(), l.background(), pad(scale), onTop, quads);
            labels.add(new Placed(l, i.object(), left, top, left + boxWidth, top + boxHeight, first, quads.count()));
        }
    }

    /**
     * {@code font} at {@code scale} times its size, rounded to whole pixels (glyphs stay crisp, and one
     * scale shares one atlas) and kept within the atlas's sizes.
     */
    static Font scaled(Font font, double scale) {
        if (scale == 1) {
            return font;
        }
        return font.deriveFont((float) Math.max(1, Math.min(GlyphAtlas.MAX_FONT_SIZE, Math.round(font.getSize2D() * scale))));
    }

    /** The backdrop's reach beyond its text at {@code scale}, whole pixels. */
    private static int pad(double scale) {
        return (int) Math.round(PAD * scale);
    }

    /**
     * Lays out {@code t} over a {@code width x height} frame into {@code quads}, on top, its font and margin
     * at {@code scale} (frame pixels per pixel of the API).
     */
    static void screenText(ScreenText t, int width, int height, QuadRaster quads, double scale) {
        GlyphAtlas atlas = GlyphAtlas.of(scaled(t.font(), scale));
        String[] lines = t.text().split("\n", -1);
        int boxWidth = widest(atlas, lines);
        int boxHeight = lines.length * atlas.lineHeight();
        boolean right = t.corner() == ScreenText.Corner.TOP_RIGHT || t.corner() == ScreenText.Corner.BOTTOM_RIGHT;
        boolean bottom = t.corner() == ScreenText.Corner.BOTTOM_LEFT
                || t.corner() == ScreenText.Corner.BOTTOM_RIGHT;
        int margin = (int) Math.round(t.margin() * scale);
        int left = right ? width - margin - boxWidth : margin;
        int top = bottom ? height - margin - boxHeight : margin;
        text(atlas, lines, left, top, boxWidth, right ? 1 : 0, 0, t.colour(), t.background(), pad(scale),
                QuadRaster.ON_TOP, quads);
    }

    /** The width of the widest line, pixels. */
    private static int widest(GlyphAtlas atlas, String[] lines) {
        int widest = 0;
        for (String line : lines) {
            widest = Math.max(widest, advance(atlas, line));
        }
        return widest;
    }

    /** The pen's travel over {@code line}, pixels. */
    static int advance(GlyphAtlas atlas, String line) {
        int pen = 0;
        for (int k = 0; k < line.length(); k = line.offsetByCodePoints(k, 1)) {
            pen += atlas.glyph(line.codePointAt(k)).advance();
        }
        return pen;
    }

    /**
     * The glyphs of {@code lines} in a box whose top-left pixel is (left, top), each line placed at
     * {@code align} of the room the widest leaves it (0 left, 0.5 centred, 1 right), after the backdrop,
     * which reaches {@code pad} pixels beyond the box.
     */
    private static void text(GlyphAtlas atlas, String[] lines, int left, int top, int boxWidth, double align,
                             double q, int rgb, int background, int pad, int onTop, QuadRaster quads) {
        int lineHeight = atlas.lineHeight();
        if (background >>> 24 != 0) {
            quads.add(left - pad, top - pad, left + boxWidth + pad, top + lines.length * lineHeight + pad, q, WHITE,
                    1, 0, 1, 1, QuadRaster.BLEND | QuadRaster.TINT | onTop, background, QuadRaster.OTHER);
        }
        int mode = QuadRaster.TEST | QuadRaster.TINT | onTop;
        for (int n = 0; n < lines.length; n++) {
            String line = lines[n];
            // One line is the box's width: its advance is not measured again.
            int pen = left + (lines.length == 1 ? 0 : (int) Math.round(align * (boxWidth - advance(atlas, line))));
            int baseline = top + n * lineHeight + atlas.ascent();
            for (int k = 0; k < line.length(); k = line.offsetByCodePoints(k, 1)) {
                GlyphAtlas.Glyph g = atlas.glyph(line.codePointAt(k));
                if (g.width() > 0) {
                    int x = pen + g.left();
                    int y = baseline + g.top();
                    quads.add(x, y, x + g.width(), y + g.height(), q, g.texels(), GlyphAtlas.WIDTH,
                            g.y() * GlyphAtlas.WIDTH + g.x(), g.width(), g.height(), mode, rgb, QuadRaster.GLYPH);
                }
                pen += g.advance();
            }
        }
    }
}
