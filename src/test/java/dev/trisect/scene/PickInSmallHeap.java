package dev.trisect.scene;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.ProceduralTextures;

/**
 * Run in a JVM with a small heap by {@link PickMemoryTest}: draws a box into a frame of the given side
 * (which fits), then picks its centre, which must draw the frame again with its triangle ids. Prints the
 * refusal's message on standard error and exits 0 when pick refuses with one, 1 when it runs out of
 * memory bare, 2 when it answers.
 */
public final class PickInSmallHeap {
    private PickInSmallHeap() {
    }

    public static void main(String[] args) {
        int side = Integer.parseInt(args[0]);
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.uvGrid(16))));
        try (SceneRenderer r = new SceneRenderer(1)) {
            r.render(scene, Camera.looking(new Vec3(2, 2, 3), Vec3.ZERO), RenderSettings.defaults(),
                    new Framebuffer(side, side));
            try {
                System.err.println("answered: " + r.pick(side / 2, side / 2));
                System.exit(2);
            } catch (IllegalStateException e) {
                System.err.println(e.getMessage());
                System.exit(0);
            } catch (OutOfMemoryError e) {
                System.err.println("bare " + e);
                System.exit(1);
            }
        }
    }
}
