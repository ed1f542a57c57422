package dev.trisect.raster;

import dev.trisect.math.Viewport;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;

/**
 * Scenes for the pixel-state tests: one random triangle in the lit layout ({@link VertexLayout#of}(5):
 * s, t, then a colour r, g, b), drawn by any of the four paths with a chosen {@link PixelState} over
 * a frame already holding something, so that a write which must leave the frame alone shows.
 */
final class PixelScenes {
    static final int WIDTH = 120;
    static final int HEIGHT = 90;
    static final VertexLayout LAYOUT = VertexLayout.of(5);

    /** The paths, as {@link Rasterizer} picks its loops. */
    enum Path {
        /** Perspective, every pixel divides ({@link PerPixelLoops}). */
        PER_PIXEL,
        /** Affine in 32.32 fixed point ({@link FixedLoops}). */
        FIXED,
        /** The span path's knots ({@link KnotLoops}). */
        KNOTS,
        /** The tessellated path's one-pass fill ({@link TreeLoops}). */
        TREE
    }

    /** The span path's knot error in these scenes, pixels. */
    static final double KNOT_ERROR = 0.5;

    private PixelScenes() {
    }

    /** The values of varyings 2..4 at a corner, from its texel coordinates. */
    interface Extra {
        double[] at(double s, double t);
    }

    /**
     * A random clip-space triangle in {@link #LAYOUT}, in front of the eye and partly off screen now and
     * then: s, t within +-range/2 texels, then varyings 2..4 {@code extra.at(s, t)}.
     */
    static double[] triangle(Random random, double range, Extra extra) {
        int cs = LAYOUT.clipStride();
        double[] v = new double[3 * cs];
        for (int k = 0; k < 3; k++) {
            int o = k * cs;
            double w = 0.2 + 4.8 * random.nextDouble();
            v[o + VertexLayout.X] = (2.4 * random.nextDouble() - 1.2) * w;
            v[o + VertexLayout.Y] = (2.4 * random.nextDouble() - 1.2) * w;
            v[o + VertexLayout.Z] = (0.1 + 0.8 * random.nextDouble()) * w;
            v[o + VertexLayout.W] = w;
            v[o + VertexLayout.S] = (random.nextDouble() - 0.5) * range;
            v[o + VertexLayout.T] = (random.nextDouble() - 0.5) * range;
            double[] c = extra.at(v[o + VertexLayout.S], v[o + VertexLayout.T]);
            for (int j = 0; j < 3; j++) {
                v[o + VertexLayout.varying(PixelState.COLOUR_SLOT + j)] = c[j];
            }
        }
        return v;
    }

    /** The triangle projected to the screen ({@link VertexLayout#projectedStride()} doubles a corner). */
    static double[] project(double[] clip) {
        int cs = LAYOUT.clipStride();
        int ps = LAYOUT.projectedStride();
        double[] v = new double[3 * ps];
        for (int k = 0; k < 3; k++) {
            System.arraycopy(clip, k * cs, v, k * ps, cs);
            double w = clip[k * cs + VertexLayout.W];
            v[k * ps + LAYOUT.screenX()] = (clip[k * cs + VertexLayout.X] / w + 1) * 0.5 * WIDTH;
            v[k * ps + LAYOUT.screenX() + 1] = (1 - clip[k * cs + VertexLayout.Y] / w) * 0.5 * HEIGHT;
        }
        return v;
    }

    /** A random texture of {@code w x h} texels with random alpha. */
    static Texture texture(Random random, int w, int h) {
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = random.nextInt();
        }
        return new Texture("random", w, h, argb);
    }

    /** A frame with the UV output, filled with a random background colour, depth and UV values. */
    static Framebuffer frame(Random random) {
        Framebuffer f = new Framebuffer(WIDTH, HEIGHT);
        f.recordUv(true);
        for (int i = 0; i < WIDTH * HEIGHT; i++) {
            f.colour()[i] = 0xFF000000 | random.nextInt(0x1000000);
            f.depth()[i] = random.nextInt(3) == 0 ? 0.2f + 2 * random.nextFloat() : 0;
            f.uv()[3 * i] = random.nextDouble();
            f.uv()[3 * i + 1] = random.nextDouble();
            f.uv()[3 * i + 2] = 99;
        }
        return f;
    }

    /** A copy of {@code f} (colour, depth and UV output). */
    static Framebuffer copy(Framebuffer f) {
        Framebuffer c = new Framebuffer(f.width(), f.height());
        c.recordUv(true);
        System.arraycopy(f.colour(), 0, c.colour(), 0, f.colour().length);
        System.arraycopy(f.depth(), 0, c.depth(), 0, f.depth().length);
        System.arraycopy(f.uv(), 0, c.uv(), 0, f.uv().length);
        return c;
    }

    /**
     * Draws the clip-space triangle by {@code path} into {@code frame}, its one material with texture
     * {@code texture} and pixel state {@code state}.
     *
     * @return pixels written
     */
    static long draw(Path path, double[] clip, Texture texture, int state, Framebuffer frame, Random random) {
        return draw(path, TextureFilter.NEAREST, clip, texture, state, frame, random);
    }

    /** As {@link #draw(Path, double[], Texture, int, Framebuffer, Random)}, sampling with {@code filter}. */
    static long draw(Path path, TextureFilter filter, double[] clip, Texture texture, int state, Framebuffer frame,
                     Random random) {
        Rasterizer r = new Rasterizer();
        r.filter(filter);
        r.states(new int[] {state});
        Texture[] textures = {texture};
        if (path != Path.TREE) {
            ScreenTriangles t = new ScreenTriangles();
            t.layout(LAYOUT);
            double[] v = project(clip);
            int ps = LAYOUT.projectedStride();
            t.add(v, 0, ps, 2 * ps, 0, 0, false, 0, ScreenTriangles.OUTER, ScreenTriangles.OUTER,
                    ScreenTriangles.OUTER);
            r.spans(path == Path.KNOTS ? KNOT_ERROR : 0);
            return r.fill(frame, t, new int[] {0}, 0, 1, textures, path != Path.FIXED, 0, 0, WIDTH, HEIGHT);
        }
        Tessellator tess = new Tessellator();
        tess.layout(LAYOUT);
        tess.configure(new Viewport(WIDTH, HEIGHT), TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR)
                .withMaxError(0.1 + random.nextDouble()));
        int cs = LAYOUT.clipStride();
        ScreenTriangles pieces = new ScreenTriangles();
        pieces.layout(LAYOUT);
        tess.process(clip, 0, cs, 2 * cs, true,
                (v, a, b, c, level, fallback, links) -> pieces.add(v, a, b, c, 0, 0, fallback, level,
                        ScreenTriangles.OUTER, ScreenTriangles.OUTER, ScreenTriangles.OUTER));
        if (!tess.splitTree().complete() || tess.splitTree().leaves() == 0) {
            return 0;
        }
        if (tess.splitTree().nodes() == 0) {
            // Not split: its one piece is the input triangle, drawn as a triangle of the affine path.
            return r.fill(frame, pieces, new int[] {0}, 0, 1, textures, false, 0, 0, WIDTH, HEIGHT);
        }
        SplitTrees trees = new SplitTrees();
        trees.layout(LAYOUT);
        int ps = LAYOUT.projectedStride();
        // With the chain's levels, so that trilinear takes each piece's own level of detail.
        int maxLevel = filter == TextureFilter.TRILINEAR ? texture.mipChain().maxLevel() : 0;
        trees.add(tess.vertices(), 0, ps, 2 * ps, 0, 0, tess.splitTree(), pieces, 0, maxLevel);
        return r.fillTree(frame, trees, 0, textures, 0, 0, WIDTH, HEIGHT);
    }
}
