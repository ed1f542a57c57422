package dev.trisect.view.internal;

import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRecord;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.pipeline.PieceInfo;
import dev.trisect.raster.Commands;
import dev.trisect.raster.QuadRaster;
import dev.trisect.raster.RowKnots;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.internal.DrawnFrame;
import dev.trisect.scene.internal.Sprites;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Locale;

/**
 * The pixel inspector's numbers for one pixel, read from the renderer's own buffers of the frame just
 * drawn: this path's UV output and depth, the per-pixel path's UV output, the piece the renderer
 * filled there, and the exact displacement. Render thread only (it asks the renderer about its last
 * frame).
 */
public final class PixelInspector {
    private PixelInspector() {
    }

    /**
     * What one pixel shows.
     *
     * @param x            frame pixel column
     * @param y            frame pixel row (0 at the top)
     * @param argb         its colour in this path
     * @param triangle     input triangle, 0-based, numbered across the frame's objects, or -1 where nothing
     *                     was drawn
     * @param owner        the object that triangle belongs to and its index in the object's mesh; null
     *                     where nothing was drawn
     * @param w            view depth, view-space units (1 / the depth buffer's 1/w)
     * @param s            this path's level-0 texel coordinate s (before wrapping)
     * @param t            and t
     * @param refS         the per-pixel path's s at this pixel (NaN if it drew another triangle or none)
     * @param refT         and t
     * @param displacement exact displacement of this pixel, pixels (NaN where undefined)
     * @param piece        the piece filled here, or null
     * @param lambda       level of detail log2(rho) of this path's texture mapping at the pixel
     * @param mipLevel     the mipmap level sampled (the lower of the two trilinear blends), 0 without mipmaps
     * @param texelX       nearest texel on that level, wrapped
     * @param texelY       and its row
     * @param knots        in the span path, the knots of this pixel's row of the filled triangle; else null
     * @param outline      with the borders on, the piece filled per pixel (a sliver, or one a cap stopped
     *                     short) whose magenta outline lights this pixel, the last drawn when several do;
     *                     else null. It explains a magenta mark the pixel's own piece does not.
     * @param outlineOwner the object of that outline's triangle, or null without an outline
     * @param refArgb      the per-pixel path's colour at this pixel, or 0 when it was not drawn
     * @param triangle2d   the input triangle on screen, frame pixels {x0, y0, x1, y1, ...}: its corners, or
     *                     where it crosses the near plane the part in front of it (four corners); null
     *                     where nothing was drawn
     * @param light        the lit colour r, g, b (0..1) the pixel's texel was multiplied by, as its path
     *                     interpolates it; null where the frame carries no colour or nothing was drawn
     * @param shape        the line segment, label, billboard or screen text drawn last over the triangles at
     *                     this pixel, named ({@link #shapeOf}); null where none was or the pixel was not probed
     */
    public record Inspection(int x, int y, int argb, int triangle, DrawnFrame.Owner owner, double w, double s, double t,
                      double refS, double refT, double displacement, PieceInfo piece, double lambda, int mipLevel,
                      int texelX, int texelY, RowKnots knots, PieceInfo outline, DrawnFrame.Owner outlineOwner,
                      int refArgb, double[] triangle2d, double[] light, String shape) {
        /** The span segment holding the pixel (the index of its first knot), or -1 (not the span path, or a lone knot). */
        public int segment() {
            return knots == null ? -1 : knots.segmentOf(x);
        }
    }

    /**
     * Inspects pixel (x, y) of {@code frame}, against {@code reference} (the per-pixel path's frame, with UV).
     *
     * @param record      the renderer's record of the frame ({@link FrameRenderer#drawn()}), asked which
     *                    piece shows the pixel, whose outline marks it and the knots of its row
     * @param perspective the frame took the per-pixel path or the span path (whose knots
     *                    {@link FrameRecord#knotsAt} then gives)
     * @param borders     the borders are drawn over the frame (so fallback pieces' outlines may light the pixel)
     * @param drawn       the frame's objects: the texture and the object of each frame triangle
     * @param probed      the frame was drawn probing this pixel ({@link FrameRenderer#probe}), so the record
     *                    names the line or quad drawn last there
     */
    static Inspection inspect(FrameRecord record, Framebuffer frame, Framebuffer reference, TexelToScreen exact,
                              DrawnFrame drawn, TextureFilter filter, boolean perspective, boolean borders, int x,
                              int y, boolean probed) {
        String shape = probed ? shapeOf(record.probed(), drawn) : null;
        int i = y * frame.width() + x;
        double[] uv = frame.uv();
        int id = (int) uv[3 * i + 2] - 1;
        int argb = frame.colour()[i];
        PieceInfo outline = borders ? record.fallbackOutlineAt(x, y, frame.depth()[i]) : null;
        DrawnFrame.Owner outlineOwner = outline == null ? null : drawn.ownerOf(outline.triangle());
        int refArgb = reference == null ? 0 : reference.colour()[i];
        if (id < 0) {
            return new Inspection(x, y, argb, -1, null, Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN,
                    Double.NaN, null, Double.NaN, 0, 0, 0, null, outline, outlineOwner, refArgb, null, null, shape);
        }
        double q = frame.depth()[i];
        double s = uv[3 * i];
        double t = uv[3 * i + 1];
        double[] ref = reference == null ? null : reference.uv();
        boolean same = ref != null && (int) ref[3 * i + 2] - 1 == id;
        double refS = same ? ref[3 * i] : Double.NaN;
        double refT = same ? ref[3 * i + 1] : Double.NaN;
        double displacement = exact == null ? Double.NaN : exact.displacement(id, s, t, x, y);
        PieceInfo piece = record.pieceAt(x, y, id, q);
        RowKnots knots = record.knotsAt(x, y, id, q);
        double lambda = Double.NaN;
        if (piece != null) {
            double[] d = perspective || piece.fallback() ? perspectiveDerivatives(piece, x + 0.5, y + 0.5)
                    : piece.affineDerivatives();
            lambda = Lod.lambda(d[0], d[1], d[2], d[3]);
            int k = knots == null ? -1 : knots.segmentOf(x);
            if (k >= 0) {
                // The span path's trilinear level is its segment's: the mean of its two knots'.
                double[] a = perspectiveDerivatives(piece, knots.columns()[k] + 0.5, y + 0.5);
                double[] b = perspectiveDerivatives(piece, knots.columns()[k + 1] + 0.5, y + 0.5);
                lambda = 0.5 * (Lod.lambda(a[0], a[1], a[2], a[3]) + Lod.lambda(b[0], b[1], b[2], b[3]));
            }
        }
        Texture tex = drawn.textureOf(id);
        MipChain chain = tex.mipChain();
        int level = 0;
        if (filter == TextureFilter.TRILINEAR && lambda > 0) {
            level = (int) Math.min(chain.maxLevel(), Math.floor(lambda));
        }
        int tx = Math.floorMod((int) Math.floor(s * chain.scaleS(level)), chain.width(level));
        int ty = Math.floorMod((int) Math.floor(t * chain.scaleT(level)), chain.height(level));
        return new Inspection(x, y, argb, id, drawn.ownerOf(id), 1 / q, s, t, refS, refT, displacement, piece, lambda,
                level, tx, ty, knots, outline, outlineOwner, refArgb, onScreen(drawn.draws(), id, frame.width(),
                frame.height()), lightAt(piece, perspective, knots, x, y), shape);
    }

    /**
     * The line segment or quad {@code probed} ({@link FrameRecord#probed}) as the user knows it: the segment
     * of an object's lines or wireframe with its colour and width, the label with its object, a billboard,
     * the screen text; null for null.
     */
    static String shapeOf(int[] probed, DrawnFrame drawn) {
        if (probed == null) {
            return null;
        }
        Draws draws = drawn.draws();
        if (probed[0] == Commands.LINE) {
            DrawnFrame.LineOwner o = drawn.lineOwnerOf(probed[1]);
            String object = o.name() != null ? "\"" + o.name() + "\"" : "object " + (o.draw() + 1);
            return String.format(Locale.ROOT, "%s %d of %s, #%06X, %d px", o.wire() ? "wireframe edge" : "line segment",
                    probed[2], object, draws.lines(probed[1]).colours()[probed[2]] & 0xFFFFFF,
                    draws.lineWidth(probed[1]));
        }
        Sprites.Placed label = drawn.labelOfQuad(probed[1]);
        if (label != null) {
            return "label \"" + label.label().text().replace("\n", " / ") + "\""
                    + (label.object() != null ? " of \"" + label.object() + "\"" : "")
                    + (label.label().isOnTop() ? ", on top" : "");
        }
        return draws.quads().kind(probed[1]) == QuadRaster.BILLBOARD ? "a billboard" : "the screen text";
    }

    /**
     * The colour the pixel's texel was multiplied by, as its path interpolates it over {@code piece}: per
     * pixel perspective-correctly (the per-pixel path, a fallback piece), exactly at the knots and
     * linearly between them (the span path), screen-linearly (the affine and tessellated paths); null
     * without a piece or a colour.
     */
    static double[] lightAt(PieceInfo piece, boolean perspective, RowKnots knots, int x, int y) {
        if (piece == null || piece.colours() == null) {
            return null;
        }
        int k = knots == null ? -1 : knots.segmentOf(x);
        if (k < 0 || piece.fallback()) {
            return piece.colourAt(x + 0.5, y + 0.5, perspective || piece.fallback());
        }
        int a = knots.columns()[k];
        int b = knots.columns()[k + 1];
        double[] ca = piece.colourAt(a + 0.5, y + 0.5, true);
        double[] cb = piece.colourAt(b + 0.5, y + 0.5, true);
        double f = (double) (x - a) / (b - a);
        return new double[] {ca[0] + f * (cb[0] - ca[0]), ca[1] + f * (cb[1] - ca[1]), ca[2] + f * (cb[2] - ca[2])};
    }

    /**
     * Frame triangle {@code id} on screen, frame pixels {x0, y0, x1, y1, ...}: its corners projected by
     * its draw's model-view-projection, the part in front of the near plane (z &ge; -w in clip space)
     * where it crosses it — a triangle, or a quadrilateral. Null where no part lies in front.
     */
    static double[] onScreen(Draws draws, int id, int width, int height) {
        int d = draws.drawOf(id);
        int local = id - draws.firstTriangle(d);
        Mesh mesh = draws.mesh(d);
        float[] pos = mesh.positions();
        double[][] clip = new double[3][4];
        for (int k = 0; k < 3; k++) {
            int p = 3 * mesh.cornerPositions()[3 * local + k];
            draws.transform(d).transformPoint(pos[p], pos[p + 1], pos[p + 2], clip[k], 0);
        }
        // Sutherland-Hodgman against the near plane alone: the outline is drawn, not filled, so the sides
        // may reach past the screen.
        double[] kept = new double[4 * 4];
        int n = 0;
        for (int k = 0; k < 3; k++) {
            double[] a = clip[k];
            double[] b = clip[(k + 1) % 3];
            double da = a[2] + a[3];
            double db = b[2] + b[3];
            if (da >= 0) {
                System.arraycopy(a, 0, kept, 4 * n++, 4);
            }
            if ((da >= 0) != (db >= 0)) {
                double t = da / (da - db);
                for (int c = 0; c < 4; c++) {
                    kept[4 * n + c] = a[c] + t * (b[c] - a[c]);
                }
                n++;
            }
        }
        if (n < 3) {
            return null;
        }
        Viewport viewport = new Viewport(width, height);
        double[] out = new double[2 * n];
        for (int k = 0; k < n; k++) {
            double w = kept[4 * k + 3];
            if (!(w > 0)) {
                return null;
            }
            out[2 * k] = viewport.screenX(kept[4 * k], w);
            out[2 * k + 1] = viewport.screenY(kept[4 * k + 1], w);
        }
        return out;
    }

    /**
     * The exact screen derivatives {ds/dx, dt/dx, ds/dy, dt/dy} of a perspective map at (px, py):
     * s = S / Q with S = s * q, T = t * q and Q = q linear on screen, so ds/dx = (S_x - s Q_x) / Q.
     */
    static double[] perspectiveDerivatives(PieceInfo p, double px, double py) {
        double[] sc = p.screen();
        double[] a = p.attributes();
        double[] qPlane = plane(sc, a[0], a[3], a[6]);
        double[] sPlane = plane(sc, a[1] * a[0], a[4] * a[3], a[7] * a[6]);
        double[] tPlane = plane(sc, a[2] * a[0], a[5] * a[3], a[8] * a[6]);
        double dx = px - sc[0];
        double dy = py - sc[1];
        double q = qPlane[0] + qPlane[1] * dx + qPlane[2] * dy;
        double s = (sPlane[0] + sPlane[1] * dx + sPlane[2] * dy) / q;
        double t = (tPlane[0] + tPlane[1] * dx + tPlane[2] * dy) / q;
        return new double[] {(sPlane[1] - s * qPlane[1]) / q, (tPlane[1] - t * qPlane[1]) / q,
            (sPlane[2] - s * qPlane[2]) / q, (tPlane[2] - t * qPlane[2]) / q};
    }

    /** {value at corner 0, d/dx, d/dy} of the linear function through the corners' values. */
    private static double[] plane(double[] sc, double v0, double v1, double v2) {
        double ex1 = sc[2] - sc[0];
        double ey1 = sc[3] - sc[1];
        double ex2 = sc[4] - sc[0];
        double ey2 = sc[5] - sc[1];
        double det = ex1 * ey2 - ex2 * ey1;
        double d1 = v1 - v0;
        double d2 = v2 - v0;
        return new double[] {v0, (d1 * ey2 - d2 * ey1) / det, (ex1 * d2 - ex2 * d1) / det};
    }
}
