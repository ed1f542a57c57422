package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.scene.Camera;

/**
 * Test oracle for a textured plane y = 0 whose texel coordinates are s = k * x and t = -k * z:
 * casts the ray through a pixel centre onto the plane to get the exact texel coordinates, and maps
 * texel coordinates back to the screen point where the exact mapping shows them.
 */
final class RayOracle {
    private final Camera camera;
    private final Viewport viewport;
    private final double texelsPerUnit;
    private final Vec3 forward;
    private final Vec3 right;
    private final Vec3 up;
    private final double tanHalf;
    private final Mat4 viewProjection;

    RayOracle(Camera camera, Viewport viewport, double texelsPerUnit) {
        this.camera = camera;
        this.viewport = viewport;
        this.texelsPerUnit = texelsPerUnit;
        this.forward = camera.target().sub(camera.eye()).normalize();
        this.right = forward.cross(camera.up()).normalize();
        this.up = right.cross(forward);
        this.tanHalf = Math.tan(Math.toRadians(camera.fovY()) / 2);
        this.viewProjection = camera.viewProjection(viewport);
    }

    /** Exact (s, t) seen at the centre of pixel (x, y), or null if the ray misses the plane. */
    double[] texelAt(int x, int y) {
        double ndcX = (x + 0.5) / viewport.width() * 2 - 1;
        double ndcY = 1 - (y + 0.5) / viewport.height() * 2;
        Vec3 dir = forward.add(right.scale(ndcX * tanHalf * viewport.aspect())).add(up.scale(ndcY * tanHalf));
        if (dir.y() >= 0) {
            return null;
        }
        double t = -camera.eye().y() / dir.y();
        Vec3 p = camera.eye().add(dir.scale(t));
        return new double[] {texelsPerUnit * p.x(), -texelsPerUnit * p.z()};
    }

    /** Screen position (pixels) where the exact mapping shows texel coordinates (s, t). */
    double[] screenOf(double s, double t) {
        Vec3 ndc = viewProjection.transformProject(new Vec3(s / texelsPerUnit, 0, -t / texelsPerUnit));
        return new double[] {(ndc.x() + 1) * 0.5 * viewport.width(), (1 - ndc.y()) * 0.5 * viewport.height()};
    }
}
