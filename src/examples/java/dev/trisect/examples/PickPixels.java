package dev.trisect.examples;

import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;

/** Which object, triangle, 3D point and texel a pixel shows: prints the answer for a few pixels. */
public final class PickPixels {
    public static void main(String[] args) {
        Scene scene = new Scene();
        SceneObject crate = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.rotation(Quaternion.ofY(30)));
        crate.setName("crate");
        SceneObject ball = new SceneObject(Primitives.sphere(0.5, 24, 12), Material.colour(0xCC3322),
                Transform.translation(1.5, 0, 0));
        ball.setName("ball");
        scene.add(crate, ball);
        try (SceneRenderer renderer = new SceneRenderer()) {
            renderer.render(scene, Camera.looking(new Vec3(0.75, 1, 4), new Vec3(0.75, 0, 0)),
                    RenderSettings.defaults(), new Framebuffer(320, 200));
            for (int[] p : new int[][] {{128, 100}, {191, 100}, {160, 30}}) {
                System.out.println(p[0] + "," + p[1] + ": " + renderer.pick(p[0], p[1])
                        .map(k -> k.object().name() + " triangle " + k.triangle() + " at " + k.point()
                                + " texel " + k.texelX() + "," + k.texelY())
                        .orElse("background"));
            }
        }
    }
}
