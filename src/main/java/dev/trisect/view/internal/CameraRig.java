package dev.trisect.view.internal;

import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;

/**
 * The fly controls: a position with yaw and pitch, moved by held keys, turned by mouse drags, raised
 * and lowered by the wheel, or carried round in an auto-orbit. +y is up. Render thread only. World
 * space, metres and radians; speeds in metres per second.
 */
public final class CameraRig {
    static final double SPEED = 4;
    static final double FAST_FACTOR = 5;
    /** Radians of turn per logical pixel of drag. */
    static final double TURN = 0.004;
    static final double WHEEL_STEP = 0.5;
    /** Orbit: radians per second. */
    static final double ORBIT_RATE = 0.12;

    private Camera base;
    private Vec3 eye;
    private double yaw;
    private double pitch;
    private double orbitAngle;
    private double orbitRadius;
    private Vec3 orbitCentre;

    public CameraRig(Camera start) {
        reset(start);
    }

    /**
     * Goes back to {@code start}: its eye, and the yaw and pitch of its view direction; its field of
     * view, near and far are kept for every camera the rig makes.
     */
    public void reset(Camera start) {
        base = start;
        place(start);
    }

    /** Moves to {@code c}'s eye and view direction, keeping the field of view, near and far of the start. */
    public void place(Camera c) {
        eye = c.eye();
        Vec3 d = c.target().sub(c.eye()).normalize();
        pitch = Math.asin(Math.max(-1, Math.min(1, d.y())));
        yaw = Math.atan2(d.x(), -d.z());
        orbitCentre = null;
    }

    /** Whether {@code input} holds anything that would move the camera (held keys, a drag, the wheel, orbiting). */
    static boolean moving(InputState input) {
        return input.pendingDrag() || input.pendingWheel() || (input.pendingHeld() & ~InputState.FAST) != 0
                || input.orbit();
    }

    /**
     * Applies the input gathered since the last frame, {@code dt} seconds ago, and returns the camera
     * for the next frame.
     */
    public Camera update(InputState input, double dt) {
        int[] drag = input.takeDrag();
        int wheel = input.takeWheel();
        int held = input.takeHeld();
        boolean manual = drag[0] != 0 || drag[1] != 0 || wheel != 0
                || (held & ~InputState.FAST) != 0;
        if (manual && input.orbit()) {
            input.orbit(false);
        }
        if (input.orbit()) {
            orbit(dt);
        } else {
            orbitCentre = null;
            yaw += drag[0] * TURN;
            pitch = Math.max(-1.5, Math.min(1.5, pitch - drag[1] * TURN));
            double speed = SPEED * ((held & InputState.FAST) != 0 ? FAST_FACTOR : 1) * dt;
            Vec3 forward = new Vec3(Math.sin(yaw), 0, -Math.cos(yaw));
            Vec3 right = new Vec3(Math.cos(yaw), 0, Math.sin(yaw));
            Vec3 move = Vec3.ZERO;
            if ((held & InputState.FORWARD) != 0) {
                move = move.add(forward);
            }
            if ((held & InputState.BACK) != 0) {
                move = move.sub(forward);
            }
            if ((held & InputState.RIGHT) != 0) {
                move = move.add(right);
            }
            if ((held & InputState.LEFT) != 0) {
                move = move.sub(right);
            }
            if ((held & InputState.UP) != 0) {
                move = move.add(Vec3.UP);
            }
            if ((held & InputState.DOWN) != 0) {
                move = move.sub(Vec3.UP);
            }
            eye = eye.add(move.scale(speed)).add(new Vec3(0, -wheel * WHEEL_STEP, 0));
        }
        return camera();
    }

    /** Circles the point the camera looked at when the orbit began, keeping height and distance. */
    private void orbit(double dt) {
        if (orbitCentre == null) {
            Vec3 d = direction();
            // Orbit around the point on the view line level with the scene's own target, or 10 m ahead.
            double ahead = Math.abs(d.y()) > 1e-3 ? (base.target().y() - eye.y()) / d.y() : -1;
            if (!(ahead > 0 && ahead < 60)) {
                ahead = 10;
            }
            orbitCentre = eye.add(d.scale(ahead));
            Vec3 flat = new Vec3(eye.x() - orbitCentre.x(), 0, eye.z() - orbitCentre.z());
            orbitRadius = Math.max(1, flat.length());
            orbitAngle = Math.atan2(flat.x(), flat.z());
        }
        orbitAngle += ORBIT_RATE * dt;
        eye = new Vec3(orbitCentre.x() + orbitRadius * Math.sin(orbitAngle), eye.y(),
                orbitCentre.z() + orbitRadius * Math.cos(orbitAngle));
        Vec3 d = orbitCentre.sub(eye).normalize();
        pitch = Math.asin(Math.max(-1, Math.min(1, d.y())));
        yaw = Math.atan2(d.x(), -d.z());
    }

    private Vec3 direction() {
        return new Vec3(Math.cos(pitch) * Math.sin(yaw), Math.sin(pitch), -Math.cos(pitch) * Math.cos(yaw));
    }

    /** The current camera, with the field of view, near and far of the starting one. */
    public Camera camera() {
        return new Camera(eye, eye.add(direction()), Vec3.UP, base.fovY(), base.near(), base.far());
    }
}
