package dev.trisect.view.internal;

import dev.trisect.scene.Camera;

/**
 * Chooses each frame's camera: the one the host set, moved by the controls in force (fly, orbit or
 * none). A camera set by the host (or R) replaces whatever the controls had done; until the user
 * moves, the host's camera is used exactly as given (its up vector and target included). Render
 * thread only.
 */
final class CameraDriver {
    private final ViewState state;
    private long homeSerial = -1;
    private Camera camera;
    private ViewState.Controls mode;
    private CameraRig fly;
    private OrbitRig orbit;

    CameraDriver(ViewState state) {
        this.state = state;
    }

    /** The serial of the host's camera the last {@link #next} started from. */
    long homeSerial() {
        return homeSerial;
    }

    /**
     * The camera for the next frame, {@code dt} seconds after the last; with {@code redraw} the same
     * camera as the last frame (a frozen frame drawn again), input made meanwhile dropped.
     */
    Camera next(boolean redraw, double dt) {
        ViewState.CameraRequest home = state.home();
        InputState input = state.input;
        if (home.serial() != homeSerial) {
            homeSerial = home.serial();
            start(home.camera());
        }
        if (input.takeReset()) {
            input.orbit(false);
            start(home.camera());
        }
        ViewState.Controls controls = state.controls();
        if (controls != mode) {
            // Another kind of control takes over from where the camera is now.
            mode = controls;
            start(camera);
        }
        if (redraw || controls == ViewState.Controls.NONE) {
            input.takeDrag();
            input.takeWheel();
            return camera;
        }
        if (!CameraRig.moving(input)) {
            return camera;
        }
        if (controls == ViewState.Controls.FLY) {
            if (fly == null) {
                fly = new CameraRig(home.camera());
                fly.place(camera);
            }
            camera = fly.update(input, dt);
        } else {
            if (orbit == null) {
                orbit = new OrbitRig(aimed(camera, home.camera()));
            }
            camera = orbit.update(input, dt);
        }
        return camera;
    }

    /**
     * The camera {@link #next} chose, or the host's when the host set another since (an update hook
     * may, between the two): input is left for the next frame.
     */
    Camera settled() {
        ViewState.CameraRequest home = state.home();
        if (home.serial() != homeSerial) {
            homeSerial = home.serial();
            start(home.camera());
        }
        return camera;
    }

    /**
     * {@code c} looking at the point as far ahead as the host's camera looks at its target, so that
     * orbiting after flying turns round a point at the distance the host chose, not one metre ahead.
     */
    private static Camera aimed(Camera c, Camera home) {
        if (c == home) {
            return c;
        }
        double reach = home.target().sub(home.eye()).length();
        return new Camera(c.eye(), c.eye().add(c.target().sub(c.eye()).normalize().scale(reach)), c.up(), c.fovY(),
                c.near(), c.far());
    }

    private void start(Camera c) {
        camera = c;
        fly = null;
        orbit = null;
    }
}
