package dev.trisect.perf;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Label;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * Segments (and labels) scattered through a camera's view, for timing the lines ({@code bench --lines N}): each
 * is centred on a random point of the view between 2 and 15 units from the eye, a tenth of that distance
 * long in a random direction, so that on a 1920x1080 frame at 60 degrees it covers tens of pixels
 * wherever it is. Deterministic for a seed.
 */
public final class ScatteredLines {
    private ScatteredLines() {
    }

    /**
     * @param camera the view, world space
     * @param aspect the frame's width over its height
     * @param count  segments
     * @param seed   the random seed
     * @param rgb    their colour, 0xRRGGBB
     * @return the segments, world space
     */
    public static Lines of(Camera camera, double aspect, int count, long seed, int rgb) {
        Random random = new Random(seed);
        Lines.Builder b = Lines.builder();
        for (int i = 0; i < count; i++) {
            double[] d = new double[1];
            Vec3 centre = point(camera, aspect, random, d);
            Vec3 half = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize()
                    .scale(d[0] / 20);
            b.segment(centre.sub(half), centre.add(half), rgb);
        }
        return b.build();
    }

    /**
     * Labels "label 0", "label 1", ... on points scattered as the segments' centres are, for timing text
     * ({@code bench --labels N}): white, 16-pixel {@link Label#DEFAULT_FONT}, depth-tested.
     *
     * @param camera the view, world space
     * @param aspect the frame's width over its height
     * @param count  labels
     * @param seed   the random seed
     * @return the labels, world space
     */
    public static List<Label> labels(Camera camera, double aspect, int count, long seed) {
        Random random = new Random(seed);
        List<Label> out = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            out.add(Label.of("label " + i, point(camera, aspect, random, new double[1])));
        }
        return out;
    }

    /** A random point of the view between 2 and 15 units from the eye; its distance into {@code d[0]}. */
    private static Vec3 point(Camera camera, double aspect, Random random, double[] d) {
        Vec3 forward = camera.target().sub(camera.eye()).normalize();
        Vec3 right = forward.cross(camera.up()).normalize();
        Vec3 up = right.cross(forward);
        double tan = Math.tan(Math.toRadians(camera.fovY()) / 2);
        d[0] = 2 + 13 * random.nextDouble();
        return camera.eye().add(forward.scale(d[0]))
                .add(right.scale((2 * random.nextDouble() - 1) * d[0] * tan * aspect))
                .add(up.scale((2 * random.nextDouble() - 1) * d[0] * tan));
    }
}
