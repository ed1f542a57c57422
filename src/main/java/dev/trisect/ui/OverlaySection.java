package dev.trisect.ui;

import javax.swing.JCheckBox;
import javax.swing.JComponent;

/** Developer tools: the polygon-border overlay, bound to the same command as the B key. */
final class OverlaySection implements ToolSection {
    private final ToolsForm form = new ToolsForm("Overlay");

    OverlaySection(DemoWindow owner) {
        JCheckBox borders = new JCheckBox(owner.bordersCommand);
        borders.setText("Show polygon borders (B)");
        borders.setToolTipText("Outline every piece actually filled in yellow: tessellated pieces, or whole "
                + "triangles in the other paths (B)");
        form.row(borders);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }
}
