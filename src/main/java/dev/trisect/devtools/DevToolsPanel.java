package dev.trisect.devtools;

import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.event.HierarchyEvent;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.JComponent;
import javax.swing.BoxLayout;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ScrollPaneConstants;
import javax.swing.Scrollable;
import javax.swing.Timer;

/**
 * The developer tools as a panel: it stacks its {@link ToolSection}s — overlay, texturing path,
 * split policy, frame budget, the comparison with the per-pixel path, statistics, frame time,
 * camera, render — in a vertical scroll pane, and forwards settings and readings to them; each
 * section owns its controls. Every control says what it does in a tooltip, and changes take effect
 * on the next frame.
 *
 * <p>A host may place it anywhere (beside the view, in a tab); the F12 window
 * ({@link DevToolsDialog}) holds one too. While it shows, it refreshes its readouts a few times a
 * second and the view measures what it displays. Event thread only.
 */
public final class DevToolsPanel extends JPanel {
    private static final long serialVersionUID = 1L;
    /** Narrowest the tools get: room for a label and a value such as "0.4 s ago, 120 ms". */
    static final int MIN_WIDTH = 400;
    /** Pixels one mouse-wheel notch (or arrow click) scrolls the tools. */
    static final int WHEEL_PIXELS = 24;
    /** Readouts refresh this often while the panel shows, milliseconds. */
    static final int REFRESH_MILLIS = 250;

    private final transient ViewController owner;
    private final transient List<ToolSection> sections;
    private final JScrollPane scroll;
    private final Timer refresh;
    private final transient Consumer<ViewSettings> sync = s -> syncFromSettings();
    private boolean showing;

    public DevToolsPanel(ViewController owner) {
        super(new BorderLayout());
        this.owner = owner;
        sections = List.of(new OverlaySection(owner), new ModeSection(owner), new SplitPolicySection(owner),
                new BudgetSection(owner), new CompareSection(owner), new StatisticsSection(owner), new LightSection(owner),
                new TimingSection(owner), new CameraSection(owner), new RenderSection(owner));
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
        add(scroll, BorderLayout.CENTER);
        ToolsForm.wrapTooltips(this);
        // The view's keys work here too while a control of the tools has the keyboard (a number field
        // keeps the keys that type for itself).
        owner.commands().bind(getInputMap(WHEN_ANCESTOR_OF_FOCUSED_COMPONENT), getActionMap());
        refresh = new Timer(REFRESH_MILLIS, e -> refresh());
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0) {
                shown(isShowing());
            }
        });
        syncFromSettings();
    }

    /** Counts this panel among the tools on screen while it shows, and keeps its readouts fresh. */
    private void shown(boolean now) {
        if (now == showing) {
            return;
        }
        showing = now;
        if (now) {
            owner.addSettingsListener(sync);
            syncFromSettings();
            refresh();
            refresh.start();
        } else {
            refresh.stop();
            owner.removeSettingsListener(sync);
        }
        owner.toolsShowing(now ? 1 : -1);
    }

    @Override
    public void removeNotify() {
        // A panel taken out of its window stops counting at once (no hierarchy event may follow).
        shown(false);
        super.removeNotify();
    }

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    public void syncFromSettings() {
        ViewSettings s = owner.state().settings();
        for (ToolSection section : sections) {
            section.sync(s);
        }
    }

    /** Updates the readouts from the render thread's latest numbers. */
    void refresh() {
        for (ToolSection s : sections) {
            s.refresh(owner.state().progress(), owner.front(), owner.state().measurement());
        }
    }

    /**
     * Sections folded first when the tools do not fit their window's height, least used first; the
     * overlay, compare and statistics sections are never folded for room.
     */
    private static final List<Class<? extends ToolSection>> FOLD_FIRST = List.of(RenderSection.class, LightSection.class,
            CameraSection.class, BudgetSection.class, TimingSection.class, ModeSection.class, SplitPolicySection.class);

    /** Folds sections, least used first, until the content is at most {@code height} pixels tall (or none is left). */
    void foldToFit(int height) {
        JComponent content = (JComponent) scroll.getViewport().getView();
        for (Class<? extends ToolSection> type : FOLD_FIRST) {
            if (content.getPreferredSize().height <= height) {
                return;
            }
            ToolsForm.of(section(type).component()).setOpen(false);
            // Before the window is first laid out nothing is valid, so nothing passes the change up: say it here.
            section(type).component().invalidate();
            content.invalidate();
        }
    }

    /** The section of this type, for tests and tooling. */
    public <T extends ToolSection> T section(Class<T> type) {
        for (ToolSection s : sections) {
            if (type.isInstance(s)) {
                return type.cast(s);
            }
        }
        throw new IllegalArgumentException("no section " + type.getSimpleName());
    }

    public JScrollPane scrollPane() {
        return scroll;
    }

    /** The text of one readout, for tests and tooling. */
    public String readout(String name) {
        for (ToolSection s : sections) {
            String text = s.readout(name);
            if (text != null) {
                return text;
            }
        }
        return null;
    }

    /** A panel that a scroll pane lays out at its own width, scrolling only vertically. */
    private static final class TrackingPanel extends JPanel implements Scrollable {
        private static final long serialVersionUID = 1L;

        @Override
        public Dimension getPreferredScrollableViewportSize() {
            return getPreferredSize();
        }

        @Override
        public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
            return WHEEL_PIXELS;
        }

        @Override
        public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
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
