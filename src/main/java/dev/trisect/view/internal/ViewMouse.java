package dev.trisect.view.internal;

import dev.trisect.scene.Pick;
import java.awt.Point;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.util.function.Consumer;
import javax.swing.JComponent;

/**
 * A view's mouse: drags turn the camera (or move the split view's divider), the wheel moves it, the
 * pixel inspector follows the mouse and a click pins it, and a click without a drag is reported (for
 * picking). Event thread only.
 */
public final class ViewMouse extends MouseAdapter {
    /** Grab distance of the split divider, logical pixels. */
    private static final int DIVIDER_GRAB = 8;

    private final JComponent view;
    private final ViewController controller;
    private final Consumer<MouseEvent> clicked;
    private int lastX;
    private int lastY;
    private boolean draggingDivider;
    private boolean inspecting;
    private boolean pinned;
    private boolean dragged;
    private final PointerTracker pointer;

    /**
     * @param view       the component it listens to
     * @param controller the view's controller
     * @param clicked    called with each click that was not a drag (view coordinates, logical pixels)
     */
    public ViewMouse(JComponent view, ViewController controller, Consumer<MouseEvent> clicked) {
        this.view = view;
        this.controller = controller;
        this.clicked = clicked;
        this.pointer = new PointerTracker(controller, this);
        view.addMouseListener(this);
        view.addMouseMotionListener(this);
        view.addMouseWheelListener(this);
    }

    private ViewState state() {
        return controller.state();
    }

    private boolean controls() {
        return state().controls() != ViewState.Controls.NONE;
    }

    @Override
    public void mousePressed(MouseEvent e) {
        dragged = false;
        lastX = e.getX();
        lastY = e.getY();
        draggingDivider = state().settings().view() == ViewKind.SPLIT
                && Math.abs(e.getX() - dividerX()) <= DIVIDER_GRAB;
        view.requestFocusInWindow();
        if (!draggingDivider) {
            pointer.pressed(e);
        }
    }

    @Override
    public void mouseExited(MouseEvent e) {
        pointer.left(e);
    }

    @Override
    public void mouseMoved(MouseEvent e) {
        pointer.moved(e);
        if (inspecting && !pinned) {
            inspectAt(e.getX(), e.getY());
        }
    }

    @Override
    public void mouseReleased(MouseEvent e) {
        if (!draggingDivider) {
            pointer.released(e);
        }
        if (dragged || draggingDivider) {
            return;
        }
        if (inspecting && e.isShiftDown()) {
            // Shift and a click pins this pixel to the list whose readouts update each frame, or unpins it.
            FrameSlot f = controller.front();
            if (f != null && view.getWidth() > 0 && view.getHeight() > 0) {
                state().togglePin(frameX(f, e.getX()), frameY(f, e.getY()));
            }
        } else if (inspecting) {
            // A click without a drag pins the inspector to this pixel, or lets it follow again.
            pinned = !pinned;
            inspectAt(e.getX(), e.getY());
        }
        clicked.accept(e);
    }

    @Override
    public void mouseDragged(MouseEvent e) {
        dragged = true;
        if (draggingDivider) {
            double f = view.getWidth() == 0 ? 0.5 : (double) e.getX() / view.getWidth();
            controller.update(s -> s.withSplitFraction(f));
        } else {
            pointer.dragged(e);
            if (controls() && !pointer.gestureConsumed()) {
                state().input.drag(e.getX() - lastX, e.getY() - lastY);
            }
        }
        lastX = e.getX();
        lastY = e.getY();
    }

    @Override
    public void mouseWheelMoved(MouseWheelEvent e) {
        if (controls()) {
            state().input.wheel(e.getWheelRotation());
        }
    }

    /** Turns the pixel inspector on (it follows the mouse; a click pins it) or off. */
    public void inspector(boolean on) {
        inspecting = on;
        pinned = false;
        if (!on) {
            state().inspect(-1, -1);
            state().clearPins();
        } else {
            Point p = view.getMousePosition();
            inspectAt(p == null ? view.getWidth() / 2 : p.x, p == null ? view.getHeight() / 2 : p.y);
        }
    }

    /** The pointer over the view's objects. */
    PointerTracker pointer() {
        return pointer;
    }

    /** A new frame is on screen: look again at what is under a still pointer. */
    public void frameShown() {
        pointer.frameShown();
    }

    /**
     * What the frame on screen shows at view point (x, y) (logical pixels), from its triangle ids;
     * null over nothing, or when the frame kept none.
     */
    public Pick pickAt(int x, int y) {
        return pointer.pickAt(x, y);
    }

    /** Whether the inspector is pinned to a pixel. */
    public boolean pinned() {
        return pinned;
    }

    /** Points the inspector at the frame pixel under view point (x, y). */
    public void inspectAt(int x, int y) {
        FrameSlot f = controller.front();
        if (f == null || view.getWidth() == 0 || view.getHeight() == 0) {
            return;
        }
        state().inspect(frameX(f, x), frameY(f, y));
    }

    /**
     * What the frame on screen shows under a click, from its triangle ids (nothing is drawn): given to
     * {@code picked}, on the event thread, unless the pixel shows the background or no frame is on
     * screen yet.
     */
    public void pick(MouseEvent click, Consumer<Pick> picked) {
        Pick pick = pickAt(click.getX(), click.getY());
        if (pick != null) {
            picked.accept(pick);
        }
    }

    /** The frame column under view point x (logical pixels). */
    public int frameX(FrameSlot f, int x) {
        return Math.max(0, Math.min(f.width() - 1, (int) ((long) x * f.width() / view.getWidth())));
    }

    /** The frame row under view point y (logical pixels). */
    public int frameY(FrameSlot f, int y) {
        return Math.max(0, Math.min(f.height() - 1, (int) ((long) y * f.height() / view.getHeight())));
    }

    private int dividerX() {
        return (int) Math.round(state().settings().splitFraction() * view.getWidth());
    }
}
