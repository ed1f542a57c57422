package dev.trisect.ui;

import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.JComponent;
import javax.swing.JRadioButton;

/** Developer tools: the texturing path, bound to the same commands as keys 1 to 3 and the Render menu. */
final class ModeSection implements ToolSection {
    private final ToolsForm form = new ToolsForm("Mode");

    ModeSection(DemoWindow owner) {
        ButtonGroup group = new ButtonGroup();
        int n = 0;
        for (Command c : owner.modeCommands) {
            JRadioButton b = new JRadioButton(c);
            b.setText(c.getValue(Action.NAME) + " (" + (++n) + ")");
            group.add(b);
            form.row(b);
        }
    }

    @Override
    public JComponent component() {
        return form.panel();
    }
}
