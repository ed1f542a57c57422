package dev.trisect.scene;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.pipeline.FrameStats;
import dev.trisect.pipeline.RenderSettings;
import dev.trisect.raster.Framebuffer;
import dev.trisect.texture.Texture;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Draws a {@link Scene} seen by a {@link Camera} into a framebuffer, and tells what a pixel of the
 * last frame shows. Owns its worker threads: close it when done (or use {@link #renderImage} for a
 * single picture).
 *
 * <pre>{@code
 * try (SceneRenderer renderer = new SceneRenderer()) {
 *     Framebuffer frame = new Framebuffer(800, 600);
 *     FrameStats stats = renderer.render(scene, camera, RenderSettings.defaults(), frame);
 *     renderer.pick(400, 300).ifPresent(p -> System.out.println(p.object().name() + " at " + p.point()));
 * }
 * }</pre>
 *
 * <p>All objects go into one frame with one depth buffer; nearer surfaces win. The projection's aspect
 * ratio is the framebuffer's, so the image is never stretched. Methods are synchronized: one frame at
 * a time, and {@link #pick} may be called from another thread (a view's event thread).
 */
public final class SceneRenderer implements AutoCloseable {
    private final FrameRenderer renderer;
    /** The draws of the last frame, kept for {@link #pick}'s redraw. */
    private final Draws draws = new Draws();
    private boolean closed;
    /** What the last frame drew, for {@link #pick}; null before the first frame. */
    private Drawn last;

    /** A renderer using every available processor. */
    public SceneRenderer() {
        this(Runtime.getRuntime().availableProcessors());
    }

    /**
     * @param threads threads to render with, &gt;= 1 (the calling thread is one of them)
     * @throws IllegalArgumentException when {@code threads} is below 1
     */
    public SceneRenderer(int threads) {
        this.renderer = new FrameRenderer(threads);
    }

    /** Threads this renderer draws with. */
    public int threads() {
        return renderer.threads();
    }

    /**
     * Draws every visible object of {@code scene}, as one {@link Scene#snapshot()}, into {@code frame},
     * which is cleared to the settings' background first.
     *
     * @return what the frame did
     * @throws IllegalStateException after {@link #close()}
     * @throws NullPointerException  for a null argument
     */
    public synchronized FrameStats render(Scene scene, Camera camera, RenderSettings settings, Framebuffer frame) {
        checkOpen();
        Objects.requireNonNull(scene, "scene is null");
        Objects.requireNonNull(camera, "camera is null");
        Objects.requireNonNull(settings, "render settings are null: use RenderSettings.defaults()");
        Objects.requireNonNull(frame, "framebuffer is null");
        Drawn d = new Drawn(scene.snapshot(), camera, settings, frame.width(), frame.height(), draws);
        FrameStats stats = renderer.render(draws, settings, frame);
        d.uvFrame = frame.uv() != null ? frame : null;
        last = d;
        return stats;
    }

    /**
     * What pixel (x, y) of the last frame drawn shows: the object, its triangle, the 3D point and the
     * texel. It describes the objects as they were drawn, not as they may have moved since. When that
     * frame recorded UV output ({@link Framebuffer#recordUv}) it is read from there; otherwise the
     * frame is drawn once more, with UV output, into a framebuffer of its own (the same pixels: drawing
     * is deterministic) — about the cost of one frame.
     *
     * @param x the pixel's column, 0 at the left
     * @param y the pixel's row, 0 at the top
     * @return the pick, or empty where the pixel shows the background, or before the first frame
     * @throws IllegalArgumentException when (x, y) is outside the last frame
     * @throws IllegalStateException    after {@link #close()}
     */
    public synchronized Optional<Pick> pick(int x, int y) {
        checkOpen();
        Drawn d = last;
        if (d == null) {
            return Optional.empty();
        }
        if (x < 0 || y < 0 || x >= d.width || y >= d.height) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the last frame, "
                    + d.width + "x" + d.height);
        }
        double[] uv = d.uvFrame != null && d.uvFrame.uv() != null ? d.uvFrame.uv() : null;
        if (uv == null) {
            Framebuffer f = new Framebuffer(d.width, d.height);
            f.recordUv(true);
            renderer.render(d.draws, d.settings.withBorders(false), f);
            d.uvFrame = f;
            uv = f.uv();
        }
        int i = 3 * (y * d.width + x);
        int id = (int) uv[i + 2] - 1;
        if (id < 0) {
            return Optional.empty();
        }
        return Optional.of(d.pick(id, uv[i], uv[i + 1], x, y));
    }

    /**
     * Draws {@code scene} seen by {@code camera} with the default settings ({@link RenderSettings#defaults()}:
     * tessellated, black background) into a new image.
     *
     * @param width  pixels, 1..{@link Viewport#MAX_SIDE}
     * @param height pixels, 1..{@link Viewport#MAX_SIDE}
     */
    public static BufferedImage renderImage(Scene scene, Camera camera, int width, int height) {
        return renderImage(scene, camera, RenderSettings.defaults(), width, height);
    }

    /** Draws {@code scene} seen by {@code camera} with {@code settings} into a new image. */
    public static BufferedImage renderImage(Scene scene, Camera camera, RenderSettings settings, int width,
                                            int height) {
        new Viewport(width, height); // checks the size with its message
        Framebuffer frame = new Framebuffer(width, height);
        try (SceneRenderer r = new SceneRenderer()) {
            r.render(scene, camera, settings, frame);
        }
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, width, height, frame.color(), 0, width);
        return image;
    }

    /** Stops the worker threads; further calls throw {@link IllegalStateException}. */
    @Override
    public synchronized void close() {
        closed = true;
        renderer.close();
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("this SceneRenderer is closed");
        }
    }

    /** One frame's objects as the pipeline drew them: a draw per object, its own model-view-projection. */
    private static final class Drawn {
        final List<Scene.Placed> placed;
        final Camera camera;
        final RenderSettings settings;
        final int width;
        final int height;
        final Draws draws;
        /** The framebuffer holding this frame's UV output, or null. */
        Framebuffer uvFrame;

        Drawn(List<Scene.Placed> placed, Camera camera, RenderSettings settings, int width, int height, Draws draws) {
            this.placed = placed;
            this.camera = camera;
            this.settings = settings;
            this.width = width;
            this.height = height;
            this.draws = draws;
            Mat4 viewProjection = camera.viewProjection(new Viewport(width, height));
            draws.clear();
            for (Scene.Placed o : placed) {
                List<Material> materials = o.materials();
                Texture[] textures = new Texture[materials.size()];
                for (int i = 0; i < textures.length; i++) {
                    textures[i] = materials.get(i).texture();
                }
                draws.add(o.mesh(), textures, viewProjection.mul(o.world()));
            }
        }

        /** The pick at pixel (x, y) showing frame triangle {@code id} with texel coordinates (s, t). */
        Pick pick(int id, double s, double t, int x, int y) {
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
            int index = texture.texelIndex(s, t);
            return new Pick(o.object(), tri, point, u, v, texture, index % texture.width(), index / texture.width(),
                    x, y);
        }
    }
}
