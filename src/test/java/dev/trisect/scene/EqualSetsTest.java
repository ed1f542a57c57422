package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.texture.Texture;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Setting a value equal to the one in force is no change ({@link Scene#version()} stays, so a view
 * draws no frame for it), as a JavaFX property ignores an equal value: a frame listener or hook that
 * sets the same screen text, light direction or transform every frame leaves a still view idle. A
 * different value is still a change. Screen texts, labels and billboards built anew with equal contents
 * are equal.
 */
class EqualSetsTest {
    private interface Change {
        void run();
    }

    private static void same(Scene scene, String what, Change change) {
        long before = scene.version();
        change.run();
        assertEquals(before, scene.version(), what + " set to what it was: no change");
    }

    private static void differs(Scene scene, String what, Change change) {
        long before = scene.version();
        change.run();
        assertTrue(scene.version() > before, what + " set to something else: a change");
    }

    @Test
    void anEqualValueIsNoChangeAndAnotherIsOne() {
        Scene scene = new Scene();
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), Material.colour(0xFF0000),
                Transform.translation(1, 2, 3));
        Light sun = Light.directional(new Vec3(1, 2, 3), Colour.WHITE);
        Light lamp = Light.point(new Vec3(0, 2, 0), Colour.WHITE, 1, 0.5, 0.25);
        scene.add(box, sun, lamp);
        scene.setFog(Fog.linear(1, 10, Colour.grey(0.5)));
        box.setLabels(List.of(Label.of("box", new Vec3(0, 1, 0)).withColour(0xFFFF00)));
        scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, "60 fps")));
        Texture pin = Texture.solid("pin", 0xFFFF0000);
        box.setBillboards(List.of(Billboard.pixels(pin, new Vec3(0, 2, 0), 16, 16)));

        same(scene, "a transform", () -> box.setTransform(Transform.translation(1, 2, 3)));
        same(scene, "visibility", () -> box.setVisible(true));
        same(scene, "a material", () -> box.setMaterial(box.materials().get(0)));
        same(scene, "a line width", () -> box.setLineWidth(1));
        same(scene, "a draw style", () -> box.setDrawStyle(DrawStyle.FILLED));
        same(scene, "a wire colour", () -> box.setWireColour(box.wireColour()));
        same(scene, "a light's direction, any length", () -> sun.setVector(new Vec3(2, 4, 6)));
        same(scene, "a light's colour", () -> sun.setColour(Colour.WHITE));
        same(scene, "attenuation", () -> lamp.setAttenuation(1, 0.5, 0.25));
        same(scene, "fog", () -> scene.setFog(Fog.linear(1, 10, Colour.grey(0.5))));
        same(scene, "labels built anew", () -> box.setLabels(List.of(Label.of("box", new Vec3(0, 1, 0))
                .withColour(0xFFFF00))));
        same(scene, "billboards built anew", () -> box.setBillboards(List.of(Billboard.pixels(pin, new Vec3(0, 2, 0),
                16, 16))));
        same(scene, "screen text built anew", () -> scene.setScreenText(List.of(ScreenText.of(
                ScreenText.Corner.TOP_LEFT, "60 fps"))));

        differs(scene, "a transform", () -> box.setTransform(Transform.translation(1, 2, 4)));
        differs(scene, "visibility", () -> box.setVisible(false));
        differs(scene, "a material", () -> box.setMaterial(Material.colour(0xFF0000)));
        differs(scene, "lines", () -> box.setLines(LineShapes.axes(1)));
        differs(scene, "a line width", () -> box.setLineWidth(2));
        differs(scene, "a draw style", () -> box.setDrawStyle(DrawStyle.WIRE));
        differs(scene, "a light's direction", () -> sun.setVector(new Vec3(3, 2, 1)));
        differs(scene, "a light's colour", () -> sun.setColour(Colour.grey(0.9)));
        differs(scene, "attenuation", () -> lamp.setAttenuation(1, 0.5, 0.5));
        differs(scene, "fog", () -> scene.setFog(null));
        differs(scene, "labels", () -> box.setLabels(List.of(Label.of("box", new Vec3(0, 1, 0)))));
        differs(scene, "billboards", () -> box.setBillboards(List.of(Billboard.pixels(pin, new Vec3(0, 2, 0), 16,
                17))));
        differs(scene, "screen text", () -> scene.setScreenText(List.of(ScreenText.of(
                ScreenText.Corner.TOP_LEFT, "59 fps"))));
    }

    @Test
    void equalTextsAreEqualValues() {
        Label a = Label.of("a\nb", new Vec3(1, 2, 3)).withBackground(0x80000000).onTop();
        Label b = Label.of("a\nb", new Vec3(1, 2, 3)).withBackground(0x80000000).onTop();
        assertEquals(a, b);
        assertEquals(a.hashCode(), b.hashCode());
        assertTrue(!a.equals(b.withColour(0x123456)));
        ScreenText s = ScreenText.of(ScreenText.Corner.BOTTOM_RIGHT, "x").withMargin(3);
        ScreenText t = ScreenText.of(ScreenText.Corner.BOTTOM_RIGHT, "x").withMargin(3);
        assertEquals(s, t);
        assertEquals(s.hashCode(), t.hashCode());
        assertTrue(!s.equals(t.withMargin(4)));
    }
}
