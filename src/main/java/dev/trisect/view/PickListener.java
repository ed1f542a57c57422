package dev.trisect.view;

import dev.trisect.scene.Pick;
import java.awt.event.MouseEvent;

/**
 * Hears about clicks on objects in a {@link TrisectView}: which object, which triangle of its mesh, the
 * exact 3D point and the texel under the mouse, in the frame on screen (see {@link TrisectView#pick}).
 *
 * <p>Called on the event thread, for a click (a press and release without a drag) on a pixel that
 * shows an object; clicks on the background are not reported. The pick's {@code x, y} are the
 * frame's pixel (device pixels times the render scale); the mouse event has the view's coordinates
 * and the buttons and modifiers.
 */
@FunctionalInterface
public interface PickListener {
    /**
     * The user clicked an object.
     *
     * @param pick  the object, its triangle, the 3D point and the texel under the mouse
     * @param click the mouse event (view coordinates, buttons, modifiers)
     */
    void picked(Pick pick, MouseEvent click);
}
