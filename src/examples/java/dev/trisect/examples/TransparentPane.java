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
import dev.trisect.texture.Texture;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Transparency, rendered headless to a PNG: {@code TransparentPane [out.png]} (pane.png in the temporary
 * folder by default): a crate seen through a blue glass pane at 40 % opacity (blended), beside a fence
 * cut out of a texture whose alpha is 0 or 255 (alpha-tested). Prints where it wrote.
 */
public final class TransparentPane {
    public static void main(String[] args) throws Exception {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(12, 12, 6, 6), Material.of(ProceduralTextures.uvGrid(256))));
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(256)),
                Transform.translation(0, 0.5, 0)));
        scene.add(new SceneObject(Primitives.box(1.6, 1.2, 0.04), Material.colour(0x3080FF).withOpacity(0.4),
                Transform.translation(0.2, 0.6, 1.1)));
        int[] fence = new int[64 * 64];
        for (int i = 0; i < fence.length; i++) {
            fence[i] = (i % 64 / 8 + i / 64 / 8) % 2 == 0 ? 0xFF30A030 : 0x00000000;
        }
        scene.add(new SceneObject(Primitives.box(1.2, 1.2, 0.02), Material.of(new Texture("fence", 64, 64, fence)),
                Transform.translation(-1.6, 0.6, 0)));
        File out = args.length > 0 ? new File(args[0]) : new File(System.getProperty("java.io.tmpdir"), "pane.png");
        ImageIO.write(SceneRenderer.renderImage(scene, Camera.looking(new Vec3(2, 1.6, 4.5), new Vec3(-0.3, 0.5, 0)),
                640, 400), "png", out);
        System.out.println("wrote " + out);
    }
}
