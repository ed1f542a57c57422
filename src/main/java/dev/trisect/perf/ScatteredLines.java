package dev.trisect.perf;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.scene.Camera;
import java.util.Random;

/**
 * Segments scattered through a camera's view, for timing the line pass ({@code bench --lines N}): each
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
        Vec3 forward = camera.target().sub(camera.eye()).normalize();
        Vec3 right = forward.cross(camera.up()).normalize();
        Vec3 up = right.cross(forward);
        double tan = Math.tan(Math.toRadians(camera.fovY()) / 2);
        Lines.Builder b = Lines.builder();
        for (int i = 0; i < count; i++) {
            double d = 2 + 13 * random.nextDouble();
            Vec3 centre = camera.eye().add(forward.scale(d))
                    .add(right.scale((2 * random.nextDouble() - 1) * d * tan * aspect))
                    .add(up.scale((2 * random.nextDouble() - 1) * d * tan));
            Vec3 half = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize()
                    .scale(d / 20);
            b.segment(centre.sub(half), centre.add(half), rgb);
        }
        return b.build();
    }
}
