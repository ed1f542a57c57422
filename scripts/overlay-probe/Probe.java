package dev.trisect.pipeline;

import dev.trisect.content.DemoScenes;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Field;
import java.util.function.Supplier;

/**
 * One build's overlay probe for overlay-probe.sh, compiled against that build's jar into package
 * pipeline, where it reaches {@link Outlines} (through reflection on the renderer's private fields):
 * each call renders a tessellated frame without borders, then prepares the plain overlay's plans
 * and draws them band by band (each band's rows read first, as {@code drawBorders} does), then
 * renders the frame with borders, each step timed by the thread's CPU time. One thread.
 */
public final class Probe {
    private Probe() {
    }

    /** @return a supplier of {prepare ms, draw ms (band rows read first), frame ms, frame with borders ms} */
    public static Supplier<double[]> make(String scene, String policy, int width, int height)
            throws ReflectiveOperationException {
        Object s = DemoScenes.byName(scene).orElseThrow(() -> new IllegalArgumentException("no scene " + scene));
        Texture[] textures = (Texture[]) s.getClass().getMethod("textureArray").invoke(s);
        Mesh mesh = (Mesh) s.getClass().getMethod("mesh").invoke(s);
        Camera camera = (Camera) s.getClass().getMethod("camera").invoke(s);
        Framebuffer frame = new Framebuffer(width, height);
        Mat4 viewProjection = camera.viewProjection(new Viewport(width, height));
        SplitPolicy split = switch (policy) {
            case "edge" -> SplitPolicy.EDGE;
            case "error" -> SplitPolicy.ERROR;
            default -> throw new IllegalArgumentException("no policy " + policy);
        };
        RenderSettings plain = RenderSettings.defaults().withBackground(DemoScenes.background(scene))
                .withMode(RenderMode.TESSELLATED)
                .withTessellation(TessellationSettings.defaults().withPolicy(split));
        RenderSettings borders = plain.withBorders(true).withBorderStyle(BorderStyle.plain());
        FrameRenderer renderer = new FrameRenderer(1);
        Outlines outlines = (Outlines) field("outlines").get(renderer);
        FrameGeometry geometry = (FrameGeometry) field("geometry").get(renderer);
        Field drawn = field("drawn");
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        int bandRows = FrameRenderer.BAND_ROWS;
        return () -> {
            long t0 = cpu.getCurrentThreadCpuTime();
            renderer.render(mesh, textures, viewProjection, plain, frame);
            long t1 = cpu.getCurrentThreadCpuTime();
            int chunks;
            try {
                chunks = ((FrameGeometry.Result) drawn.get(renderer)).chunkCount();
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            }
            long t2 = cpu.getCurrentThreadCpuTime();
            outlines.begin(chunks);
            for (int c = 0; c < chunks; c++) {
                outlines.prepare(c, geometry.chunks().get(c).out, BorderStyle.plain(), plain.tessellation(), height);
            }
            long t3 = cpu.getCurrentThreadCpuTime();
            for (int b = 0, y0 = 0; y0 < height; b++, y0 += bandRows) {
                int y1 = Math.min(height, y0 + bandRows);
                frame.touchRows(y0, y1);
                outlines.drawBand(0, frame, b, y0, y1);
            }
            long t4 = cpu.getCurrentThreadCpuTime();
            renderer.render(mesh, textures, viewProjection, borders, frame);
            long t5 = cpu.getCurrentThreadCpuTime();
            return new double[] {(t3 - t2) / 1e6, (t4 - t3) / 1e6, (t1 - t0) / 1e6, (t5 - t4) / 1e6};
        };
    }

    private static Field field(String name) throws NoSuchFieldException {
        Field f = FrameRenderer.class.getDeclaredField(name);
        f.setAccessible(true);
        return f;
    }
}
