package dev.trisect.examples;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Light;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Three crates on a floor under a warm sun, a dim ambient light and a blue lamp in front of them, rendered
 * headless to a PNG: {@code LitCrates [out.png]} (lit-crates.png in the temporary folder by default).
 * Each face of a crate takes its own brightness from the sun (flat shading); the floor is lit smoothly.
 */
public final class LitCrates {
    public static void main(String[] args) throws Exception {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(20, 20, 10, 10),
                Material.of(ProceduralTextures.uvGrid(256)).withShading(Shading.SMOOTH)));
        Material crate = Material.of(ProceduralTextures.crate(256)).withShading(Shading.FLAT);
        for (int i = -1; i <= 1; i++) {
            scene.add(new SceneObject(Primitives.box(1, 1, 1), crate, Transform.translation(1.6 * i, 0.5, 0)));
        }
        scene.add(Light.ambient(Colour.grey(0.2)),
                Light.directional(new Vec3(2, 3, 1), new Colour(1, 0.9, 0.75)),
                Light.point(new Vec3(0, 0.6, 1.4), new Colour(0.3, 0.5, 1), 1, 0.5, 0.5));
        Camera camera = Camera.looking(new Vec3(2.4, 2.2, 3.8), new Vec3(0, 0.4, 0));
        File out = args.length > 0 ? new File(args[0]) : new File(System.getProperty("java.io.tmpdir"), "lit-crates.png");
        ImageIO.write(SceneRenderer.renderImage(scene, camera, 640, 400), "png", out);
        System.out.println("wrote " + out);
    }
}
