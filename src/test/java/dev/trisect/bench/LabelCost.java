package dev.trisect.bench;

import dev.trisect.math.Vec3;
import dev.trisect.perf.ScatteredLines;
import dev.trisect.raster.BandBins;
import dev.trisect.raster.BandFill;
import dev.trisect.raster.Commands;
import dev.trisect.raster.QuadRaster;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.internal.Sprites;
import java.util.List;
import java.util.Locale;

/**
 * What 1,000 labels cost on one thread, apart from a frame: their layout ({@link Sprites#layOut}: glyph
 * quads placed for the demo's first camera at 1920x1080) and their draw as a frame draws them (set up,
 * listed as QUAD commands, binned into bands of 16 rows and drawn band by band by {@link BandFill}, into
 * an empty depth buffer); the minimum of many rounds each, so that a loaded
 * machine's preemptions fall out. {@code bench --labels} gives the cost inside frames on the renderer's
 * threads. Run: {@code mvn -q test-compile exec:java -Dmain.class=dev.trisect.bench.LabelCost
 * -Dexec.classpathScope=test [-Dexec.args=ROUNDS]}.
 */
public final class LabelCost {
    /** The renderer's band height, rows. */
    private static final int BAND_ROWS = 16;

    private LabelCost() {
    }

    public static void main(String[] args) {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 400;
        int w = 1920;
        int h = 1080;
        Camera camera = new Camera(new Vec3(0.5, 1.8, 6), new Vec3(0, 1.0, -10), Vec3.UP, Camera.DEFAULT_FOV,
                Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR);
        Scene scene = new Scene();
        scene.add(SceneObject.labels(ScatteredLines.labels(camera, (double) w / h, 1000, 1)));
        List<Scene.Placed> placed = scene.snapshot();
        QuadRaster quads = new QuadRaster();
        Framebuffer frame = new Framebuffer(w, h);
        Commands list = new Commands().quads(quads);
        BandFill fill = new BandFill();
        int bands = BandBins.bandCount(h, BAND_ROWS);
        double layout = Double.MAX_VALUE;
        double draw = Double.MAX_VALUE;
        long pixels = 0;
        for (int r = 0; r < rounds; r++) {
            long t0 = System.nanoTime();
            quads.clear();
            Sprites.layOut(placed, camera, w, h, quads);
            long t1 = System.nanoTime();
            frame.clearRows(0, h, 0);
            long t2 = System.nanoTime();
            quads.setUp(w, h);
            list.clear();
            for (int s = 0; s < quads.count(); s++) {
                list.add(Commands.QUAD, s, quads.firstRow(s), quads.lastRow(s) + 1);
            }
            list.bin(h, BAND_ROWS);
            pixels = 0;
            for (int b = 0; b < bands; b++) {
                pixels += fill.fill(frame, list, b, null, false, 0, b * BAND_ROWS, w, Math.min(h, (b + 1) * BAND_ROWS));
            }
            long t3 = System.nanoTime();
            layout = Math.min(layout, (t1 - t0) / 1e6);
            draw = Math.min(draw, (t3 - t2) / 1e6);
        }
        System.out.printf(Locale.ROOT, "1000 labels, %d glyph and backdrop quads, %d pixels: layout %.3f ms, "
                + "draw %.3f ms (one thread, minimum of %d rounds)%n", quads.count(), pixels, layout, draw, rounds);
    }
}
