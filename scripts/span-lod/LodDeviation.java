import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.pipeline.PieceInfo;
import dev.trisect.raster.RowKnots;
import dev.trisect.render.*;
import dev.trisect.texture.internal.Lod;
import java.util.*;

/**
 * The span path's level of detail against the exact per-pixel lambda, and the tessellated path's: see
 * scripts/span-lod.sh.
 */
public class LodDeviation {
    static double[] plane(double[] sc, double v0, double v1, double v2) {
        double ex1 = sc[2] - sc[0], ey1 = sc[3] - sc[1], ex2 = sc[4] - sc[0], ey2 = sc[5] - sc[1];
        double det = ex1 * ey2 - ex2 * ey1, d1 = v1 - v0, d2 = v2 - v0;
        return new double[] {v0, (d1 * ey2 - d2 * ey1) / det, (ex1 * d2 - ex2 * d1) / det};
    }
    static double lambda(PieceInfo p, double px, double py) {
        double[] sc = p.screen(), a = p.attributes();
        double[] q = plane(sc, a[0], a[3], a[6]), s = plane(sc, a[1] * a[0], a[4] * a[3], a[7] * a[6]),
                t = plane(sc, a[2] * a[0], a[5] * a[3], a[8] * a[6]);
        double dx = px - sc[0], dy = py - sc[1];
        double Q = q[0] + q[1] * dx + q[2] * dy, S = (s[0] + s[1] * dx + s[2] * dy) / Q, T = (t[0] + t[1] * dx + t[2] * dy) / Q;
        return Lod.lambda((s[1] - S * q[1]) / Q, (t[1] - T * q[1]) / Q, (s[2] - S * q[2]) / Q, (t[2] - T * q[2]) / Q);
    }
    public static void main(String[] args) {
        int w = Integer.parseInt(args[0]), h = Integer.parseInt(args[1]);
        for (String name : new String[] {"demo", "floor", "boxes", "sphere"}) {
            SceneAsset sc = DemoScenes.byName(name).orElseThrow();
            Mat4 vp = sc.camera().viewProjection(new Viewport(w, h));
            for (String path : new String[] {"spans", "error"}) {
                RenderSettings s = RenderSettings.defaults().withFilter(dev.trisect.texture.TextureFilter.TRILINEAR);
                s = path.equals("spans") ? s.withMode(RenderMode.SPANS)
                        : s.withMode(RenderMode.TESSELLATED).withTessellation(TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR));
                try (FrameRenderer r = new FrameRenderer(1)) {
                    Framebuffer fb = new Framebuffer(w, h);
                    fb.recordUv(true);
                    r.render(sc.mesh(), sc.textureArray(), vp, s, fb);
                    List<Double> dev = new ArrayList<>();
                    for (int y = 0; y < h; y += 2) for (int x = 0; x < w; x += 2) {
                        int i = y * w + x;
                        int id = (int) fb.uv()[3 * i + 2] - 1;
                        if (id < 0) continue;
                        PieceInfo p = r.drawn().pieceAt(x, y, id, fb.depth()[i]);
                        if (p == null) continue;
                        double exact = lambda(p, x + 0.5, y + 0.5);
                        double used;
                        if (path.equals("spans")) {
                            RowKnots k = r.drawn().knotsAt(x, y, id, fb.depth()[i]);
                            int found = Arrays.binarySearch(k.columns(), x);
                            int seg = found >= 0 ? found : -found - 2;
                            int a = k.columns()[seg], b = k.columns()[Math.min(seg + 1, k.columns().length - 1)];
                            used = 0.5 * (lambda(p, a + 0.5, y + 0.5) + lambda(p, b + 0.5, y + 0.5));
                        } else {
                            double[] d = p.affineDerivatives();
                            used = p.fallback() ? exact : Lod.lambda(d[0], d[1], d[2], d[3]);
                        }
                        // Only where trilinear blends levels: lambda in (0, 7) for these 256..512 px textures.
                        double ce = Math.max(0, Math.min(8, exact)), cu = Math.max(0, Math.min(8, used));
                        dev.add(Math.abs(ce - cu));
                    }
                    Collections.sort(dev);
                    System.out.printf("%s %s %dx%d: %d pixels, max %.3f, p99 %.3f, p999 %.3f, mean %.4f level%n", name, path, w, h,
                            dev.size(), dev.get(dev.size() - 1), dev.get((int) (dev.size() * 0.99)), dev.get((int) (dev.size() * 0.999)),
                            dev.stream().mapToDouble(d -> d).average().orElse(0));
                }
            }
        }
    }
}
