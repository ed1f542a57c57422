package dev.trisect.scene.internal;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.pipeline.Draws;
import dev.trisect.render.Colour;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.ScreenText;
import dev.trisect.texture.Texture;
import java.util.List;
import java.util.Optional;

/**
 * One frame's objects as the pipeline draws them: a draw per visible object, with its own
 * model-view-projection, and the way back from a pixel of the frame to the object, the triangle, the
 * exact 3D point and the texel it shows ({@link #pick}). Used by {@link dev.trisect.scene.SceneRenderer}
 * and the view. Valid while its {@link Draws} are not refilled.
 */
public final class DrawnFrame {
    private static final Mesh NO_TRIANGLES = new MeshBuilder().build();
    private static final Texture[] NO_TEXTURES = new Texture[NO_TRIANGLES.materialCount()];

    static {
        java.util.Arrays.fill(NO_TEXTURES, Texture.solid("none", 0xFF000000));
    }

    private final List<Scene.Placed> placed;
    private final Camera camera;
    private final int width;
    private final int height;
    private final Draws draws;
    private final Sprites sprites;
    /** Frame pixels per pixel of the API: line widths, label and screen text sizes, pixel-sized billboards. */
    private final double pixelScale;
    /** The object of each line draw ({@link Draws#lines(int)}), in order. */
    private final List<LineOwner> lineOwners = new java.util.ArrayList<>();

    /**
     * Fills {@code draws} (cleared first) with a draw per object of {@code placed}, each with its own
     * model-view-projection for {@code camera} and a {@code width x height} frame.
     */
    public DrawnFrame(List<Scene.Placed> placed, Camera camera, int width, int height, Draws draws) {
        this(new Scene.Snapshot(placed, List.of(), Optional.empty()), camera, width, height, draws);
    }

    /**
     * Fills {@code draws} (cleared first) with a draw per object of {@code snapshot}, each with its own
     * model-view-projection for {@code camera} and a {@code width x height} frame, its world matrix and
     * how light falls on each of its materials, and the snapshot's lights and fog.
     */
    public DrawnFrame(Scene.Snapshot snapshot, Camera camera, int width, int height, Draws draws) {
        this(snapshot, camera, width, height, draws, 1);
    }

    /**
     * As {@link #DrawnFrame(Scene.Snapshot, Camera, int, int, Draws)}, with {@code pixelScale} frame pixels
     * for each pixel the API gives a size in (line widths, fonts, pixel-sized billboards, margins): a
     * view's screen scale on a high-density screen, so that they keep their size beside Swing's.
     *
     * @param pixelScale frame pixels per pixel of the API, 1 to 16
     */
    public DrawnFrame(Scene.Snapshot snapshot, Camera camera, int width, int height, Draws draws, double pixelScale) {
        if (!(pixelScale >= 1 && pixelScale <= 16)) {
            throw new IllegalArgumentException("pixel scale must be 1 to 16, got " + pixelScale);
        }
        this.pixelScale = pixelScale;
        List<Scene.Placed> placed = snapshot.objects();
        this.camera = camera;
        this.width = width;
        this.height = height;
        this.draws = draws;
        Mat4 viewProjection = camera.viewProjection(new Viewport(width, height));
        // Draw k is object k of this order: blended objects last, farthest first.
        this.placed = BlendOrder.order(placed, viewProjection);
        draws.clear();
        for (int k = 0; k < this.placed.size(); k++) {
            Scene.Placed o = this.placed.get(k);
            List<Material> materials = o.materials();
            Texture[] textures = new Texture[materials.size()];
            Surface[] surfaces = new Surface[materials.size()];
            for (int i = 0; i < textures.length; i++) {
                Material m = materials.get(i);
                textures[i] = m.texture();
                surfaces[i] = new Surface(m.shading(), m.ambient(), m.diffuse());
            }
            Mat4 mvp = viewProjection.mul(o.world());
            // One draw per object, so that draw k is object k: an object drawn as wire alone draws no triangles.
            if (o.filled()) {
                draws.add(o.mesh(), textures, BlendOrder.states(materials), mvp, o.world(), surfaces);
            } else {
                draws.add(NO_TRIANGLES, NO_TEXTURES, mvp);
            }
            if (!o.lines().isEmpty()) {
                draws.addLines(o.lines(), mvp, scaledWidth(o.lineWidth()));
                lineOwners.add(new LineOwner(o.object().name(), k, false));
            }
            if (!o.wire().isEmpty()) {
                draws.addLines(o.wire(), mvp, scaledWidth(o.lineWidth()), o.filled() ? Draws.WIRE_NEARER : 0);
                lineOwners.add(new LineOwner(o.object().name(), k, true));
            }
        }
        draws.setLights(lights(snapshot.lights()));
        draws.setFog(snapshot.fog().orElse(null));
        sprites = new Sprites(this.placed, viewProjection, camera, width, height, draws.quads(), pixelScale);
    }

    /** A line width of the API in frame pixels, whole. */
    private int scaledWidth(int width) {
        return pixelScale == 1 ? width : (int) Math.round(width * pixelScale);
    }

    /**
     * Adds {@code screen} over the frame: its glyphs after the objects' billboards and labels in the
     * frame's quads ({@link Draws#quads()}).
     *
     * @param screen the screen text to show over the frame, in order
     * @return this
     */
    public DrawnFrame withScreenText(List<ScreenText> screen) {
        for (ScreenText t : screen) {
            Sprites.screenText(t, width, height, draws.quads(), pixelScale);
        }
        return this;
    }

    /** The shining lights as the frame's {@link Lights}, world space. */
    static Lights lights(List<Scene.PlacedLight> shining) {
        Lights.Builder b = Lights.builder();
        double[] none = new double[3];
        for (Scene.PlacedLight l : shining) {
            Colour c = l.colour();
            double[] rgb = {c.r(), c.g(), c.b()};
            Vec3 v = l.vector();
            switch (l.kind()) {
                case AMBIENT -> b.ambient(c.r(), c.g(), c.b());
                // Transforms valid alone can place a light beyond double range (a point light at 1e200
                // under a group scaled 1e200; a direction under groups scaled 1e-200 twice, which
                // underflows to zero): such a light does not shine, rather than failing every frame.
                case DIRECTIONAL -> {
                    if (v.isFinite() && v.length() > 0) {
                        b.directional(v.x(), v.y(), v.z(), none, rgb);
                    }
                }
                case POINT -> {
                    if (v.isFinite()) {
                        b.point(v.x(), v.y(), v.z(), none, rgb, l.kc(), l.kl(), l.kq());
                    }
                }
            }
        }
        return b.build();
    }

    /** The draws, as filled. */
    public Draws draws() {
        return draws;
    }

    /** The objects drawn, in draw order. */
    public List<Scene.Placed> placed() {
        return placed;
    }

    /** The camera the frame was drawn with. */
    public Camera camera() {
        return camera;
    }

    /**
     * Which object a frame triangle belongs to, for readouts such as the pixel inspector.
     *
     * @param name     the object's name, or null when it has none
     * @param draw     the object's place in the frame's draw order, 0-based
     * @param triangle the triangle's index in the object's own mesh, 0-based
     */
    public record Owner(String name, int draw, int triangle) {
    }

    /**
     * Which object a line draw belongs to, for readouts such as the pixel inspector.
     *
     * @param name the object's name, or null when it has none
     * @param draw the object's place in the frame's draw order, 0-based
     * @param wire whether the lines are its mesh's wireframe (else its own lines)
     */
    public record LineOwner(String name, int draw, boolean wire) {
    }

    /** The object line draw {@code i} ({@link Draws#lines(int)}) belongs to. */
    public LineOwner lineOwnerOf(int i) {
        return lineOwners.get(i);
    }

    /**
     * The label quad {@code quad} of {@link Draws#quads()} belongs to (its backdrop or a glyph), or null
     * for a billboard's or the screen text's.
     */
    public Sprites.Placed labelOfQuad(int quad) {
        for (Sprites.Placed p : sprites.labels()) {
            if (quad >= p.firstQuad() && quad < p.endQuad()) {
                return p;
            }
        }
        return null;
    }

    /** The object frame triangle {@code id} (0-based, numbered across the draws) belongs to. */
    public Owner ownerOf(int id) {
        int k = draws.drawOf(id);
        return new Owner(placed.get(k).object().name(), k, id - draws.firstTriangle(k));
    }

    /** The texture frame triangle {@code id} was drawn with. */
    public Texture textureOf(int id) {
        int k = draws.drawOf(id);
        Scene.Placed o = placed.get(k);
        return o.materials().get(o.mesh().triangleMaterials()[id - draws.firstTriangle(k)]).texture();
    }

    /**
     * The pick at pixel (x, y) showing frame triangle {@code id} (0-based: the frame's triangle id
     * minus 1, {@link dev.trisect.render.Framebuffer#ids()}): everything from the triangle and the
     * frame's camera alone — the ray through the pixel centre met with the triangle's plane gives the
     * point, its barycentric weights the texture coordinates, and those the texel — so no UV output and
     * no redraw is needed.
     */
    public Pick pick(int id, int x, int y) {
        int k = draws.drawOf(id);
        Scene.Placed o = placed.get(k);
        int tri = id - draws.firstTriangle(k);
        Mesh m = o.mesh();
        Texture texture = o.materials().get(m.triangleMaterials()[tri]).texture();
        // The ray through the pixel centre, world space (as gluLookAt and gluPerspective build it).
        Vec3 f = camera.target().sub(camera.eye()).normalize();
        Vec3 side = f.cross(camera.up()).normalize();
        Vec3 up = side.cross(f);
        double tanHalf = Math.tan(Math.toRadians(camera.fovY()) / 2);
        double nx = 2 * (x + 0.5) / width - 1;
        double ny = 1 - 2 * (y + 0.5) / height;
        Vec3 dir = f.add(side.scale(nx * tanHalf * width / height)).add(up.scale(ny * tanHalf));
        Vec3[] c = new Vec3[3];
        double[] cu = new double[3];
        double[] cv = new double[3];
        double[] p = new double[4];
        for (int j = 0; j < 3; j++) {
            int pi = m.cornerPositions()[3 * tri + j];
            float[] pos = m.positions();
            o.world().transformPoint(pos[3 * pi], pos[3 * pi + 1], pos[3 * pi + 2], p, 0);
            c[j] = new Vec3(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
            int ui = m.cornerUvs()[3 * tri + j];
            cu[j] = ui < 0 ? 0 : m.uvs()[2 * ui];
            cv[j] = ui < 0 ? 0 : m.uvs()[2 * ui + 1];
        }
        Vec3 e1 = c[1].sub(c[0]);
        Vec3 e2 = c[2].sub(c[0]);
        Vec3 n = e1.cross(e2);
        double along = n.dot(c[0].sub(camera.eye())) / n.dot(dir);
        Vec3 point = camera.eye().add(dir.scale(along));
        // Barycentric weights of the point in the triangle (areas against the normal).
        double nn = n.dot(n);
        double b1 = point.sub(c[0]).cross(e2).dot(n) / nn;
        double b2 = e1.cross(point.sub(c[0])).dot(n) / nn;
        double b0 = 1 - b1 - b2;
        double u = b0 * cu[0] + b1 * cu[1] + b2 * cu[2];
        double v = b0 * cv[0] + b1 * cv[1] + b2 * cv[2];
        // The texel at (u, v), level 0, nearest with repeat: the one the per-pixel perspective path samples.
        int index = texture.texelIndex(u * texture.width(), v * texture.height());
        return new Pick(o.object(), tri, point, u, v, texture, index % texture.width(), index / texture.width(),
                x, y);
    }
}
