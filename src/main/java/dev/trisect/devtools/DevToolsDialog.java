package dev.trisect.devtools;

import dev.trisect.view.internal.ViewController;
import java.awt.Dialog;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
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
     * The window's size: tall enough for every section where the screen allows, else the screen's
     * usable height below {@code top} (and then a scroll bar, for which the width makes room).
     */
    static Dimension fit(Dimension content, int scrollBarWidth, Rectangle usable, int top) {
        int room = Math.max(200, usable.y + usable.height - Math.max(usable.y, top));
        int height = Math.min(content.height, room);
        int width = Math.max(DevToolsPanel.MIN_WIDTH, content.width) + (height < content.height ? scrollBarWidth : 0);
        return new Dimension(width, height);
    }

    /** The window's size for its content now, its top at {@code top}. */
    private Dimension size(Rectangle usable, int top) {
        Dimension content = panel.scrollPane().getViewport().getView().getPreferredSize();
        Insets frame = getInsets();
        return fit(new Dimension(content.width + frame.left + frame.right,
                content.height + frame.top + frame.bottom), panel.scrollPane().getVerticalScrollBar()
                .getPreferredSize().width, usable, top);
    }

    /**
     * Places the window to the right of {@code main} (or inside the screen), sized to fit, and shows
     * it; without {@code main}, at the screen's top right. The first time, sections are folded (the
     * least used first) until the rest fit the screen's height, so that none is cut off.
     */
    public void showBeside(Window main) {
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        int top = main == null ? usable.y : main.getY();
        if (!folded) {
            folded = true;
            Insets frame = getInsets();
            panel.foldToFit(usable.y + usable.height - Math.max(usable.y, top) - frame.top - frame.bottom);
        }
        setSize(size(usable, top));
        int x = main == null ? usable.x + usable.width : main.getX() + main.getWidth();
        if (x + getWidth() > usable.x + usable.width) {
            x = Math.max(usable.x, usable.x + usable.width - getWidth());
        }
        setLocation(x, Math.max(usable.y, Math.min(top, usable.y + usable.height - getHeight())));
        setVisible(true);
    }

    /** Resizes the window to its content (after a section was folded or opened), where it stands. */
    void refit() {
        if (!isShowing()) {
            return;
        }
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        setSize(size(usable, getY()));
        validate();
    }
}
