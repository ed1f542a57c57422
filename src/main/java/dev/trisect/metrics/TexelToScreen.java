package dev.trisect.metrics;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.texture.Texture;
import java.util.Arrays;

/**
 * The exact map from a triangle's texel coordinates to the screen, for every triangle of a mesh in
 * one frame (camera and viewport): where the true perspective projection draws the point of the
 * triangle that carries given texel coordinates. It measures the <em>exact displacement</em> of a
 * pixel: map the texel coordinates the pixel shows back to the 3D point of its triangle that carries
 * them, project that point, and take the distance to the pixel centre (docs/math.md, "Measuring
 * displacement exactly").
 *
 * <p>Per triangle the map is one 3x3 homogeneous matrix H, precomputed in doubles: texel coordinates
 * to barycentric coordinates is affine (the inverse of the corners' texel coordinates), barycentric
 * to clip space is linear (the corners' clip positions), clip space to screen is projective (the
 * divide by w and the viewport). So {@code (x w, y w, w) = H (s - s0, t - t0, 1)}, with the triangle's
 * corner-0 texel coordinates {@code (s0, t0)} subtracted first so that large unwrapped coordinates
 * (a texture repeated many times) lose no precision to cancellation. Screen space is pixels, x right,
 * y down, pixel (i, j) centred at (i + 0.5, j + 0.5); texel coordinates are {@code (u W, v H)} of the
 * triangle's material's texture, as in the UV output.
 *
 * <p>Undefined (NaN) displacements: a triangle whose corners' texel coordinates span no area
 * ({@link #isDegenerate degenerate UV}, for example a mesh without texture coordinates) carries the
 * same texel coordinates at more than one point, so no single point is "the" one; a point at or
 * behind the eye plane ({@code w <= 0}) does not project; a triangle with non-finite coordinates is
 * never drawn. Callers count such pixels rather than guess.
 *
 * <p>Maps are built on first use of a triangle and kept, so the cost follows the triangles a frame
 * shows, not the mesh's size. Not thread-safe: one thread per instance. Build a new instance when the
 * camera, the viewport, the mesh or a texture's size changes.
 */
public final class TexelToScreen {
    /**
     * Relative size of the corners' texel-space area (the determinant of their texel-coordinate
     * differences), against the sum of the absolute products it is made of, at or below which a
     * triangle's UV mapping counts as degenerate: only (nearly) exact cancellation.
     */
    public static final double DEGENERATE_TOLERANCE = 1e-9;

    /** Doubles per map: s0, t0, then H row by row. */
    private static final int STRIDE = 11;
    private static final int UNBUILT = 0;
    private static final int DEGENERATE = -1;
    private static final int INVALID = -2;

    /** What the frame drew; triangles are numbered across its draws, as the UV output's ids. */
    private final Draws draws;
    /** Texture size of each frame material (the draws' materials, concatenated). */
    private final int[] textureWidths;
    private final int[] textureHeights;
    private final double halfWidth;
    private final double halfHeight;
    /** Per triangle: UNBUILT, DEGENERATE, INVALID, or 1 + the map's index in {@link #maps}. */
    private final int[] slot;
    private double[] maps = new double[STRIDE * 64];
    private int built;
    private final double[] clip = new double[12];
    private final double[] st = new double[6];

    /**
     * The maps of one frame.
     *
     * @param mesh           the mesh drawn (object space = world space, as the renderer draws it)
     * @param textures       the texture of each material of the mesh, by material index (only their
     *                       sizes are used, to scale UV to texel coordinates)
     * @param viewProjection world space to clip space, as given to the renderer
     * @param viewport       the frame's size
     * @throws IllegalArgumentException when there are fewer textures than materials
     */
    public TexelToScreen(Mesh mesh, Texture[] textures, Mat4 viewProjection, Viewport viewport) {
        this(one(mesh, textures, viewProjection), viewport);
    }

    private static Draws one(Mesh mesh, Texture[] textures, Mat4 viewProjection) {
        Draws d = new Draws();
        d.add(mesh, textures, viewProjection);
        return d;
    }

    /**
     * The maps of one frame of several draws, each mesh with its own model-view-projection; triangle
     * ids are the frame's (numbered across the draws, as in the UV output). Reads {@code draws} as it
     * is now: build a new instance after the draws are cleared or changed.
     *
     * @param draws    what the frame drew
     * @param viewport the frame's size
     */
    public TexelToScreen(Draws draws, Viewport viewport) {
        this.draws = draws;
        int materials = draws.firstMaterial(draws.size());
        this.textureWidths = new int[materials];
        this.textureHeights = new int[materials];
        Texture[] textures = draws.textures();
        for (int m = 0; m < materials; m++) {
            textureWidths[m] = textures[m].width();
            textureHeights[m] = textures[m].height();
        }
        this.halfWidth = 0.5 * viewport.width();
        this.halfHeight = 0.5 * viewport.height();
        this.slot = new int[draws.triangleCount()];
    }

    /** Number of triangles of the mesh (valid triangle indices are 0 to this minus 1). */
    public int triangleCount() {
        return slot.length;
    }

    /**
     * Whether the triangle's corners' texel coordinates span no area (or are not finite), so that
     * texel coordinates do not identify one point of it.
     *
     * @param triangle triangle index, 0-based (the UV output's id minus 1); out of range gives false
     */
    public boolean isDegenerate(int triangle) {
        return triangle >= 0 && triangle < slot.length && mapOf(triangle) < 0;
    }

    /**
     * The exact displacement, in pixels, of pixel (x, y) showing texel coordinates (s, t) of
     * {@code triangle}: the distance from the pixel centre (x + 0.5, y + 0.5) to where the triangle's
     * point with those texel coordinates projects.
     *
     * @param triangle triangle index, 0-based; out of range gives NaN
     * @return pixels; NaN when the triangle is degenerate, the point does not project, or the
     *         triangle index is out of range
     */
    public double displacement(int triangle, double s, double t, int x, int y) {
        if (triangle < 0 || triangle >= slot.length) {
            return Double.NaN;
        }
        int o = mapOf(triangle);
        if (o < 0) {
            return Double.NaN;
        }
        double[] h = maps;
        double ds = s - h[o];
        double dt = t - h[o + 1];
        double xw = h[o + 2] * ds + h[o + 3] * dt + h[o + 4];
        double yw = h[o + 5] * ds + h[o + 6] * dt + h[o + 7];
        double w = h[o + 8] * ds + h[o + 9] * dt + h[o + 10];
        // Written so that NaN fails too.
        if (!(w > 0)) {
            return Double.NaN;
        }
        double dx = xw / w - (x + 0.5);
        double dy = yw / w - (y + 0.5);
        return Math.sqrt(dx * dx + dy * dy);
    }

    /**
     * Where the point of {@code triangle} carrying texel coordinates (s, t) projects, for inspecting
     * one pixel; allocates, so not for loops over pixels.
     *
     * @param triangle triangle index, 0-based
     * @return screen (x, y) in pixels, or null when undefined (see {@link #displacement})
     */
    public double[] screenOf(int triangle, double s, double t) {
        if (triangle < 0 || triangle >= slot.length) {
            return null;
        }
        int o = mapOf(triangle);
        if (o < 0) {
            return null;
        }
        double[] h = maps;
        double ds = s - h[o];
        double dt = t - h[o + 1];
        double w = h[o + 8] * ds + h[o + 9] * dt + h[o + 10];
        if (!(w > 0)) {
            return null;
        }
        return new double[] {(h[o + 2] * ds + h[o + 3] * dt + h[o + 4]) / w,
                             (h[o + 5] * ds + h[o + 6] * dt + h[o + 7]) / w};
    }

    /** Offset of the triangle's map in {@link #maps}, building it on first use; negative when undefined. */
    private int mapOf(int triangle) {
        int k = slot[triangle];
        if (k == UNBUILT) {
            k = build(triangle);
            slot[triangle] = k;
        }
        return k > 0 ? (k - 1) * STRIDE : k;
    }

    private int build(int frameTriangle) {
        int d = draws.drawOf(frameTriangle);
        int triangle = frameTriangle - draws.firstTriangle(d);
        Mesh mesh = draws.mesh(d);
        Mat4 modelViewProjection = draws.transform(d);
        int[] corners = mesh.cornerPositions();
        int[] cornerUvs = mesh.cornerUvs();
        float[] positions = mesh.positions();
        float[] uvs = mesh.uvs();
        int material = draws.firstMaterial(d) + mesh.triangleMaterials()[triangle];
        int texW = textureWidths[material];
        int texH = textureHeights[material];
        for (int i = 0; i < 3; i++) {
            int p = corners[3 * triangle + i];
            modelViewProjection.transformPoint(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2], clip, 4 * i);
            int uv = cornerUvs[3 * triangle + i];
            // A corner without texture coordinates has UV (0, 0), as the renderer treats it.
            st[2 * i] = uv < 0 ? 0 : (double) uvs[2 * uv] * texW;
            st[2 * i + 1] = uv < 0 ? 0 : (double) uvs[2 * uv + 1] * texH;
        }
        double s0 = st[0];
        double t0 = st[1];
        double ds1 = st[2] - s0;
        double dt1 = st[3] - t0;
        double ds2 = st[4] - s0;
        double dt2 = st[5] - t0;
        double det = ds1 * dt2 - ds2 * dt1;
        if (!Double.isFinite(det)) {
            return INVALID;
        }
        if (!(Math.abs(det) > DEGENERATE_TOLERANCE * (Math.abs(ds1 * dt2) + Math.abs(ds2 * dt1)))) {
            return DEGENERATE;
        }
        if (STRIDE * (built + 1) > maps.length) {
            maps = Arrays.copyOf(maps, 2 * maps.length);
        }
        int o = STRIDE * built;
        maps[o] = s0;
        maps[o + 1] = t0;
        // Barycentric weights of corners 1 and 2 from (ds, dt) = (s - s0, t - t0):
        // b1 = (dt2 ds - ds2 dt) / det, b2 = (ds1 dt - dt1 ds) / det, b0 = 1 - b1 - b2.
        // Screen-homogeneous position = h0 + b1 (h1 - h0) + b2 (h2 - h0), h_i = viewport(clip_i).
        for (int r = 0; r < 3; r++) {
            double h0 = homogeneous(r, 0);
            double e1 = homogeneous(r, 1) - h0;
            double e2 = homogeneous(r, 2) - h0;
            maps[o + 2 + 3 * r] = (e1 * dt2 - e2 * dt1) / det;
            maps[o + 3 + 3 * r] = (e2 * ds1 - e1 * ds2) / det;
            maps[o + 4 + 3 * r] = h0;
        }
        for (int i = 2; i < STRIDE; i++) {
            if (!Double.isFinite(maps[o + i])) {
                return INVALID;
            }
        }
        built++;
        return built;
    }

    /**
     * Row r of corner i's screen-homogeneous position {@code (x w, y w, w)}: the viewport transform
     * (OpenGL's, with y flipped so that row 0 is the top) applied to clip space without dividing.
     */
    private double homogeneous(int r, int i) {
        double x = clip[4 * i];
        double y = clip[4 * i + 1];
        double w = clip[4 * i + 3];
        return switch (r) {
            case 0 -> (x + w) * halfWidth;
            case 1 -> (w - y) * halfHeight;
            default -> w;
        };
    }
}
