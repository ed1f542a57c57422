package dev.trisect.devtools;

import dev.trisect.view.internal.ViewController;
import java.awt.Component;
import java.awt.Dialog;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import javax.swing.JDialog;

/**
 * The "Developer tools" window (F12): a {@link DevToolsPanel} in a window beside the view's.
 *
 * <p>The window takes the keyboard when clicked, so that numbers can be typed into its fields, but
 * never takes it by opening ({@link #setAutoRequestFocus} false): F12 leaves the keyboard with the
 * view. The view's command keys (B, C, 1 to 4, F12...) work here as in the view, except while a
 * number is being typed. Event thread only.
 */
public final class DevToolsDialog extends JDialog {
    private static final long serialVersionUID = 1L;

    private final DevToolsPanel panel;
    private boolean folded;
    /** The view's window and the view, which the tools window docks to; null before it is first shown. */
    private Window main;
    private Component view;

    /** A tools window owned by {@code owner} (the view's window; may be null). */
    public DevToolsDialog(Window owner, ViewController controller) {
        super(owner, "Developer tools", Dialog.ModalityType.MODELESS);
        setAutoRequestFocus(false);
        setDefaultCloseOperation(HIDE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                controller.devToolsClosed();
            }
        });
        panel = new DevToolsPanel(controller);
        setContentPane(panel);
        pack();
    }

    public DevToolsPanel panel() {
        return panel;
    }

    /**
     * Docks the window to {@code main}, the window of {@code view} ({@link DevToolsDock}), and shows
     * it; without {@code main}, at the screen's top right. The first time, sections are folded (the
     * least used first) until the rest fit the height it gets, so that none is cut off.
     */
    public void showBeside(Window main, Component view) {
        this.main = main;
        this.view = view;
        if (!folded) {
            folded = true;
            Insets frame = getInsets();
            panel.foldToFit(bounds(Integer.MAX_VALUE / 2, 0).height - frame.top - frame.bottom);
        }
        dock();
        setVisible(true);
    }

    /** Puts the window where {@link DevToolsDock} says for the view's window where it is now. */
    void dock() {
        Dimension content = panel.scrollPane().getViewport().getView().getPreferredSize();
        Insets frame = getInsets();
        int w = Math.max(DevToolsPanel.MIN_WIDTH, content.width + frame.left + frame.right);
        int h = content.height + frame.top + frame.bottom;
        Rectangle b = bounds(h, w);
        if (b.height < h) {
            // Cut short: a scroll bar shows the rest, and the width makes room for it.
            b = bounds(h, w + panel.scrollPane().getVerticalScrollBar().getPreferredSize().width);
        }
        setBounds(b);
        validate();
    }

    private Rectangle bounds(int height, int width) {
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        Dimension wanted = new Dimension(Math.max(width, DevToolsPanel.MIN_WIDTH), height);
        if (main == null || !main.isShowing() || view == null || !view.isShowing()) {
            int h = Math.min(height, usable.height);
            return new Rectangle(usable.x + usable.width - wanted.width, usable.y, wanted.width, h);
        }
        Point at = view.getLocationOnScreen();
        return DevToolsDock.place(main.getBounds(), new Rectangle(at.x, at.y, view.getWidth(), view.getHeight()),
                wanted, usable);
    }

    /** Resizes the window to its content (after a section was folded or opened), docked as before. */
    void refit() {
        if (isShowing()) {
            dock();
        }
    }
}
