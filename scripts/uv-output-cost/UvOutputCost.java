import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;

/**
 * What recording the UV output (each pixel's texel coordinates and triangle: what picking reads)
 * costs a frame: the same frame drawn without and with it, interleaved, wall time, after a warm-up.
 * Arguments: [scene] [WxH] [threads] [frames]; defaults demo 1280x720 2 100.
 */
public class UvOutputCost {
    public static void main(String[] args) {
        SceneAsset s = DemoScenes.byName(args.length > 0 ? args[0] : "demo").orElseThrow();
        String[] size = (args.length > 1 ? args[1] : "1280x720").split("x");
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        int n = args.length > 3 ? Integer.parseInt(args[3]) : 100;
        var vp = s.camera().viewProjection(new Viewport(w, h));
        try (FrameRenderer r = new FrameRenderer(threads)) {
            for (RenderMode mode : new RenderMode[] {RenderMode.TESSELLATED, RenderMode.PERSPECTIVE}) {
                RenderSettings rs = RenderSettings.defaults().withMode(mode).withFilter(TextureFilter.TRILINEAR);
                Framebuffer plain = new Framebuffer(w, h);
                Framebuffer uv = new Framebuffer(w, h);
                uv.recordUv(true);
                for (int i = 0; i < 60; i++) {
                    r.render(s.mesh(), s.textureArray(), vp, rs, plain);
                    r.render(s.mesh(), s.textureArray(), vp, rs, uv);
                }
                double[] without = new double[n];
                double[] with = new double[n];
                for (int i = 0; i < n; i++) {
                    long t0 = System.nanoTime();
                    r.render(s.mesh(), s.textureArray(), vp, rs, plain);
                    long t1 = System.nanoTime();
                    r.render(s.mesh(), s.textureArray(), vp, rs, uv);
                    long t2 = System.nanoTime();
                    without[i] = (t1 - t0) / 1e6;
                    with[i] = (t2 - t1) / 1e6;
                }
                Arrays.sort(without);
                Arrays.sort(with);
                System.out.printf("%s: without UV %.1f ms (p10 %.1f, p90 %.1f), with UV %.1f ms (p10 %.1f, p90 %.1f)%n",
                        mode.id(), without[n / 2], without[n / 10], without[9 * n / 10], with[n / 2], with[n / 10],
                        with[9 * n / 10]);
            }
        }
    }
}
