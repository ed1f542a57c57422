import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;
import java.util.Locale;

/**
 * What recording the triangle ids (what a view's picking and hover read: 4 bytes a pixel) and the UV
 * output (each pixel's texel coordinates and triangle, 24 bytes a pixel: the comparison's and the
 * pixel inspector's) cost a frame, per path: the same frame drawn without either, with the ids and
 * with the UV output, interleaved (the order rotating each round, so that none always follows
 * another), wall time, after a warm-up. Each path prints the medians with the 10th and 90th
 * percentiles, and the median of the per-round ratios to the frame without (the pairs drawn
 * moments apart, so the machine's load mostly cancels). Arguments: [scene] [WxH] [threads] [frames]
 * [filter]; defaults demo 1280x720 2 100 trilinear.
 */
public class UvOutputCost {
    public static void main(String[] args) {
        SceneAsset s = DemoScenes.byName(args.length > 0 ? args[0] : "demo").orElseThrow();
        String[] size = (args.length > 1 ? args[1] : "1280x720").split("x");
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        int n = args.length > 3 ? Integer.parseInt(args[3]) : 100;
        TextureFilter filter = TextureFilter.valueOf((args.length > 4 ? args[4] : "trilinear").toUpperCase(Locale.ROOT));
        var vp = s.camera().viewProjection(new Viewport(w, h));
        String[] names = {"without", "ids", "uv"};
        try (FrameRenderer r = new FrameRenderer(threads)) {
            for (RenderMode mode : RenderMode.values()) {
                RenderSettings rs = RenderSettings.defaults().withMode(mode).withFilter(filter);
                Framebuffer[] fbs = {new Framebuffer(w, h), new Framebuffer(w, h), new Framebuffer(w, h)};
                fbs[1].recordIds(true);
                fbs[2].recordUv(true);
                for (int i = 0; i < 40; i++) {
                    for (Framebuffer f : fbs) {
                        r.render(s.mesh(), s.textureArray(), vp, rs, f);
                    }
                }
                double[][] ms = new double[3][n];
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < 3; j++) {
                        int k = (i + j) % 3;
                        long t0 = System.nanoTime();
                        r.render(s.mesh(), s.textureArray(), vp, rs, fbs[k]);
                        ms[k][i] = (System.nanoTime() - t0) / 1e6;
                    }
                }
                StringBuilder line = new StringBuilder(mode.id() + " " + filter.name().toLowerCase(Locale.ROOT) + ":");
                for (int k = 0; k < 3; k++) {
                    double[] ratio = new double[n];
                    for (int i = 0; i < n; i++) {
                        ratio[i] = ms[k][i] / ms[0][i];
                    }
                    Arrays.sort(ratio);
                    double[] sorted = ms[k].clone();
                    Arrays.sort(sorted);
                    line.append(String.format(Locale.ROOT, " %s %.2f ms (p10 %.2f, p90 %.2f)", names[k], sorted[n / 2],
                            sorted[n / 10], sorted[9 * n / 10]));
                    if (k > 0) {
                        line.append(String.format(Locale.ROOT, " x%.3f", ratio[n / 2]));
                    }
                    line.append(k < 2 ? "," : "");
                }
                System.out.println(line);
            }
        }
    }
}
