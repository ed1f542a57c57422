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
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.view.ViewFrame;

/** A textured cube on a ground plane, lit by a sun and a dim ambient light, in a window: fly with W A S D and the mouse; F12 opens the developer tools. */
public final class CubeWindow {
    public static void main(String[] args) {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(20, 20, 10, 10),
                Material.of(ProceduralTextures.uvGrid(256)).withShading(Shading.SMOOTH)));
        scene.add(new SceneObject(Primitives.box(1, 1, 1),
                Material.of(ProceduralTextures.crate(256)).withShading(Shading.FLAT), Transform.translation(0, 0.5, 0)));
        scene.add(Light.ambient(Colour.grey(0.3)), Light.directional(new Vec3(2, 3, 1), Colour.WHITE));
        ViewFrame.open("Cube", scene, Camera.looking(new Vec3(2.5, 1.8, 3), new Vec3(0, 0.4, 0)));
    }
}
