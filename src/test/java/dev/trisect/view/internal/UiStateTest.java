package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;
import java.awt.event.ActionEvent;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.JCheckBox;
import javax.swing.KeyStroke;
import org.junit.jupiter.api.Test;

/** The demo's state and actions, without a window. */
class UiStateTest {
    @Test
    void aToggleFlipsOnItsKeyAndFollowsItsButtons() {
        AtomicInteger runs = new AtomicInteger();
        Command c = Command.toggle("Borders", "tip", KeyStroke.getKeyStroke('B'), cmd -> runs.incrementAndGet());
        assertFalse(c.selected());
        c.actionPerformed(new ActionEvent(new Object(), 0, "key"));
        assertTrue(c.selected(), "a key binding flips the state");
        c.actionPerformed(null);
        assertFalse(c.selected());
        JCheckBox box = new JCheckBox(c);
        box.doClick();
        assertTrue(c.selected(), "a button bound to the action flips it once, not twice");
        assertTrue(box.isSelected());
        c.actionPerformed(new ActionEvent(new Object(), 0, "key"));
        assertFalse(box.isSelected(), "every button shows the state the key set");
        assertEquals(4, runs.get());
        c.show(true);
        assertTrue(box.isSelected());
        assertEquals(4, runs.get(), "showing a state does not run the behaviour");
    }

    @Test
    void inputPacksDragsAndForgetsHeldKeys() {
        InputState in = new InputState();
        in.drag(5, -7);
        in.drag(-2, 3);
        int[] d = in.takeDrag();
        assertEquals(3, d[0]);
        assertEquals(-4, d[1]);
        assertEquals(0, in.takeDrag()[0]);
        in.press(InputState.FORWARD);
        in.press(InputState.FAST);
        in.release(InputState.FORWARD);
        assertEquals(InputState.FAST, in.held());
        in.releaseAll();
        assertEquals(0, in.held());
        in.wheel(2);
        in.wheel(-5);
        assertEquals(-3, in.takeWheel());
        in.requestReset();
        assertTrue(in.takeReset());
        assertFalse(in.takeReset());
    }

    private static Camera start() {
        return Camera.looking(new Vec3(0, 2, 5), new Vec3(0, 2, 0));
    }

    @Test
    void heldKeysFlyAlongTheViewAndShiftIsFaster() {
        CameraRig rig = new CameraRig(start());
        InputState in = new InputState();
        in.press(InputState.FORWARD);
        Camera c = rig.update(in, 0.5);
        assertEquals(5 - CameraRig.SPEED * 0.5, c.eye().z(), 1e-9, "forward is toward the target (-z)");
        in.press(InputState.FAST);
        Camera fast = rig.update(in, 0.5);
        assertEquals(CameraRig.SPEED * CameraRig.FAST_FACTOR * 0.5, c.eye().z() - fast.eye().z(), 1e-9);
        in.releaseAll();
        in.press(InputState.RIGHT);
        Camera right = rig.update(in, 1);
        assertEquals(CameraRig.SPEED, right.eye().x() - fast.eye().x(), 1e-9, "right is +x when looking down -z");
        in.releaseAll();
        in.wheel(-2);
        assertEquals(right.eye().y() + 2 * CameraRig.WHEEL_STEP, rig.update(in, 0.1).eye().y(), 1e-9,
                "wheel away raises the camera");
    }

    @Test
    void aKeyTappedBetweenTwoFramesMovesTheCameraForOne() {
        CameraRig rig = new CameraRig(start());
        InputState in = new InputState();
        in.press(InputState.FORWARD);
        in.release(InputState.FORWARD);
        assertEquals(0, in.held(), "no longer held");
        assertTrue(CameraRig.moving(in), "but the frame still moves the camera");
        Camera c = rig.update(in, 0.1);
        assertEquals(5 - CameraRig.SPEED * 0.1, c.eye().z(), 1e-9, "one frame's worth");
        assertFalse(CameraRig.moving(in), "and only one");
        assertEquals(c.eye(), rig.update(in, 0.1).eye());
        in.press(InputState.BACK);
        in.releaseAll();
        assertFalse(CameraRig.moving(in), "losing the keyboard forgets a tap too");
    }

    @Test
    void dragTurnsAndResetRestores() {
        CameraRig rig = new CameraRig(start());
        InputState in = new InputState();
        in.drag((int) Math.round(Math.PI / 2 / CameraRig.TURN), 0);
        Camera turned = rig.update(in, 0.016);
        Vec3 dir = turned.target().sub(turned.eye());
        assertEquals(1, dir.x(), 1e-3, "a drag to the right turns the view to the right (+x)");
        rig.reset(start());
        Camera back = rig.update(in, 0.016);
        assertEquals(start().eye(), back.eye());
        assertEquals(-1, back.target().sub(back.eye()).z(), 1e-9);
    }

    @Test
    void orbitCirclesAtTheSameHeightAndAnyInputStopsIt() {
        CameraRig rig = new CameraRig(Camera.looking(new Vec3(0, 2, 10), new Vec3(0, 0, 0)));
        InputState in = new InputState();
        in.orbit(true);
        Camera a = rig.update(in, 0.1);
        Camera b = rig.update(in, 2.0);
        assertEquals(a.eye().y(), b.eye().y(), 1e-9);
        assertTrue(a.eye().sub(b.eye()).length() > 0.1, "the camera moved");
        // The orbit circles the point where the view line reaches the target's height: the origin here.
        Vec3 centre = Vec3.ZERO;
        double ra = Math.hypot(a.eye().x() - centre.x(), a.eye().z() - centre.z());
        double rb = Math.hypot(b.eye().x() - centre.x(), b.eye().z() - centre.z());
        assertEquals(ra, rb, 1e-6, "same distance from the centre");
        in.press(InputState.FORWARD);
        rig.update(in, 0.1);
        assertFalse(in.orbit(), "moving by hand ends the orbit");
    }

    @Test
    void tripleBufferNeverHandsTheShownSlotBackToTheRenderer() {
        TripleBuffer t = new TripleBuffer();
        FrameSlot a = new FrameSlot(4, 4);
        FrameSlot b = new FrameSlot(4, 4);
        FrameSlot c = new FrameSlot(4, 4);
        assertNull(t.publish(a));
        FrameSlot shown = t.acquire(null);
        assertSame(a, shown);
        assertSame(a, t.acquire(a), "nothing new: keep showing");
        assertNull(t.publish(b));
        FrameSlot back = t.publish(c);
        assertSame(b, back, "an unshown frame is overwritten by a newer one and reused");
        assertNotSame(shown, back);
        shown = t.acquire(shown);
        assertSame(c, shown, "the newest frame is shown");
        assertSame(a, t.publish(b), "the slot shown before comes back for drawing");
    }

    @Test
    void frameSlotImageShowsTheFramebufferWithoutCopying() {
        FrameSlot s = new FrameSlot(3, 2);
        s.frame.colour()[4] = 0xFF123456;
        assertEquals(0xFF123456, s.image.getRGB(1, 1));
        assertEquals(java.awt.image.BufferedImage.TYPE_INT_RGB, s.image.getType(), "Java2D's fast INT_RGB path");
    }
}
