package dev.trisect.tessellate;

/**
 * The one description of a vertex in the geometry and pixel stages: doubles per vertex in a primitive
 * array, clip-space position first, then the <em>varyings</em> (values interpolated across a
 * triangle: slots 0 and 1 the texel coordinates s, t; any further slot is free, such as a lit colour's
 * r, g, b), then, once projected, the screen position. Clip space and screen space are linear in
 * each other per slot, so the clipper and the tessellator interpolate every slot alike without
 * knowing what it holds; the raster stage carries the same slots on as planes ({@code
 * raster.ScreenTriangles}, {@code raster.TriangleSetup}, {@code raster.SplitTrees}).
 *
 * <pre>
 * clip vertex:       x y z w | v0 .. v(n-1)            {@link #clipStride()}      = 4 + n
 * projected vertex:  x y z w | v0 .. v(n-1) | sx sy    {@link #projectedStride()} = 6 + n
 * </pre>
 *
 * <p>A layout may also carry <em>flat</em> values ({@link #flats()}): values constant over a triangle,
 * as GLSL's {@code flat} qualifier and OpenGL's flat shading take the provoking vertex's, held once
 * per triangle beside it instead of in every vertex. A flat-lit frame's one flat value is the
 * triangle's lit colour packed into one number ({@code raster.PixelState.flatColour}: each channel rounded to
 * 65536ths, clamped to 0..65536, in 17 bits; exact in a double), which the setup unpacks by shifts.
 * They are in no vertex, so the clipper and the tessellator never see them: a clipped or split
 * triangle's pieces keep their triangle's.
 *
 * <p>{@link #TEXTURED} is the layout of a textured frame (the varyings s, t alone); its offsets are
 * also the static constants below, {@link #CLIP_STRIDE}, {@link #SCREEN_X}, {@link #SCREEN_Y},
 * {@link #PROJECTED_STRIDE}, for code that knows it works in that layout.
 */
public final class VertexLayout {
    /** Clip-space x, y, z, w (OpenGL's clip coordinates; w is the view depth, &gt; 0 once clipped). */
    public static final int X = 0;
    public static final int Y = 1;
    public static final int Z = 2;
    public static final int W = 3;
    /** Offset of varying slot 0: the varyings follow the clip-space position. */
    public static final int FIRST_VARYING = 4;
    /** Texel coordinates s = u * width, t = v * height of the material's texture, level-0 texels: varyings 0 and 1. */
    public static final int S = FIRST_VARYING;
    public static final int T = FIRST_VARYING + 1;
    /** The varying slot of s; t is the next one. */
    public static final int SLOT_S = 0;
    /** The most varyings a layout may have. */
    public static final int MAX_VARYINGS = 16;
    /** The layout of a textured frame: the varyings s and t alone. */
    public static final VertexLayout TEXTURED = new VertexLayout(2, 0);
    /** One instance per size, so that layouts compare by identity. */
    private static final VertexLayout[] LAYOUTS = new VertexLayout[MAX_VARYINGS + 1];
    /** {@link #TEXTURED}'s doubles per clip vertex: x, y, z, w, s, t. */
    public static final int CLIP_STRIDE = 6;
    /** The clip stride of {@code of(5)}: s, t and a colour r, g, b, the layout of a lit frame. */
    private static final int LIT_CLIP_STRIDE = CLIP_STRIDE + 3;
    /** {@link #TEXTURED}'s screen position in pixels, x right and y down (see {@link dev.trisect.math.Viewport}). */
    public static final int SCREEN_X = 6;
    public static final int SCREEN_Y = 7;
    /** {@link #TEXTURED}'s doubles per projected vertex: x, y, z, w, s, t, screen x, screen y. */
    public static final int PROJECTED_STRIDE = 8;

    /** The most flat values a layout may have. */
    public static final int MAX_FLATS = 4;
    /** Layouts with flat values, by varyings and flat values: one instance each, as {@link #LAYOUTS}. */
    private static final VertexLayout[][] FLAT_LAYOUTS = new VertexLayout[MAX_VARYINGS + 1][MAX_FLATS + 1];

    private final int varyings;
    private final int flats;

    static {
        LAYOUTS[2] = TEXTURED;
        for (int n = 2; n <= MAX_VARYINGS; n++) {
            if (n > 2) {
                LAYOUTS[n] = new VertexLayout(n, 0);
            }
            FLAT_LAYOUTS[n][0] = LAYOUTS[n];
            for (int f = 1; f <= MAX_FLATS; f++) {
                FLAT_LAYOUTS[n][f] = new VertexLayout(n, f);
            }
        }
    }

    private VertexLayout(int varyings, int flats) {
        this.varyings = varyings;
        this.flats = flats;
    }

    /**
     * The layout with {@code varyings} slots, s and t first.
     *
     * @throws IllegalArgumentException unless 2 &lt;= varyings &lt;= {@link #MAX_VARYINGS}
     */
    public static VertexLayout of(int varyings) {
        if (varyings < 2 || varyings > MAX_VARYINGS) {
            throw new IllegalArgumentException("a vertex layout has 2 to " + MAX_VARYINGS
                    + " varyings (s and t first), got " + varyings);
        }
        return LAYOUTS[varyings];
    }

    /**
     * The layout with {@code varyings} slots, s and t first, and {@code flats} flat values per triangle.
     *
     * @throws IllegalArgumentException unless 2 &lt;= varyings &lt;= {@link #MAX_VARYINGS} and
     *                                  0 &lt;= flats &lt;= {@link #MAX_FLATS}
     */
    public static VertexLayout of(int varyings, int flats) {
        if (flats < 0 || flats > MAX_FLATS) {
            throw new IllegalArgumentException("a vertex layout has 0 to " + MAX_FLATS + " flat values, got " + flats);
        }
        of(varyings); // checks the varyings
        return FLAT_LAYOUTS[varyings][flats];
    }

    /** Values constant over a triangle, held once per triangle (not in its vertices); 0 for most layouts. */
    public int flats() {
        return flats;
    }

    /** Values interpolated across a triangle per vertex, s and t included. */
    public int varyings() {
        return varyings;
    }

    /** Offset of varying {@code slot} in a vertex. */
    public static int varying(int slot) {
        return FIRST_VARYING + slot;
    }

    /** Doubles per clip vertex: x, y, z, w and the varyings. */
    public int clipStride() {
        return FIRST_VARYING + varyings;
    }

    /** Offset of the screen x of a projected vertex, pixels; screen y follows. */
    public int screenX() {
        return FIRST_VARYING + varyings;
    }

    /** Offset of the screen y of a projected vertex, pixels. */
    public int screenY() {
        return FIRST_VARYING + varyings + 1;
    }

    /** Doubles per projected vertex: a clip vertex followed by its screen x and y. */
    public int projectedStride() {
        return FIRST_VARYING + varyings + 2;
    }

    /**
     * Copies {@code count} doubles (a clip vertex, or part of one) from {@code src[from..]} to
     * {@code dst[to..]}. The textured layout's six doubles go by {@link System#arraycopy} of a constant
     * length, which the compiler turns into a few moves; a length it does not know costs a call or a
     * loop per vertex, 5-9 % of a frame of 160,000 small triangles
     * (docs/performance/pixel-stage.md, "The pixel stage as templates, and attributes by layout").
     */
    public static void copy(double[] src, int from, double[] dst, int to, int count) {
        if (count == CLIP_STRIDE) {
            System.arraycopy(src, from, dst, to, CLIP_STRIDE);
            return;
        }
        if (count == LIT_CLIP_STRIDE) {
            // The lit layout (s, t and a colour), in every clipped vertex of a lit frame: a copy of a
            // constant length compiles to moves, a loop of a variable one does not.
            System.arraycopy(src, from, dst, to, LIT_CLIP_STRIDE);
            return;
        }
        for (int k = 0; k < count; k++) {
            dst[to + k] = src[from + k];
        }
    }

    @Override
    public String toString() {
        return "VertexLayout[" + varyings + " varyings" + (flats > 0 ? ", " + flats + " flat]" : "]");
    }
}
