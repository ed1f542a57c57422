package dev.trisect.devtools;

import java.awt.Component;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.IntConsumer;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.SwingConstants;

/**
 * The developer tools' form layout: titled sections of label/value rows, monospaced readouts, and
 * sliders that report changes made by the user but not those made while showing settings.
 */
final class ToolsForm {
    private final JPanel panel;
    private final Map<String, JLabel> readouts = new LinkedHashMap<>();
    private int rows;

    ToolsForm(String title) {
        panel = new JPanel(new GridBagLayout());
        panel.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
                BorderFactory.createEmptyBorder(2, 4, 4, 4)));
        panel.setAlignmentX(Component.LEFT_ALIGNMENT);
    }

    JPanel panel() {
        return panel;
    }

    /** A right-aligned monospaced value label. */
    static JLabel value() {
        JLabel l = new JLabel("", SwingConstants.RIGHT);
        l.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        return l;
    }

    static JLabel label(String text, String tip) {
        JLabel l = new JLabel(text);
        l.setToolTipText(tip);
        return l;
    }

    /** Adds a row: {@code left} across the width, or {@code left} and {@code right} side by side. */
    void row(Component left, Component right) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = rows++;
        c.insets = new Insets(1, 2, 1, 2);
        c.anchor = GridBagConstraints.WEST;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.gridx = 0;
        c.weightx = right == null ? 1 : 0.6;
        c.gridwidth = right == null ? 2 : 1;
        panel.add(left, c);
        if (right != null) {
            c.gridx = 1;
            c.weightx = 0.4;
            panel.add(right, c);
        }
    }

    void row(Component whole) {
        row(whole, null);
    }

    /** Adds a named readout row, its value empty until {@link #set}. */
    void readout(String name, String tip) {
        JLabel v = value();
        v.setToolTipText(tip);
        readouts.put(name, v);
        row(label(name, tip), v);
    }

    /** Adds readouts from {name, tooltip} pairs. */
    void readouts(String[][] namesAndTips) {
        for (String[] r : namesAndTips) {
            readout(r[0], r[1]);
        }
    }

    void set(String name, String text) {
        JLabel l = readouts.get(name);
        if (l != null && !text.equals(l.getText())) {
            l.setText(text);
        }
    }

    String get(String name) {
        JLabel l = readouts.get(name);
        return l == null ? null : l.getText();
    }

    boolean enabled(String name) {
        JLabel l = readouts.get(name);
        return l != null && l.isEnabled();
    }

    void setEnabled(String name, boolean on) {
        JLabel l = readouts.get(name);
        if (l != null) {
            l.setEnabled(on);
        }
    }

    /**
     * Calls {@code change} when the user moves the slider, and {@code shown} on every change (also
     * those made by {@code syncing} code, for which {@code change} is not called).
     */
    static void listen(JSlider s, java.util.function.BooleanSupplier syncing, Runnable shown, IntConsumer change) {
        s.addChangeListener(e -> {
            shown.run();
            if (!syncing.getAsBoolean()) {
                change.accept(s.getValue());
            }
        });
    }
}
