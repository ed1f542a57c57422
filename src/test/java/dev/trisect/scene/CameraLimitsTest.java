package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import org.junit.jupiter.api.Test;

/** The far plane's limit, {@link Camera#maxFar}: the largest far whose projection is finite, and no larger. */
class CameraLimitsTest {
    private static Camera camera(double near, double far) {
        return new Camera(new Vec3(0, 1, 5), Vec3.ZERO, Vec3.UP, 60, near, far);
    }

    private static boolean finite(Camera c) {
        var m = c.viewProjection(new Viewport(64, 48));
        for (int r = 0; r < 4; r++) {
            for (int col = 0; col < 4; col++) {
                if (!Double.isFinite(m.get(r, col))) {
                    return false;
                }
            }
        }
        return true;
    }

    @Test
    void maxFarIsTheLastFarWhoseProjectionIsFinite() {
        assertEquals(Double.MAX_VALUE, Camera.maxFar(0.1));
        assertEquals(Double.MAX_VALUE, Camera.maxFar(0.5));
        assertEquals(Double.MAX_VALUE, Camera.maxFar(Double.MIN_VALUE));
        for (double near : new double[] {0.75, 1, 3, 1e10, 1e150}) {
            double max = Camera.maxFar(near);
            assertTrue(finite(camera(near, max)), "near " + near + ", far " + max);
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> camera(near, Math.nextUp(max)));
            assertTrue(e.getMessage().contains("so far may be at most " + max), e.getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> Camera.maxFar(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> Camera.maxFar(0));
    }
}
