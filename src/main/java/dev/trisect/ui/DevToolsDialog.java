package dev.trisect.ui;

import java.awt.Dialog;
import java.awt.Toolkit;
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
                new CompareSection(owner), new StatisticsSection(owner), new RenderSection(owner));
        JPanel content = new JPanel();
        content.setLayout(new BoxLayout(content, BoxLayout.Y_AXIS));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        for (ToolSection s : sections) {
            content.add(s.component());
        }
        content.add(Box.createVerticalGlue());
        JScrollPane scroll = new JScrollPane(content);
        scroll.setBorder(null);
        setContentPane(scroll);
        pack();
        setSize(380, Math.min(getHeight(), 900));
    }

    /** Places the window to the right of the main window (or inside the screen) and shows it. */
    void showBeside(Window main) {
        int x = main.getX() + main.getWidth();
        int screen = Toolkit.getDefaultToolkit().getScreenSize().width;
        if (x + getWidth() > screen) {
            x = Math.max(0, screen - getWidth());
        }
        setLocation(x, main.getY());
        setVisible(true);
    }

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    void syncFromSettings() {
        ViewSettings s = owner.state().settings();
        for (ToolSection section : sections) {
            section.sync(s);
        }
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
}
