package dev.trisect.examples;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * A textured cube on a ground plane, rendered headless to a PNG: {@code HeadlessRender [out.png]}
 * (cube.png in the temporary folder by default, not beside the sources); prints where it wrote.
 */
public final class HeadlessRender {
    public static void main(String[] args) throws Exception {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(20, 20, 10, 10), Material.of(ProceduralTextures.uvGrid(256))));
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(256)),
                Transform.translation(0, 0.5, 0)));
        Camera camera = Camera.looking(new Vec3(2.5, 1.8, 3), new Vec3(0, 0.4, 0));
        File out = args.length > 0 ? new File(args[0]) : new File(System.getProperty("java.io.tmpdir"), "cube.png");
        ImageIO.write(SceneRenderer.renderImage(scene, camera, 640, 400), "png", out);
        System.out.println("wrote " + out);
    }
}
