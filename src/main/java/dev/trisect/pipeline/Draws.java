package dev.trisect.pipeline;

import dev.trisect.light.FogPass;
import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.raster.PixelState;
import dev.trisect.raster.QuadRaster;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.texture.Texture;
import java.util.Arrays;
import java.util.Objects;

/**
 * What one frame draws: a list of meshes, each with the texture of each of its materials and its
 * own model-view-projection (object space to clip space). Reused from frame to frame: {@link #clear}
 * then {@link #add} each draw.
 *
 * <p>The frame numbers triangles across the draws in order: draw d's triangle t is frame triangle
 * {@code firstTriangle(d) + t} (the id in the UV output and in {@link FrameRecord#pieceAt}), and
 * likewise its positions and materials follow those of the draws before it, so that the stages
 * after the transform see one list of triangles, positions and textures. One draw is exactly the
 * single-mesh frame: every base is 0.
 *
 * <p>Lines ({@link #addLines}) are a list of their own, drawn in their order after every mesh's
 * triangles (see {@link LineGeometry}); the screen-aligned quads ({@link #quads()}) after the fill (see
 * {@link QuadGeometry}).
 */
public final class Draws {
    private static final Mat4 IDENTITY = Mat4.identity();
    private Mesh[] meshes = new Mesh[4];
    private Mat4[] transforms = new Mat4[4];
    /** Per draw and one past the last: the first frame triangle, position and material of the draw. */
    private int[] firstTriangle = new int[5];
    private int[] firstPosition = new int[5];
    private int[] firstMaterial = new int[5];
    /** The textures of every draw's materials, concatenated: indexed by frame material. */
    private Texture[] textures = new Texture[4];
    /** The {@link PixelState} of every draw's materials, beside {@link #textures}. */
    private int[] states = new int[4];
    /** How light falls on every draw's materials, concatenated: indexed by frame material. */
    private Surface[] surfaces = new Surface[4];
    /** Object space to world space per draw, for lighting; the identity unless given. */
    private Mat4[] worlds = new Mat4[4];
    private int count;
    private Lines[] lines = new Lines[2];
    private Mat4[] lineTransforms = new Mat4[2];
    private int[] lineWidths = new int[2];
    private double[] lineNearer = new double[2];
    private int lineCount;
    private long segmentCount;
    private Lights lights = Lights.NONE;
    private boolean anyLit;
    /** Whether any material's pixel state modulates its texel by the colour varyings. */
    private boolean anyModulate;
    /** Whether any lit material is shaded smooth: its colour then varies over a triangle. */
    private boolean anySmooth;
    private Fog fog;
    /** The frame's screen-aligned quads: billboards, glyphs, text backdrops, in drawing order. */
    private final QuadRaster quads = new QuadRaster();
    /** The pass of the last fog set, kept across {@link #clear} for the next frame's same fog. */
    private FogPass fogPass;

    /** Removes every draw, every quad, the lights and the fog, keeping the storage. */
    public void clear() {
        quads.clear();
        Arrays.fill(lines, 0, lineCount, null);
        Arrays.fill(lineTransforms, 0, lineCount, null);
        lineCount = 0;
        segmentCount = 0;
        Arrays.fill(meshes, 0, count, null);
        Arrays.fill(transforms, 0, count, null);
        Arrays.fill(worlds, 0, count, null);
        Arrays.fill(textures, 0, firstMaterial[count], null);
        Arrays.fill(surfaces, 0, firstMaterial[count], null);
        count = 0;
        lights = Lights.NONE;
        anyLit = false;
        anyModulate = false;
        anySmooth = false;
        fog = null;
    }

    /**
     * The frame's lights, world space, until {@link #clear}.
     *
     * @param lights the lights; {@link Lights#NONE} for none
     */
    public void setLights(Lights lights) {
        this.lights = Objects.requireNonNull(lights, "lights is null: use Lights.NONE");
    }

    /** The frame's lights, world space. */
    public Lights lights() {
        return lights;
    }

    /**
     * Whether the frame carries a colour (in varyings 2..4, or once per triangle without a smooth
     * material, {@link #anySmooth}): some material is lit or modulates its texel by the colour
     * ({@link PixelState#MODULATE}).
     */
    public boolean carriesColour() {
        return anyModulate;
    }

    /**
     * Whether some lit material is shaded {@link Shading#SMOOTH}: without one, every triangle of the
     * frame has one colour (its provoking vertex's, or white), which it may carry once per triangle.
     */
    public boolean anySmooth() {
        return anySmooth;
    }

    /** Whether any draw has a lit material. */
    public boolean anyLit() {
        return anyLit;
    }

    /**
     * Adds a mesh to draw after those added before, lit: as {@link #add(Mesh, Texture[], int[], Mat4)},
     * with its model matrix (for its normals and world-space positions) and how light falls on each
     * material. A lit material's pixel state takes {@link PixelState#MODULATE}: its texel is multiplied
     * by the lit colour the frame carries in varyings 2..4.
     *
     * @param states   the {@link PixelState} of each material, or null for state 0 everywhere
     * @param world    object space to world space
     * @param surfaces per material of the mesh, by material index
     */
    public void add(Mesh mesh, Texture[] textures, int[] states, Mat4 modelViewProjection, Mat4 world,
                    Surface[] surfaces) {
        Objects.requireNonNull(world, "world matrix is null");
        Objects.requireNonNull(surfaces, "surfaces array is null");
        if (surfaces.length < mesh.materialCount()) {
            throw new IllegalArgumentException("mesh has " + mesh.materialCount() + " materials but "
                    + surfaces.length + " surfaces were given");
        }
        add(mesh, textures, states, modelViewProjection);
        int m0 = firstMaterial[count - 1];
        for (int i = 0; i < mesh.materialCount(); i++) {
            this.surfaces[m0 + i] = Objects.requireNonNull(surfaces[i], "surface " + i + " is null");
            if (surfaces[i].lit()) {
                anyLit = true;
                this.states[m0 + i] |= PixelState.MODULATE;
                anyModulate = true;
                anySmooth |= surfaces[i].shading() == Shading.SMOOTH;
            }
        }
        worlds[count - 1] = world;
    }

    /** As {@link #add(Mesh, Texture[], int[], Mat4, Mat4, Surface[])} with state 0 for every material. */
    public void add(Mesh mesh, Texture[] textures, Mat4 modelViewProjection, Mat4 world, Surface[] surfaces) {
        add(mesh, textures, null, modelViewProjection, world, surfaces);
    }

    /**
     * Fogs the frame, until {@link #clear}.
     *
     * @param fog the fog, or null for none
     */
    public void setFog(Fog fog) {
        if (fog != null && (fogPass == null || !fog.equals(fogPass.fog()))) {
            fogPass = new FogPass(fog);
        }
        this.fog = fog;
    }

    /** The frame's fog, or null for none. */
    public Fog fog() {
        return fog;
    }

    /** The pass of the frame's fog, or null for none. */
    FogPass fogPass() {
        return fog == null ? null : fogPass;
    }

    /**
     * Adds a mesh to draw after those added before.
     *
     * @param textures            the texture of each material of the mesh, by material index (entries
     *                            past the mesh's material count are ignored)
     * @param modelViewProjection object space to clip space (projection * view * model), as OpenGL
     * @throws IllegalArgumentException when a texture is missing, or the frame would exceed
     *                                   {@link Integer#MAX_VALUE} triangles or positions
     */
    public void add(Mesh mesh, Texture[] textures, Mat4 modelViewProjection) {
        add(mesh, textures, null, modelViewProjection);
    }

    /**
     * Adds a mesh to draw after those added before, each material with its pixel state.
     *
     * @param textures            the texture of each material of the mesh, by material index (entries
     *                            past the mesh's material count are ignored)
     * @param states              the {@link PixelState} of each material, by material index (entries
     *                            past the mesh's material count are ignored), or null for state 0
     *                            ({@code TEXEL | OPAQUE}) everywhere; a {@code MODULATE} state needs a
     *                            frame whose layout carries the colour varyings
     * @param modelViewProjection object space to clip space (projection * view * model), as OpenGL
     * @throws IllegalArgumentException when a texture is missing, a state is not a pixel state, or the
     *                                  frame would exceed {@link Integer#MAX_VALUE} triangles or positions
     */
    public void add(Mesh mesh, Texture[] textures, int[] states, Mat4 modelViewProjection) {
        Objects.requireNonNull(mesh, "mesh is null");
        Objects.requireNonNull(textures, "textures array is null");
        Objects.requireNonNull(modelViewProjection, "model-view-projection matrix is null");
        int materials = mesh.materialCount();
        if (textures.length < materials) {
            throw new IllegalArgumentException("mesh has " + materials + " materials but " + textures.length
                    + " textures were given");
        }
        for (int i = 0; i < materials; i++) {
            if (textures[i] == null) {
                throw new IllegalArgumentException("the texture of material " + i + " (" + mesh.materialNames().get(i)
                        + ") is null");
            }
        }
        if (states != null) {
            if (states.length < materials) {
                throw new IllegalArgumentException("mesh has " + materials + " materials but " + states.length
                        + " pixel states were given");
            }
            for (int i = 0; i < materials; i++) {
                PixelState.check(states[i]);
            }
        }
        long triangles = (long) firstTriangle[count] + mesh.triangleCount();
        long positions = (long) firstPosition[count] + mesh.positionCount();
        if (triangles > Integer.MAX_VALUE || positions > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("a frame holds at most " + Integer.MAX_VALUE
                    + " triangles and positions");
        }
        if (count == meshes.length) {
            meshes = Arrays.copyOf(meshes, 2 * count);
            transforms = Arrays.copyOf(transforms, 2 * count);
            worlds = Arrays.copyOf(worlds, 2 * count);
            firstTriangle = Arrays.copyOf(firstTriangle, 2 * count + 1);
            firstPosition = Arrays.copyOf(firstPosition, 2 * count + 1);
            firstMaterial = Arrays.copyOf(firstMaterial, 2 * count + 1);
        }
        int m0 = firstMaterial[count];
        if (m0 + materials > this.textures.length) {
            this.textures = Arrays.copyOf(this.textures, Math.max(2 * this.textures.length, m0 + materials));
            this.states = Arrays.copyOf(this.states, this.textures.length);
            this.surfaces = Arrays.copyOf(this.surfaces, this.textures.length);
        }
        System.arraycopy(textures, 0, this.textures, m0, materials);
        Arrays.fill(this.surfaces, m0, m0 + materials, Surface.UNLIT);
        if (states == null) {
            Arrays.fill(this.states, m0, m0 + materials, 0);
        } else {
            System.arraycopy(states, 0, this.states, m0, materials);
            for (int i = 0; i < materials; i++) {
                anyModulate |= PixelState.colour(states[i]) == PixelState.MODULATE;
            }
        }
        meshes[count] = mesh;
        transforms[count] = modelViewProjection;
        firstTriangle[count + 1] = (int) triangles;
        firstPosition[count + 1] = (int) positions;
        firstMaterial[count + 1] = m0 + materials;
        count++;
    }

    /**
     * Adds lines to draw after every mesh's triangles and the lines added before.
     *
     * @param lines               the segments, object space
     * @param modelViewProjection object space to clip space, as OpenGL
     * @param width               width in whole pixels, at least 1
     * @throws IllegalArgumentException when the width is below 1
     */
    public void addLines(Lines lines, Mat4 modelViewProjection, int width) {
        addLines(lines, modelViewProjection, width, 0);
    }

    /**
     * As {@link #addLines(Lines, Mat4, int)}, with the lines' depth brought nearer by the fraction
     * {@code nearer} of their 1/w before the depth test (as {@code glPolygonOffset} is used for a
     * wireframe over its own faces: so that edges lying on them show on every pixel).
     *
     * @param nearer 0 for none; a wireframe takes {@link #WIRE_NEARER}
     */
    public void addLines(Lines lines, Mat4 modelViewProjection, int width, double nearer) {
        Objects.requireNonNull(lines, "lines is null");
        Objects.requireNonNull(modelViewProjection, "model-view-projection matrix is null");
        if (width < 1) {
            throw new IllegalArgumentException("line width must be at least 1 pixel, got " + width);
        }
        if (lineCount == this.lines.length) {
            this.lines = Arrays.copyOf(this.lines, 2 * lineCount);
            lineTransforms = Arrays.copyOf(lineTransforms, 2 * lineCount);
            lineWidths = Arrays.copyOf(lineWidths, 2 * lineCount);
            lineNearer = Arrays.copyOf(lineNearer, 2 * lineCount);
        }
        lineNearer[lineCount] = nearer;
        this.lines[lineCount] = lines;
        lineTransforms[lineCount] = modelViewProjection;
        lineWidths[lineCount++] = width;
        segmentCount += lines.segmentCount();
    }

    /**
     * The depth offset of a wireframe drawn over its own faces: 1/w times {@code 1 + WIRE_NEARER}. Large
     * enough for an edge to pass its faces' depth half a pixel off it on a face that recedes by a few
     * percent of its depth per pixel, small enough (1/64) that edges more than that behind a surface
     * stay hidden.
     */
    public static final double WIRE_NEARER = 1.0 / 64;

    /** The depth offset of line draw {@code i} (see {@link #addLines(Lines, Mat4, int, double)}). */
    public double lineNearer(int i) {
        return lineNearer[i];
    }

    /** Number of line draws. */
    public int lineDrawCount() {
        return lineCount;
    }

    /** The lines of line draw {@code i}. */
    public Lines lines(int i) {
        return lines[i];
    }

    /** The model-view-projection of line draw {@code i}. */
    public Mat4 lineTransform(int i) {
        return lineTransforms[i];
    }

    /** The width of line draw {@code i}, pixels. */
    public int lineWidth(int i) {
        return lineWidths[i];
    }

    /** Segments of all line draws. */
    public long segmentCount() {
        return segmentCount;
    }

    /**
     * The frame's screen-aligned quads — billboards, the glyphs of labels and screen text — laid out
     * in screen pixels for this frame's size by whoever fills the draws, and drawn in the order added
     * after the lines; emptied by {@link #clear}.
     *
     * @return the quads, to add to
     */
    public QuadRaster quads() {
        return quads;
    }

    /** Number of draws. */
    public int size() {
        return count;
    }

    /** Triangles of all draws. */
    public int triangleCount() {
        return firstTriangle[count];
    }

    /** Positions of all draws. */
    int positionCount() {
        return firstPosition[count];
    }

    /** The mesh of draw {@code d}. */
    public Mesh mesh(int d) {
        return meshes[d];
    }

    /** The model-view-projection of draw {@code d}. */
    public Mat4 transform(int d) {
        return transforms[d];
    }

    /** Object space to world space of draw {@code d}; the identity for a draw added unlit. */
    public Mat4 world(int d) {
        return worlds[d] != null ? worlds[d] : IDENTITY;
    }

    /** How light falls on each frame material; read-only, may be longer than needed. */
    public Surface[] surfaces() {
        return surfaces;
    }

    /** Frame triangle of draw {@code d}'s first triangle; {@code d == size()} gives the total. */
    public int firstTriangle(int d) {
        return firstTriangle[d];
    }

    /** Frame position of draw {@code d}'s first position. */
    int firstPosition(int d) {
        return firstPosition[d];
    }

    /** Frame material of draw {@code d}'s first material. */
    public int firstMaterial(int d) {
        return firstMaterial[d];
    }

    /** Every draw's textures, indexed by frame material; read-only, may be longer than needed. */
    public Texture[] textures() {
        return textures;
    }

    /**
     * Every draw's {@link PixelState}s, indexed by frame material as {@link #textures()}; read-only, may
     * be longer than needed.
     */
    public int[] states() {
        return states;
    }

    /**
     * The draw holding frame triangle {@code triangle}: the last draw whose first triangle is at most
     * {@code triangle} and which has triangles.
     *
     * @throws IndexOutOfBoundsException outside 0..triangleCount()-1
     */
    public int drawOf(int triangle) {
        if (triangle < 0 || triangle >= triangleCount()) {
            throw new IndexOutOfBoundsException("frame triangle " + triangle + " not in 0.." + (triangleCount() - 1));
        }
        int lo = 0;
        int hi = count - 1;
        // Largest d with firstTriangle[d] <= triangle: draws without triangles share their successor's
        // first triangle and so are passed over.
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (firstTriangle[mid] <= triangle) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }
}
