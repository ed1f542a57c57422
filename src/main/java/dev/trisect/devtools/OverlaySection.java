package dev.trisect.devtools;

import dev.trisect.render.BorderStyle;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;

/**
 * Developer tools: the polygon-border overlay (bound to the same command as the B key), how its
 * outlines are coloured (as the C key), and whether they fade where pieces are dense.
 */
final class OverlaySection implements ToolSection {
    private final ViewController owner;
    private final ToolsForm form = new ToolsForm("Overlay");
    private final JComboBox<String> colouring = new JComboBox<>(new String[] {"Yellow", "Split depth", "Error bound"});
    private final JCheckBox fade = new JCheckBox("Fade where pieces are dense");
    private boolean syncing;

    OverlaySection(ViewController owner) {
        this.owner = owner;
        JCheckBox borders = new JCheckBox(owner.commands().borders);
        borders.setText("Show polygon borders (B)");
        borders.setToolTipText("Outline every piece actually filled: tessellated pieces, or whole triangles in the "
                + "other paths (B)");
        colouring.setToolTipText("Outline colour (C): yellow; by split depth, cyan unsplit to red at Max depth; or "
                + "by the piece's worst edge error bound over Max error, green to yellow at it, red above. Pieces a "
                + "cap stopped short, filled per pixel, are magenta in each");
        fade.setToolTipText("Outline pieces whose inscribed circle is under 2 px in radius translucent (opacity the "
                + "square of radius / 2 px), so the "
                + "texture still shows near the horizon instead of a solid band of lines");
        colouring.addActionListener(e -> style());
        fade.addActionListener(e -> style());
        form.row(borders);
        form.row(ToolsForm.label("Colour (C)", colouring.getToolTipText()), colouring);
        form.row(fade);
    }

    private void style() {
        if (!syncing) {
            owner.selectBorderStyle(new BorderStyle(BorderStyle.Colouring.values()[colouring.getSelectedIndex()],
                    fade.isSelected()));
        }
    }

    @Override
    public void sync(ViewSettings settings) {
        syncing = true;
        try {
            BorderStyle s = settings.render().borderStyle();
            colouring.setSelectedIndex(s.colouring().ordinal());
            fade.setSelected(s.fade());
        } finally {
            syncing = false;
        }
    }

    @Override
    public JComponent component() {
        return form.panel();
    }
}
