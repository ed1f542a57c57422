package dev.trisect.examples;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.DrawStyle;
import dev.trisect.scene.Label;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.io.File;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * Wireframes and helpers, rendered headless to a PNG: {@code WireframeAxes [out.png]} (wireframe.png in
 * the temporary folder by default): a ground grid, axes, a ball filled with its edges over it, a box as
 * wire alone and a wire box around both, the axes named by labels and the ball by one over a backdrop.
 * Prints where it wrote.
 */
public final class WireframeAxes {
    public static void main(String[] args) throws Exception {
        Scene scene = new Scene();
        scene.add(SceneObject.lines(LineShapes.grid(6, 12, 0x606060), 1));
        scene.add(SceneObject.lines(LineShapes.axes(2), 2));
        scene.add(SceneObject.labels(List.of(Label.of("x", new Vec3(2.1, 0, 0)).withColour(0xFF4040),
                Label.of("y", new Vec3(0, 2.1, 0)).withColour(0x40FF40), Label.of("z", new Vec3(0, 0, 2.1)).withColour(0x4080FF))));
        SceneObject ball = new SceneObject(Primitives.sphere(0.6, 16, 8), Material.of(ProceduralTextures.uvGrid(256)),
                Transform.translation(-0.8, 0.6, 0));
        ball.setDrawStyle(DrawStyle.FILLED_AND_WIRE);
        ball.setWireColour(0xFF40FF);
        scene.add(ball);
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), Material.colour(0xFFFFFF),
                Transform.translation(0.9, 0.5, 0));
        box.setDrawStyle(DrawStyle.WIRE);
        box.setWireColour(0xFFC040);
        scene.add(box);
        scene.add(SceneObject.lines(LineShapes.box(3.2, 1.4, 1.6, 0x40C0FF), 1));
        ball.setLabels(List.of(Label.of("ball", new Vec3(0, 0.7, 0)).withBackground(0x80000000)));
        File out = args.length > 0 ? new File(args[0]) : new File(System.getProperty("java.io.tmpdir"), "wireframe.png");
        ImageIO.write(SceneRenderer.renderImage(scene, Camera.looking(new Vec3(3, 2.4, 4), new Vec3(0, 0.4, 0)),
                640, 400), "png", out);
        System.out.println("wrote " + out);
    }
}
