package dev.trisect.devtools;

import dev.trisect.texture.TextureFilter;
import dev.trisect.view.internal.Command;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import java.awt.Component;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JList;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JRadioButton;

/**
 * Developer tools: the texturing path, bound to the same commands as keys 1 to 4 and the Render menu,
 * and the texture filter (key F and the View menu step through the same choices).
 */
final class ModeSection implements ToolSection {
    private final ToolsForm form = new ToolsForm("Mode");
    private final JComboBox<TextureFilter> filter = new JComboBox<>(TextureFilter.values());
    private boolean syncing;

    ModeSection(ViewController owner) {
        ButtonGroup group = new ButtonGroup();
        int n = 0;
        for (Command c : owner.commands().modes) {
            JRadioButton b = new JRadioButton(c);
            b.setText(c.getValue(Action.NAME) + " (" + (++n) + ")");
            group.add(b);
            form.row(b);
        }
        filter.setRenderer(new DefaultListCellRenderer() {
            private static final long serialVersionUID = 1L;

            @Override
            public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                                                          boolean focus) {
                Object shown = value instanceof TextureFilter f ? f.id() : value;
                return super.getListCellRendererComponent(list, shown, index, selected, focus);
            }
        });
        filter.setToolTipText("Texture filter in every path: OpenGL's GL_NEAREST, GL_LINEAR or "
                + "GL_LINEAR_MIPMAP_LINEAR (F steps through them)");
        filter.addActionListener(e -> {
            if (!syncing) {
                owner.selectFilter((TextureFilter) filter.getSelectedItem());
            }
        });
        form.row(ToolsForm.label("Texture filter (F)", filter.getToolTipText()), filter);
    }

    @Override
    public void sync(ViewSettings settings) {
        syncing = true;
        try {
            filter.setSelectedItem(settings.render().filter());
        } finally {
            syncing = false;
        }
    }

    @Override
    public JComponent component() {
        return form.panel();
    }
}
