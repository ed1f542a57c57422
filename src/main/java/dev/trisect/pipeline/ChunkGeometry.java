package dev.trisect.pipeline;

import dev.trisect.render.CullMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import static dev.trisect.tessellate.VertexLayout.S;
import static dev.trisect.tessellate.VertexLayout.T;
import static dev.trisect.tessellate.VertexLayout.W;
import static dev.trisect.tessellate.VertexLayout.X;
import static dev.trisect.tessellate.VertexLayout.Y;
import static dev.trisect.tessellate.VertexLayout.Z;

import dev.trisect.light.Surface;
import dev.trisect.math.Viewport;
import dev.trisect.raster.Commands;
import dev.trisect.raster.PixelState;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.mesh.Mesh;
import dev.trisect.tessellate.PieceBudget;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;

/**
 * The geometry of one chunk of input triangles: cull, clip and fan them in clip space, then split
 * them (tessellated path) or pass them whole through the {@link Tessellator}, whose pieces a
 * {@link ScreenPieceSink} appends to the chunk's screen triangles in input order.
 *
 * <p>A triangle with a flagged corner or a non-finite UV is skipped and counted, and so is one whose
 * clipped corners double precision cannot place ({@link Clipper#representable}), or whose facing
 * it cannot decide (larger than {@link #LARGE} and the determinant within its rounding error of zero). One wholly outside
 * a plane of the view volume is culled. Facing comes from the sign of the homogeneous determinant of
 * the corners' (x, y, w), right even for triangles that cross the eye plane; zero is degenerate.
 * Triangles that cross the near or far plane, or the guard band {@link #GUARD_PIXELS} beyond the
 * screen's sides, are clipped ({@link Clipper}) and fanned. Vertices are in the frame's {@link
 * VertexLayout} ({@link Input#layout()}): {@link #loadCorner} writes each corner's varyings, and every
 * later stage carries them on slot by slot. Each thread has its own scratch; any thread may take any chunk.
 */
final class ChunkGeometry {
    /** Guard band beyond each side of the viewport, pixels. */
    static final int GUARD_PIXELS = 8192;
    /**
     * Clip coordinates above which a triangle whose determinant is zero within its rounding error is
     * skipped as unrepresentable rather than called degenerate or given a facing: 2<sup>26</sup>.
     */
    static final double LARGE = 0x1p26;
    /** Doubles between the corners of the triangle being culled: room for the largest layout's clip vertex. */
    private static final int CORNER = VertexLayout.FIRST_VARYING + VertexLayout.MAX_VARYINGS;
    /** The flat colour of an unlit material in a flat-lit frame: white, the texel unchanged. */
    private static final double WHITE = PixelState.flatColour(1, 1, 1);
    /** Triangles per timing batch inside a chunk. */
    private static final int BATCH = 1024;

    /**
     * What every chunk of one attempt at a frame's geometry works from.
     *
     * @param draws           the meshes, their textures, and the frame's numbering of their triangles
     * @param clip            clip-space positions of every draw, 4 doubles each (see {@link ClipSpace})
     * @param invalidPosition per position: not finite in clip space
     * @param guardX          the guard band as a multiple of the view volume's half-width
     * @param guardY          likewise of its half-height
     * @param split           tessellate (else pass triangles whole)
     * @param budget          the frame's piece budget, shared by all threads' tessellators
     * @param layout          the vertices' varyings (s, t first), carried on to the pixel loops
     * @param colours         the lit vertices' colours when a material is lit, else null; a layout with
     *                        more than two varyings carries r, g, b in varyings 2..4 (white where unlit),
     *                        one with flat values the provoking corner's colour in flat value
     *                        {@link PixelState#FLAT_COLOUR} ({@link PixelState#flatColour})
     */
    record Input(Draws draws, double[] clip, boolean[] invalidPosition, RenderSettings settings,
                 Viewport viewport, double guardX, double guardY, boolean split, PieceBudget budget,
                 VertexLayout layout, VertexColours colours) {
    }

    /** Per-thread scratch. */
    private static final class Scratch {
        final Clipper clipper = new Clipper();
        final Tessellator tessellator = new Tessellator();
        final ScreenPieceSink sink = new ScreenPieceSink();
        /** The three corners of the triangle being culled and clipped, {@link #CORNER} doubles apart. */
        final double[] corners = new double[3 * CORNER];
        /** Doubles per clipped vertex in {@link #batch}: the layout's clip stride. */
        int clipStride = VertexLayout.CLIP_STRIDE;
        /** Clipped triangles of the current batch: 3 vertices of the layout's clip stride each. */
        double[] batch = new double[3 * VertexLayout.CLIP_STRIDE * BATCH];
        int[] batchIds = new int[BATCH];
        int[] batchMaterials = new int[BATCH];
        /** Flat values per triangle of the layout ({@link VertexLayout#flats()}). */
        int flatStride;
        /** The flat values of the batch's triangles, {@link #flatStride} each. */
        double[] batchFlats = new double[VertexLayout.MAX_FLATS * BATCH];
        /** The flat values of the triangle being culled and clipped. */
        final double[] flat = new double[VertexLayout.MAX_FLATS];
    }

    private final Scratch[] scratch;

    /** @param threads threads that may call {@link #run}, numbered as {@link WorkerPool} numbers them */
    ChunkGeometry(int threads) {
        scratch = new Scratch[threads];
        for (int i = 0; i < threads; i++) {
            scratch[i] = new Scratch();
        }
    }

    /**
     * Replaces {@code chunk}'s screen triangles and counters with those of input triangles
     * [from, to), on thread {@code thread}. Stops early once the frame's piece budget is exceeded
     * (the attempt is then thrown away).
     */
    void run(int thread, Chunk chunk, Input in, int from, int to) {
        Scratch w = scratch[thread];
        VertexLayout layout = in.layout();
        chunk.clear(layout);
        Tessellator tess = w.tessellator;
        tess.layout(layout);
        w.clipper.layout(layout);
        int clipStride = layout.clipStride();
        w.clipStride = clipStride;
        int flatStride = layout.flats();
        w.flatStride = flatStride;
        PieceBudget budget = in.budget();
        tess.configure(in.viewport(), in.settings().tessellation());
        tess.budget(budget);
        // Only the border overlay reads the pieces' links so far: spare their bookkeeping without it.
        tess.links(in.settings().borders());
        tess.resetStatistics();
        w.clipper.guardBand(in.guardX(), in.guardY());
        w.sink.target(chunk.out);
        boolean cullBack = in.settings().cull() == CullMode.BACK;
        boolean split = in.split();
        boolean trilinear = in.settings().filter() == TextureFilter.TRILINEAR;
        for (int batchStart = from; batchStart < to && !budget.exceeded(); batchStart += BATCH) {
            int batchEnd = Math.min(to, batchStart + BATCH);
            long t0 = System.nanoTime();
            // The batch's triangles draw by draw: each draw's own arrays, its triangles and materials
            // renumbered into the frame's.
            Draws draws = in.draws();
            int n = 0;
            for (int d = draws.drawOf(batchStart); d < draws.size() && draws.firstTriangle(d) < batchEnd; d++) {
                int first = draws.firstTriangle(d);
                int lo = Math.max(batchStart, first);
                int hi = Math.min(batchEnd, draws.firstTriangle(d + 1));
                if (lo < hi) {
                    n = cullAndClip(w, chunk, in, d, lo - first, hi - first, cullBack, n);
                }
            }
            long t1 = System.nanoTime();
            double[] b = w.batch;
            int stride = 3 * clipStride;
            for (int i = 0; i < n; i++) {
                w.sink.triangle(w.batchIds[i], w.batchMaterials[i], w.batchFlats, i * flatStride);
                int o = i * stride;
                int firstPiece = chunk.out.count();
                tess.process(b, o, o + clipStride, o + 2 * clipStride, split, w.sink);
                if (split && tess.splitTree().complete() && tess.splitTree().leaves() > 0) {
                    if (tess.splitTree().nodes() == 0) {
                        // Not split: its one piece is the input triangle, filled as the other paths fill one.
                        chunk.commands.add(Commands.TRIANGLE, firstPiece, chunk.out.firstRow(firstPiece),
                                chunk.out.endRow(firstPiece));
                    } else {
                        int material = w.batchMaterials[i];
                        int maxLevel = trilinear ? draws.textures()[material].mipChain().maxLevel() : 0;
                        int ps = layout.projectedStride();
                        int g = chunk.trees.add(tess.vertices(), 0, ps, 2 * ps, w.batchIds[i], material,
                                w.batchFlats, i * flatStride, tess.splitTree(), chunk.out, firstPiece, maxLevel);
                        ScreenTriangles inputs = chunk.trees.inputs();
                        chunk.commands.add(Commands.TREE, g, inputs.firstRow(g), inputs.endRow(g));
                    }
                }
            }
            long t2 = System.nanoTime();
            chunk.clipNanos += t1 - t0;
            chunk.tessellateNanos += t2 - t1;
        }
        if (!split) {
            // An unsplit frame's commands are its screen triangles in order: added in a loop of their
            // own, as in the per-triangle loop above C2 kept this one's values on the stack.
            long t0 = System.nanoTime();
            ScreenTriangles out = chunk.out;
            for (int p = 0, n = out.count(); p < n; p++) {
                chunk.commands.add(Commands.TRIANGLE, p, out.firstRow(p), out.endRow(p));
            }
            chunk.tessellateNanos += System.nanoTime() - t0;
        }
        chunk.pieces = tess.pieces();
        chunk.offScreen = tess.culledOffScreen();
        chunk.splits = tess.splits();
        chunk.deepest = tess.deepestLevel();
        chunk.caps = tess.capsReached();
        chunk.fallback = tess.fallbackPieces();
    }

    /**
     * Culls and clips triangles [from, to) of draw {@code d} into the thread's batch, after the
     * {@code count} already there, as triangles in clip space with texel coordinates, their frame
     * triangle ids and frame materials, counting what it drops in {@code chunk}; returns the new count.
     */
    private static int cullAndClip(Scratch w, Chunk chunk, Input in, int d, int from, int to, boolean cullBack,
                                   int count) {
        Draws draws = in.draws();
        Mesh mesh = draws.mesh(d);
        Texture[] textures = draws.textures();
        int idBase = draws.firstTriangle(d);
        int positionBase = draws.firstPosition(d);
        int materialBase = draws.firstMaterial(d);
        double[] clip = in.clip();
        boolean[] invalidPosition = in.invalidPosition();
        int[] corners = mesh.cornerPositions();
        int[] cornerUvs = mesh.cornerUvs();
        int[] materials = mesh.triangleMaterials();
        float[] uvs = mesh.uvs();
        Clipper clipper = w.clipper;
        double[] corner = w.corners;
        VertexColours colours = in.colours();
        boolean carriesColour = in.layout().varyings() > PixelState.COLOUR_SLOT;
        boolean flatColour = in.layout().flats() > PixelState.FLAT_COLOUR;
        Surface[] surfaces = draws.surfaces();
        // A flat-lit frame's colours: per vertex, packed once when lit (VertexColours), and the
        // provoking vertex of each triangle.
        double[] flatColours = flatColour && colours != null ? colours.flatColours() : null;
        int[] provoking = flatColours != null ? colours.provoking(d) : null;
        int vertexBase = flatColours != null ? colours.base(d) : 0;
        int c1 = CORNER;
        int c2 = 2 * CORNER;
        for (int t = from; t < to; t++) {
            int c = 3 * t;
            int p0 = positionBase + corners[c];
            int p1 = positionBase + corners[c + 1];
            int p2 = positionBase + corners[c + 2];
            int material = materialBase + materials[t];
            int id = idBase + t;
            Texture tex = textures[material];
            if (invalidPosition[p0] || invalidPosition[p1] || invalidPosition[p2]
                    || !loadCorner(corner, 0, clip, p0, uvs, cornerUvs[c], tex)
                    || !loadCorner(corner, c1, clip, p1, uvs, cornerUvs[c + 1], tex)
                    || !loadCorner(corner, c2, clip, p2, uvs, cornerUvs[c + 2], tex)) {
                chunk.invalid++;
                continue;
            }
            int f0 = Clipper.frustumCode(corner[X], corner[Y], corner[Z], corner[W]);
            int f1 = Clipper.frustumCode(corner[c1 + X], corner[c1 + Y], corner[c1 + Z], corner[c1 + W]);
            int f2 = Clipper.frustumCode(corner[c2 + X], corner[c2 + Y], corner[c2 + Z], corner[c2 + W]);
            if ((f0 & f1 & f2) != 0) {
                chunk.culledFrustum++;
                continue;
            }
            // Facing from the homogeneous determinant of (x, y, w): its sign is the projected
            // winding for w > 0 and stays right for triangles crossing the eye plane.
            double det = determinant(corner);
            // Far larger than the view (beyond LARGE clip units) and zero within rounding: rounding may
            // have hidden its facing (a quad 1e20 wide passing 3 units from the eye), so it is skipped
            // and counted, unless it has no area where it was made. Smaller triangles keep the plain rule.
            // Inside the view volume every coordinate is within [-w, w]: the largest w bounds them all,
            // which spares the full search for almost every triangle.
            double size = (f0 | f1 | f2) == 0 ? Math.max(corner[W], Math.max(corner[c1 + W], corner[c2 + W]))
                    : largest(corner);
            if (size > LARGE && Math.abs(det) <= determinantError(corner)
                    && !zeroArea(mesh.positions(), corners[c], corners[c + 1], corners[c + 2])) {
                chunk.invalid++;
                continue;
            }
            if (det == 0) {
                chunk.culledDegenerate++;
                continue;
            }
            if (cullBack && det < 0) {
                chunk.culledBack++;
                continue;
            }
            // Colours only for what survived culling: about half of a closed mesh faces away.
            if (carriesColour) {
                loadColours(corner, colours, d, c, surfaces[material]);
            } else if (flatColour) {
                // OpenGL's provoking vertex, the last corner's (Shading.FLAT), or white for an unlit material.
                w.flat[PixelState.FLAT_COLOUR] = flatColours != null && surfaces[material].lit()
                        ? flatColours[vertexBase + provoking[t]] : WHITE;
            }
            int g = clipper.clipCode(corner[X], corner[Y], corner[Z], corner[W])
                    | clipper.clipCode(corner[c1 + X], corner[c1 + Y], corner[c1 + Z], corner[c1 + W])
                    | clipper.clipCode(corner[c2 + X], corner[c2 + Y], corner[c2 + Z], corner[c2 + W]);
            if (g == 0) {
                count = append(w, count, corner, 0, c1, c2, id, material);
                continue;
            }
            chunk.clipped++;
            int n = clipper.clip(corner, 0, c1, c2, g);
            if (n == 0) {
                chunk.culledFrustum++;
                continue;
            }
            if (!clipper.representable(n, largest(corner))) {
                chunk.invalid++;
                continue;
            }
            double[] poly = clipper.vertices();
            for (int k = 1; k + 1 < n; k++) {
                count = append(w, count, poly, 0, k * w.clipStride, (k + 1) * w.clipStride, id, material);
            }
        }
        return count;
    }

    /**
     * Loads corner {@code o} from clip-space position {@code p} and its UV (varyings s, t); false if a
     * texel coordinate is not finite. A layout's further varyings are written here beside them, by
     * whatever produces them per corner.
     */
    private static boolean loadCorner(double[] dst, int o, double[] clip, int p, float[] uvs, int uvIndex,
                                      Texture tex) {
        System.arraycopy(clip, 4 * p, dst, o + X, 4);
        double u = 0;
        double v = 0;
        if (uvIndex >= 0) {
            u = uvs[2 * uvIndex];
            v = uvs[2 * uvIndex + 1];
        }
        dst[o + S] = u * tex.width();
        dst[o + T] = v * tex.height();
        return Double.isFinite(dst[o + S]) && Double.isFinite(dst[o + T]);
    }

    /**
     * Writes the lit colour r, g, b of mesh corners {@code c .. c+2} of draw {@code d} into varyings 2..4
     * of the three loaded corners: each corner's own with {@link Shading#SMOOTH}, the triangle's last
     * corner's in all three with {@link Shading#FLAT} (OpenGL's provoking vertex, so the loops need no
     * flat case), and white for an unlit material ({@code colours} is null in a frame without a lit
     * one), whose texel then shows unchanged.
     */
    private static void loadColours(double[] dst, VertexColours colours, int d, int c, Surface surface) {
        VertexColours lit = surface.lit() ? colours : null;
        boolean flat = surface.shading() == Shading.FLAT;
        for (int k = 0; k < 3; k++) {
            putColour(dst, k * CORNER + VertexLayout.varying(PixelState.COLOUR_SLOT), lit, d, c + k, flat);
        }
    }

    /**
     * Writes at {@code dst[o..o+2]} the colour of draw {@code d}'s corner {@code c} (its triangle's last
     * corner's with {@code flat}), or white when {@code colours} is null.
     */
    private static void putColour(double[] dst, int o, VertexColours colours, int d, int c, boolean flat) {
        if (colours != null) {
            float[] rgb = colours.colours();
            int i = colours.index(d, c, flat);
            dst[o] = rgb[i];
            dst[o + 1] = rgb[i + 1];
            dst[o + 2] = rgb[i + 2];
        } else {
            dst[o] = 1;
            dst[o + 1] = 1;
            dst[o + 2] = 1;
        }
    }

    /** The determinant of the three corners' clip-space (x, y, w). */
    private static double determinant(double[] c) {
        int c1 = CORNER;
        int c2 = 2 * CORNER;
        double x0 = c[X];
        double y0 = c[Y];
        double w0 = c[W];
        double x1 = c[c1 + X];
        double y1 = c[c1 + Y];
        double w1 = c[c1 + W];
        double x2 = c[c2 + X];
        double y2 = c[c2 + Y];
        double w2 = c[c2 + W];
        return x0 * (y1 * w2 - y2 * w1) - y0 * (x1 * w2 - x2 * w1) + w0 * (x1 * y2 - x2 * y1);
    }

    /**
     * A bound on the rounding error of {@link #determinant}: each of its 11 operations rounds by at
     * most 2<sup>-53</sup> of its magnitude, so the error is at most about 6 * 2<sup>-53</sup> times
     * the sum of the magnitudes of its six products (Higham, section 3.1); 8 units are taken.
     */
    private static double determinantError(double[] c) {
        int c1 = CORNER;
        int c2 = 2 * CORNER;
        double sum = Math.abs(c[X]) * (Math.abs(c[c1 + Y] * c[c2 + W]) + Math.abs(c[c2 + Y] * c[c1 + W]))
                + Math.abs(c[Y]) * (Math.abs(c[c1 + X] * c[c2 + W]) + Math.abs(c[c2 + X] * c[c1 + W]))
                + Math.abs(c[W]) * (Math.abs(c[c1 + X] * c[c2 + Y]) + Math.abs(c[c2 + X] * c[c1 + Y]));
        return 8 * 0x1p-53 * sum;
    }

    /**
     * Whether the object-space triangle of positions {@code a, b, c} has no area: its edge vectors'
     * cross product, computed in doubles from the float positions, is exactly zero.
     */
    private static boolean zeroArea(float[] p, int a, int b, int c) {
        double ux = (double) p[3 * b] - p[3 * a];
        double uy = (double) p[3 * b + 1] - p[3 * a + 1];
        double uz = (double) p[3 * b + 2] - p[3 * a + 2];
        double vx = (double) p[3 * c] - p[3 * a];
        double vy = (double) p[3 * c + 1] - p[3 * a + 1];
        double vz = (double) p[3 * c + 2] - p[3 * a + 2];
        return uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0;
    }

    /** The largest magnitude among the three corners' clip coordinates x, y, z, w. */
    private static double largest(double[] c) {
        double m = 0;
        for (int k = 0; k < 3; k++) {
            int o = k * CORNER;
            m = Math.max(m, Math.max(Math.max(Math.abs(c[o + X]), Math.abs(c[o + Y])),
                    Math.max(Math.abs(c[o + Z]), Math.abs(c[o + W]))));
        }
        return m;
    }

    private static int append(Scratch w, int count, double[] src, int a, int b, int c, int id, int material) {
        int cs = w.clipStride;
        int stride = 3 * cs;
        if ((count + 1) * stride > w.batch.length) {
            w.batch = Arrays.copyOf(w.batch, w.batch.length * 2);
            w.batchIds = Arrays.copyOf(w.batchIds, w.batchIds.length * 2);
            w.batchMaterials = Arrays.copyOf(w.batchMaterials, w.batchMaterials.length * 2);
            w.batchFlats = Arrays.copyOf(w.batchFlats, w.batchFlats.length * 2);
        }
        int o = count * stride;
        VertexLayout.copy(src, a, w.batch, o, cs);
        VertexLayout.copy(src, b, w.batch, o + cs, cs);
        VertexLayout.copy(src, c, w.batch, o + 2 * cs, cs);
        w.batchIds[count] = id;
        w.batchMaterials[count] = material;
        int fs = w.flatStride;
        if (fs == 1) {
            // A flat-lit frame's colour (FrameGeometry.FLAT_LIT_LAYOUT): one store, not a copy of a
            // length the compiler does not know.
            w.batchFlats[count] = w.flat[0];
        } else if (fs != 0) {
            System.arraycopy(w.flat, 0, w.batchFlats, count * fs, fs);
        }
        return count + 1;
    }
}
