package dev.trisect.ui;

import dev.trisect.content.SceneLighting;
import dev.trisect.math.Vec3;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Light;
import dev.trisect.scene.Scene;
import dev.trisect.view.TrisectView;
import dev.trisect.view.UpdateListener;

/**
 * The demo's light and fog: off, flat or smooth lighting of every material (the L key cycles), by a
 * dim ambient light, a white light from the camera (it follows the camera, as a miner's lamp) and a
 * warm point light circling the point the scene's camera first looked at; and fog on or off (the G
 * key), linear towards the sky's colour. Sized by the scene's first camera: the lamp circles at half
 * the distance from that camera to its target, and the fog reaches from that distance to eight times
 * it. Every scene shown gets the same lights and the same state. The state is the scene's own, not a
 * copy kept here: the developer tools change the same shading, lights and fog, so the keys step from
 * what is shown and the Fog item's check says what is drawn. Event thread, apart from {@link #update},
 * which the view calls on its render thread.
 */
final class DemoLighting implements UpdateListener {
    /** The lighting states the L key steps through. */
    static final Shading[] CYCLE = {Shading.NONE, Shading.FLAT, Shading.SMOOTH};
    /** The lamp's turn, radians a second. */
    static final double LAMP_SPEED = 0.8;

    private final TrisectView view;
    private final Light ambient = Light.ambient(Colour.grey(0.25));
    private final Light headlight = Light.directional(new Vec3(0, 0, 1), Colour.grey(0.75));
    private final Light lamp = Light.point(Vec3.ZERO, new Colour(1, 0.6, 0.3));
    /** The lamp's circle: its centre, radius, angle. */
    private volatile Vec3 centre = Vec3.ZERO;
    private volatile double radius = 1;
    private double angle;
    private volatile Scene scene;

    DemoLighting(TrisectView view) {
        this.view = view;
        view.addUpdateListener(this);
    }

    /** Lights and fogs {@code shown} (the view's new scene, first seen from {@code camera}) as the last one was. */
    void sceneShown(Scene shown, Camera camera) {
        Shading lit = shading();
        boolean fogged = fog();
        if (scene != null) {
            scene.remove(ambient);
            scene.remove(headlight);
            scene.remove(lamp);
        }
        scene = shown;
        centre = camera.target();
        radius = Math.max(1e-3, 0.5 * camera.eye().sub(camera.target()).length());
        double r = radius;
        // Half its light at the centre it circles: 1 / (1 + 0.5 + 0.5).
        lamp.setAttenuation(1, 0.5 / r, 0.5 / (r * r));
        shown.add(ambient, headlight, lamp);
        light(lit);
        setFog(fogged);
    }

    /** Steps from the lighting state shown to the next (off, flat, smooth) and returns it. */
    Shading cycle() {
        Shading next = DemoCommands.next(CYCLE, shading());
        light(next);
        return next;
    }

    /**
     * The lighting state shown: the scene's shading while one of the demo's lights shines, else off
     * (lit materials with every light hidden draw black, which is no lighting state of the L key).
     */
    Shading shading() {
        Scene s = scene;
        if (s == null || !(ambient.isVisible() || headlight.isVisible() || lamp.isVisible())) {
            return Shading.NONE;
        }
        return SceneLighting.shading(s);
    }

    /** Turns the demo's fog on (linear, sized by the scene's first camera) or the scene's fog off. */
    void setFog(boolean on) {
        Scene s = scene;
        if (s == null) {
            return;
        }
        double d = 2 * radius;
        s.setFog(on ? Fog.linear(d, 8 * d, Colour.of(view.getRenderSettings().background())) : null);
        view.requestFrame();
    }

    /** Whether the scene shown has fog, the demo's or any other (the developer tools set others). */
    boolean fog() {
        Scene s = scene;
        return s != null && s.fog().isPresent();
    }

    /** Lights every material as {@code s} says, the demo's lights shining unless it is off. */
    private void light(Shading s) {
        Scene shown = scene;
        if (shown == null) {
            return;
        }
        boolean on = s != Shading.NONE;
        shown.update(() -> {
            SceneLighting.setShading(shown, s);
            ambient.setVisible(on);
            headlight.setVisible(on);
            lamp.setVisible(on);
        });
        view.requestFrame();
    }

    /**
     * Moves the headlight to the camera and the lamp on along its circle; animates while lit, whether
     * by the L key or by the developer tools.
     */
    @Override
    public boolean update(double seconds, long frame) {
        if (shading() == Shading.NONE) {
            return false;
        }
        Camera c = view.getCamera();
        headlight.setVector(c.eye().sub(c.target()));
        angle += LAMP_SPEED * seconds;
        double r = radius;
        lamp.setVector(centre.add(new Vec3(r * Math.cos(angle), 0.6 * r, r * Math.sin(angle))));
        return true;
    }
}
