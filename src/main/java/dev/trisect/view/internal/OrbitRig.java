package dev.trisect.view.internal;

import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;

/**
 * The orbit controls: the camera on a sphere round a centre (the target of the camera it starts
 * from), always looking at it. Drags turn it round the centre, the wheel and W/S (or the up and down
 * arrows) move it nearer or further, A/D (left, right) turn it round, E/Q (Page Up, Page Down) raise
 * and lower it; Shift is faster. +y is up. Render thread only. World space, metres and radians.
 */
public final class OrbitRig {
    /** Radians of turn per logical pixel of drag. */
    static final double TURN = 0.006;
    /** Radians per second a held key turns. */
    static final double KEY_TURN = 1.2;
    /** Distance factor per wheel notch (toward you: further). */
    static final double WHEEL_ZOOM = 1.12;
    /** Distance halves (W) or doubles (S) in this many seconds of a held key. */
    static final double KEY_ZOOM_SECONDS = 0.7;
    /** Highest elevation, radians, short of straight above or below, where "up" would be undefined. */
    static final double MAX_PITCH = 1.55;

    private final Camera base;
    private final Vec3 centre;
    private double distance;
    private double yaw;
    private double pitch;

    /** Orbits round {@code start}'s target, from where {@code start} is. */
    public OrbitRig(Camera start) {
        base = start;
        centre = start.target();
        Vec3 offset = start.eye().sub(centre);
        distance = offset.length();
        pitch = Math.asin(Math.max(-1, Math.min(1, offset.y() / distance)));
        pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch));
        yaw = Math.atan2(offset.x(), offset.z());
    }

    /** The centre turned round, world space. */
    public Vec3 centre() {
        return centre;
    }

    /**
     * Applies the input gathered since the last frame, {@code dt} seconds ago; returns the camera for
     * the next frame. A hand movement ends an auto-orbit (which turns round the centre slowly).
     */
    public Camera update(InputState input, double dt) {
        int[] drag = input.takeDrag();
        int wheel = input.takeWheel();
        int held = input.takeHeld();
        boolean manual = drag[0] != 0 || drag[1] != 0 || wheel != 0 || (held & ~InputState.FAST) != 0;
        if (manual && input.orbit()) {
            input.orbit(false);
        }
        double fast = (held & InputState.FAST) != 0 ? CameraRig.FAST_FACTOR : 1;
        // Dragging right turns the scene right: the camera goes left round the centre.
        yaw -= drag[0] * TURN;
        pitch += drag[1] * TURN;
        double turn = KEY_TURN * fast * dt;
        yaw += ((held & InputState.RIGHT) != 0 ? turn : 0) - ((held & InputState.LEFT) != 0 ? turn : 0);
        pitch += ((held & InputState.UP) != 0 ? turn : 0) - ((held & InputState.DOWN) != 0 ? turn : 0);
        if (input.orbit()) {
            yaw += CameraRig.ORBIT_RATE * dt;
        }
        pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch));
        double zoom = fast * dt / KEY_ZOOM_SECONDS;
        double exponent = ((held & InputState.BACK) != 0 ? zoom : 0) - ((held & InputState.FORWARD) != 0 ? zoom : 0);
        distance *= Math.pow(2, exponent) * Math.pow(WHEEL_ZOOM, wheel);
        // Never into the centre, nor so far that the view direction's length overflows.
        distance = Math.max(1e-6, Math.min(1e12, distance));
        return camera();
    }

    /** The current camera, with the field of view, near and far of the starting one. */
    public Camera camera() {
        Vec3 offset = new Vec3(Math.cos(pitch) * Math.sin(yaw), Math.sin(pitch), Math.cos(pitch) * Math.cos(yaw));
        return new Camera(centre.add(offset.scale(distance)), centre, Vec3.UP, base.fovY(), base.near(), base.far());
    }
}
