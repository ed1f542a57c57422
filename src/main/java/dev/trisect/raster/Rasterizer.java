package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;

/**
 * Fills screen-space triangles into a {@link Framebuffer}, restricted to a rectangle of the frame:
 * for each triangle, {@link TriangleSetup} (bounds and attribute planes), {@link SpanSolver} (the
 * covered pixels of each row), then the pixel loop of the texture filter and path, chosen once per
 * triangle: the loops generated from templates, one per colour source ({@link ColourSources}: the
 * filter and the texture's kind) and UV setting ({@link PerPixelLoops}, {@link FixedLoops}, in the
 * span path {@link KnotLoops}, in the tessellated path {@link TreeLoops}); the span path's knots
 * are placed by {@link KnotSpacing}. A triangle of one colour sampled nearest is drawn by the texel
 * loop from a lit copy of its texture when the renderer's {@link LitTextures} has one: the same pixels.
 *
 * <p>Coverage is exact integer arithmetic on snapped corners: a pixel belongs to a triangle when its
 * centre is inside, and a centre exactly on an edge goes to the triangle for which that edge is a top
 * or a left edge (image coordinates, y down); see {@link SpanSolver}.
 *
 * <p>Because every decision is a function of the triangle and the pixel alone, filling the frame in
 * bands or tiles — on any number of threads — gives the same pixels as filling it whole, provided
 * each pixel sees its triangles in the same order.
 *
 * <p>One instance per thread: its setup and span solver hold the current triangle. Nothing is
 * allocated per triangle or per pixel.
 */
public final class Rasterizer {
    private final TriangleSetup setup = new TriangleSetup();
    private final SpanSolver solver = new SpanSolver();
    private final TreeFill trees = new TreeFill();
    /**
     * The {@link ColourSources} of the texture filter (nearest until {@link #filter} sets one) for a
     * texture whose sides are powers of two, and for any other: chosen per filter, not per triangle.
     */
    private int potSource = ColourSources.NEAREST_POT;
    private int anySource = ColourSources.NEAREST_ANY;
    /** The span path's largest displacement between knots, pixels; 0: perspective fills divide per pixel. */
    private double knotError;
    /** The {@link PixelState} of each material index, or null: state 0 for every material. */
    private int[] states;
    /** This thread's side of the renderer's lit textures, or null: none used. */
    private LitTextures.Lane lit;
    /** The lit copy {@link #oneColour} picked for the triangle being filled, or null: its material's texture. */
    private Texture chosenCopy;

    /** Sets how the following {@link #fill} calls sample textures (nearest until set). */
    public void filter(TextureFilter f) {
        if (f == null) {
            throw new IllegalArgumentException("texture filter must not be null");
        }
        potSource = switch (f) {
            case BILINEAR -> ColourSources.BILINEAR_POT;
            case TRILINEAR -> ColourSources.TRILINEAR_POT;
            default -> ColourSources.NEAREST_POT;
        };
        anySource = switch (f) {
            case BILINEAR -> ColourSources.BILINEAR_ANY;
            case TRILINEAR -> ColourSources.TRILINEAR_ANY;
            default -> ColourSources.NEAREST_ANY;
        };
    }

    /**
     * Sets the pixel state of each material for the following fills: {@code states[m]} is material
     * m's {@link PixelState}, indexed as the textures are.
     *
     * @param states read, never copied or changed; null (until set) for state 0 everywhere
     */
    public void states(int[] states) {
        this.states = states;
    }

    /**
     * The pixel state of {@code material} for a triangle of {@code triangles}, checked against their
     * layout once per triangle.
     *
     * @throws IllegalStateException when the state modulates and the layout carries no colour
     */
    private int state(ScreenTriangles triangles, int material) {
        int state = states == null ? 0 : states[material];
        if (!PixelState.carried(state, triangles.layout())) {
            throw new IllegalStateException("material " + material + " modulates by a colour (pixel state "
                    + state + ") but its triangles carry " + triangles.layout().varyings()
                    + " varyings and no flat colour: the frame needs VertexLayout.of(5) or VertexLayout.of(2, 1)");
        }
        return state;
    }

    /**
     * Sets where the following fills find lit copies of textures ({@link LitTextures}): a triangle of one
     * colour sampled nearest is drawn from its texture's copy modulated by that colour when there is one.
     *
     * @param lane this thread's lane of the renderer's cache, or null (until set) for none
     */
    public void lit(LitTextures.Lane lane) {
        this.lit = lane;
    }

    /**
     * Sets the path of the following perspective {@link #fill} calls: with {@code knotError > 0} the
     * span path, exact texel coordinates at knots along each row spaced so that no pixel between them
     * is displaced by more than {@code knotError} pixels ({@link KnotSpacing}), affine between them; with
     * 0 (until set) every pixel divides.
     */
    public void spans(double knotError) {
        if (!(knotError >= 0) || Double.isInfinite(knotError)) {
            throw new IllegalArgumentException("knot error must be 0 (off) or a positive number of pixels, got "
                    + knotError);
        }
        this.knotError = knotError;
    }

    /**
     * Fills triangles {@code order[from..to)} of {@code triangles}, in that order, into the pixels
     * {@code [x0, x1) x [y0, y1)} of the frame.
     *
     * @param perspective true: u/w, v/w and 1/w interpolate linearly on screen and every pixel
     *                    divides (or, after {@link #spans} with a positive error, every knot); false: u and v interpolate linearly on screen (affine), except for
     *                    triangles flagged {@link ScreenTriangles#perPixel()}, which divide
     * @param textures    texture of each material index
     * @return the number of pixels written (depth test passed)
     */
    public long fill(Framebuffer frame, ScreenTriangles triangles, int[] order, int from, int to,
                     Texture[] textures, boolean perspective, int x0, int y0, int x1, int y1) {
        long written = 0;
        for (int n = from; n < to; n++) {
            written += fillOne(frame, triangles, order[n], textures, perspective, x0, y0, x1, y1);
        }
        return written;
    }

    /** {@link #fill} of one triangle, {@code tri} of {@code triangles}: a {@link Commands#TRIANGLE} command. */
    long fillOne(Framebuffer frame, ScreenTriangles triangles, int tri, Texture[] textures,
                         boolean perspective, int x0, int y0, int x1, int y1) {
        TriangleSetup t = setup;
        boolean divide = perspective || triangles.perPixel()[tri];
        // The span path places its knots on each row's covered columns within the frame, whatever
        // the rectangle, so that a pixel never depends on the rectangle being filled.
        boolean knots = perspective && knotError > 0;
        if (!t.prepare(triangles, tri, divide, knots ? 0 : x0, y0, knots ? frame.width() : x1, y1)) {
            return 0;
        }
        if (knots && !t.fixedPointSafe) {
            // Texel coordinates beyond 32.32 fixed point: filled per pixel, over the rectangle.
            knots = false;
            if ((x0 != 0 || x1 != frame.width()) && !t.prepare(triangles, tri, true, x0, y0, x1, y1)) {
                return 0;
            }
        }
        solver.walk(t);
        int[] spans = solver.spans();
        int material = triangles.materials()[tri];
        Texture texture = textures[material];
        int source = source(texture);
        int state = state(triangles, material);
        // Only a modulating material's triangle of one colour has anything more to decide: an unlit
        // triangle pays two tests here, as before lit copies.
        if (PixelState.colour(state) == PixelState.MODULATE && t.constantColour) {
            state = oneColour(state, source, material, t, spans);
            if (chosenCopy != null) {
                texture = chosenCopy;
            }
        }
        int uvId = triangles.ids()[tri] + 1;
        boolean uv = frame.uv() != null;
        boolean ids = frame.ids() != null;
        if (knots) {
            return KnotLoops.fill(source, state, uv, ids, t, spans, frame, texture, uvId, knotError, x0, x1);
        } else if (!divide && t.fixedPointSafe) {
            return FixedLoops.fill(source, state, uv, ids, t, spans, frame, texture, uvId);
        } else {
            return PerPixelLoops.fill(source, state, uv, ids, divide, t, spans, frame, texture, uvId);
        }
    }

    /**
     * The pixel state for a triangle of one colour ({@link TriangleSetup#constantColour}: flat shading, a
     * face lit evenly, a colour carried through clipping and cuts) of a material whose {@code state}
     * modulates: {@link PixelState#CONSTANT}, the colour being in {@code t}, so that the loop multiplies
     * by the colour taken once instead of interpolating three varyings at every pixel; or, sampled
     * nearest when the cache has a lit copy of the texture ({@link LitTextures}), whose texel is the
     * texel times that colour bit for bit, the texel loop, that copy being put in {@link #chosenCopy}
     * (else null there).
     */
    private int oneColour(int state, int source, int material, TriangleSetup t, int[] spans) {
        int constant = state - PixelState.MODULATE + PixelState.CONSTANT;
        chosenCopy = null;
        if (lit == null || source != ColourSources.NEAREST_POT && source != ColourSources.NEAREST_ANY) {
            return constant;
        }
        Texture copy = lit.lit(material, t, spans);
        if (copy == null) {
            return constant;
        }
        chosenCopy = copy;
        return PixelState.write(constant);
    }

    /** The colour source of the filter sampling {@code texture}: masks wrap a power-of-two side. */
    private int source(Texture texture) {
        int tw = texture.width();
        int th = texture.height();
        return (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0 ? potSource : anySource;
    }

    /**
     * The tessellated path's one-pass fill of input triangle {@code g} of {@code trees} (a
     * {@link Commands#TREE} command) into the pixels {@code [x0, x1) x [y0, y1)} of the frame: its
     * coverage and depth from the input triangle, each pixel's texel coordinates from the piece of the
     * split tree it lies in ({@link TreeFill}).
     *
     * @param textures texture of each material index
     * @return the number of pixels written (depth test passed)
     */
    public long fillTree(Framebuffer frame, SplitTrees trees, int g, Texture[] textures, int x0, int y0, int x1,
                         int y1) {
        ScreenTriangles inputs = trees.inputs();
        TriangleSetup t = setup;
        if (!t.prepare(inputs, g, true, x0, y0, x1, y1)) {
            return 0;
        }
        solver.walk(t);
        int[] spans = solver.spans();
        int material = inputs.materials()[g];
        Texture texture = textures[material];
        int source = source(texture);
        int state = state(inputs, material);
        if (PixelState.colour(state) == PixelState.MODULATE && t.constantColour) {
            state = oneColour(state, source, material, t, spans);
            if (chosenCopy != null) {
                texture = chosenCopy;
            }
        }
        return TreeLoops.fill(source, state, frame.uv() != null, frame.ids() != null, this.trees, t,
                spans, trees, trees.roots()[g], trees.nodeCount(g), frame, texture, inputs.ids()[g] + 1);
    }

    /**
     * Adds 1 to {@code counts[y * width + x]} for every pixel of {@code [x0, x1) x [y0, y1)} that the
     * one-pass fill of input triangle {@code g} of {@code trees} gives a piece, ignoring depth: the
     * input triangle's coverage, less any pixel the split tree leaves without a piece (which would be
     * a crack).
     *
     * @return the number of coverings counted
     */
    public long countTree(int[] counts, int width, SplitTrees trees, int g, int x0, int y0, int x1, int y1) {
        TriangleSetup t = setup;
        if (!t.prepare(trees.inputs(), g, false, x0, y0, x1, y1)) {
            return 0;
        }
        solver.walk(t);
        return this.trees.count(t, solver.spans(), trees, trees.roots()[g], trees.nodeCount(g), counts, width);
    }

    /**
     * Adds 1 to {@code counts[y * width + x]} for every pixel of {@code [x0, x1) x [y0, y1)} whose
     * centre each of triangles {@code order[from..to)} covers, with exactly the coverage rule of
     * {@link #fill}, ignoring depth. For checking that pieces tile without gaps or overlaps, and for
     * showing overdraw.
     *
     * @return the number of coverings counted
     */
    public long countCoverage(int[] counts, int width, ScreenTriangles triangles, int[] order, int from, int to,
                              int x0, int y0, int x1, int y1) {
        long covered = 0;
        for (int n = from; n < to; n++) {
            covered += countOne(counts, width, triangles, order[n], x0, y0, x1, y1);
        }
        return covered;
    }

    /** {@link #countCoverage} of one triangle, {@code tri} of {@code triangles}. */
    long countOne(int[] counts, int width, ScreenTriangles triangles, int tri, int x0, int y0, int x1,
                          int y1) {
        TriangleSetup t = setup;
        if (!t.prepare(triangles, tri, false, x0, y0, x1, y1)) {
            return 0;
        }
        solver.walk(t);
        int[] sp = solver.spans();
        long covered = 0;
        for (int y = t.rowStart, j = 0; y < t.rowEnd; y++, j += 2) {
            int row = y * width;
            int end = sp[j + 1];
            for (int x = sp[j]; x < end; x++) {
                counts[row + x]++;
            }
            covered += end - sp[j];
        }
        return covered;
    }

    /** The last triangle set up, for tests. */
    TriangleSetup setup() {
        return setup;
    }

    /** The spans of the last triangle walked, for tests (see {@link SpanSolver#spans()}). */
    int[] spans() {
        return solver.spans();
    }
}
