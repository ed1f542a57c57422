package dev.trisect.ui;

import java.awt.Dialog;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JDialog;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.Scrollable;
import javax.swing.ScrollPaneConstants;

/**
 * The "Developer tools" window. It only stacks its {@link ToolSection}s — overlay, texturing path,
 * split policy, the comparison with the per-pixel path, statistics, render — and forwards settings
 * and readings to them; each section owns its controls. Every control says what it does in a
 * tooltip, and changes take effect on the next frame.
 *
 * <p>The window never takes the keyboard ({@link #setFocusableWindowState} false), so the view keeps
 * flying while the mouse works the controls here. Event thread only.
 */
final class DevToolsDialog extends JDialog {
    private static final long serialVersionUID = 1L;

    private final transient DemoWindow owner;
    private final transient List<ToolSection> sections;

    DevToolsDialog(DemoWindow owner) {
        super(owner.frame(), "Developer tools", Dialog.ModalityType.MODELESS);
        this.owner = owner;
        setFocusableWindowState(false);
        setAutoRequestFocus(false);
        setDefaultCloseOperation(HIDE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                owner.devToolsClosed();
            }
        });
        sections = List.of(new OverlaySection(owner), new ModeSection(owner), new SplitPolicySection(owner),
                new BudgetSection(owner), new CompareSection(owner), new StatisticsSection(owner), new TimingSection(owner),
                new CameraSection(owner), new RenderSection(owner));
        // Laid out at the viewport's width, so that the value column never hides under the scroll bar.
        JPanel content = new TrackingPanel();
        content.setLayout(new BoxLayout(content, BoxLayout.Y_AXIS));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        for (ToolSection s : sections) {
            content.add(s.component());
        }
        content.add(Box.createVerticalGlue());
        scroll = new JScrollPane(content, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        scroll.setBorder(null);
        // One wheel notch moves about three rows, not the default few pixels.
        scroll.getVerticalScrollBar().setUnitIncrement(WHEEL_PIXELS);
        setContentPane(scroll);
        pack();
    }

    /** Narrowest the tools get: room for a label and a value such as "0.4 s ago, 120 ms". */
    static final int MIN_WIDTH = 400;

    /** Pixels one mouse-wheel notch (or arrow click) scrolls the tools. */
    static final int WHEEL_PIXELS = 24;

    private final JScrollPane scroll;

    /**
     * The window's size: tall enough for every section where the screen allows, else the screen's
     * usable height below {@code top} (and then a scroll bar, for which the width makes room).
     */
    static Dimension fit(Dimension content, int scrollBarWidth, Rectangle usable, int top) {
        int room = Math.max(200, usable.y + usable.height - Math.max(usable.y, top));
        int height = Math.min(content.height, room);
        int width = Math.max(MIN_WIDTH, content.width) + (height < content.height ? scrollBarWidth : 0);
        return new Dimension(width, height);
    }

    /** Places the window to the right of the main window (or inside the screen), sized to fit, and shows it. */
    void showBeside(Window main) {
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        Dimension content = getContentPane().getPreferredSize();
        Insets frame = getInsets();
        Dimension size = fit(new Dimension(content.width + frame.left + frame.right,
                content.height + frame.top + frame.bottom), scroll.getVerticalScrollBar().getPreferredSize().width,
                usable, main.getY());
        setSize(size);
        int x = main.getX() + main.getWidth();
        if (x + getWidth() > usable.x + usable.width) {
            x = Math.max(usable.x, usable.x + usable.width - getWidth());
        }
        setLocation(x, Math.max(usable.y, Math.min(main.getY(), usable.y + usable.height - getHeight())));
        setVisible(true);
    }

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    void syncFromSettings() {
        ViewSettings s = owner.state().settings();
        for (ToolSection section : sections) {
            section.sync(s);
        }
    }

    /** The section of this type, for tests and tooling. */
    <T extends ToolSection> T section(Class<T> type) {
        for (ToolSection s : sections) {
            if (type.isInstance(s)) {
                return type.cast(s);
            }
        }
        throw new IllegalArgumentException("no section " + type.getSimpleName());
    }

    JScrollPane scrollPane() {
        return scroll;
    }

    /** The text of one readout, for tests and tooling. */
    String readout(String name) {
        for (ToolSection s : sections) {
            String text = s.readout(name);
            if (text != null) {
                return text;
            }
        }
        return null;
    }

    /** Updates the readouts from the render thread's latest numbers. */
    void refresh(DemoState.Progress progress, FrameSlot front, DemoState.Measurement m) {
        for (ToolSection s : sections) {
            s.refresh(progress, front, m);
        }
    }

    /** A panel that a scroll pane lays out at its own width, scrolling only vertically. */
    private static final class TrackingPanel extends JPanel implements Scrollable {
        private static final long serialVersionUID = 1L;

        @Override
        public Dimension getPreferredScrollableViewportSize() {
            return getPreferredSize();
        }

        @Override
        public int getScrollableUnitIncrement(java.awt.Rectangle visible, int orientation, int direction) {
            return WHEEL_PIXELS;
        }

        @Override
        public int getScrollableBlockIncrement(java.awt.Rectangle visible, int orientation, int direction) {
            return Math.max(WHEEL_PIXELS, visible.height - WHEEL_PIXELS);
        }

        @Override
        public boolean getScrollableTracksViewportWidth() {
            return true;
        }

        @Override
        public boolean getScrollableTracksViewportHeight() {
            return false;
        }
    }
}
