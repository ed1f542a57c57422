package dev.trisect.devtools;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.IntConsumer;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;

/**
 * The developer tools' form layout: sections of label/value rows under a header that folds the section
 * away and opens it again (the window then refits), monospaced readouts, and sliders that report
 * changes made by the user but not those made while showing settings.
 */
final class ToolsForm {
    private static final String OPEN = "\u25BE ";
    private static final String SHUT = "\u25B8 ";
    private final String title;
    private final JPanel outer = new JPanel(new BorderLayout());
    private final JButton header = new JButton();
    private final JPanel panel;
    private final Map<String, JLabel> readouts = new LinkedHashMap<>();
    /** The sentence readouts ({@link #note}), by name. */
    private final Map<String, JLabel> notes = new LinkedHashMap<>();
    /** Client property of a note's label: its text, plain. */
    private static final String PLAIN = "trisect.plain";
    private int rows;

    ToolsForm(String title) {
        this.title = title;
        panel = new JPanel(new GridBagLayout());
        panel.setBorder(BorderFactory.createEmptyBorder(0, 4, 6, 4));
        header.setHorizontalAlignment(SwingConstants.LEFT);
        header.setBorderPainted(false);
        header.setContentAreaFilled(false);
        header.setFocusable(false);
        header.setFont(header.getFont().deriveFont(Font.BOLD));
        header.setMargin(new Insets(0, 2, 0, 2));
        header.setToolTipText("Fold this section away, or open it");
        header.addActionListener(e -> setOpen(!open()));
        outer.add(header, BorderLayout.NORTH);
        outer.add(panel, BorderLayout.CENTER);
        outer.setBorder(BorderFactory.createMatteBorder(1, 0, 0, 0, new Color(128, 128, 128, 90)));
        outer.setAlignmentX(Component.LEFT_ALIGNMENT);
        outer.putClientProperty(ToolsForm.class, this);
        setOpen(true);
    }

    /** The section's whole panel: its header and its rows. */
    JPanel panel() {
        return outer;
    }

    /** The form of a section's panel, or null if it has none. */
    static ToolsForm of(java.awt.Component sectionPanel) {
        return sectionPanel instanceof JComponent c && c.getClientProperty(ToolsForm.class) instanceof ToolsForm f ? f
                : null;
    }

    String title() {
        return title;
    }

    boolean open() {
        return panel.isVisible();
    }

    /** Opens or folds the section; a tools window holding it refits to its new height. */
    void setOpen(boolean on) {
        panel.setVisible(on);
        header.setText((on ? OPEN : SHUT) + title);
        outer.revalidate();
        if (SwingUtilities.getWindowAncestor(outer) instanceof DevToolsDialog d) {
            SwingUtilities.invokeLater(d::refit);
        }
    }

    /** The header that folds the section, for tests. */
    JButton header() {
        return header;
    }

    /** Characters a tooltip line holds at most before it wraps (about 420 pixels). */
    static final int TIP_LINE = 64;

    /**
     * Wraps every long plain tooltip under {@code root} into lines of at most {@link #TIP_LINE}
     * characters, so that none runs across the screen.
     */
    static void wrapTooltips(Component root) {
        if (root instanceof JComponent c) {
            String tip = c.getToolTipText();
            if (tip != null && !tip.startsWith("<html>") && tip.length() > TIP_LINE) {
                c.setToolTipText(wrap(tip, TIP_LINE));
            }
        }
        if (root instanceof java.awt.Container parent) {
            for (Component child : parent.getComponents()) {
                wrapTooltips(child);
            }
        }
    }

    /** {@code text} as HTML in lines of at most {@code width} characters, broken between words (a longer word alone). */
    static String wrap(String text, int width) {
        StringBuilder out = new StringBuilder("<html>");
        int line = 0;
        for (String word : text.split(" ")) {
            if (line > 0 && line + 1 + word.length() > width) {
                out.append("<br>");
                line = 0;
            } else if (line > 0) {
                out.append(' ');
                line++;
            }
            out.append(word.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;"));
            line += word.length();
        }
        return out.append("</html>").toString();
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
        if (right instanceof NumberField field && field.getToolTipText() == null && left instanceof JLabel l
                && l.getToolTipText() != null) {
            field.setToolTipText(l.getToolTipText() + "; type a number and press Enter");
        }
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

    /**
     * Adds a named readout of a sentence or two: its name above, its text wrapped to the section's width
     * below (read back with {@link #get} as plain text).
     */
    void note(String name, String tip) {
        JLabel text = new JLabel(" ");
        text.setToolTipText(tip);
        row(label(name, tip));
        row(text);
        notes.put(name, text);
    }

    /** Adds readouts from {name, tooltip} pairs. */
    void readouts(String[][] namesAndTips) {
        for (String[] r : namesAndTips) {
            readout(r[0], r[1]);
        }
    }

    void set(String name, String text) {
        JLabel n = notes.get(name);
        if (n != null && !text.equals(n.getClientProperty(PLAIN))) {
            n.putClientProperty(PLAIN, text);
            n.setText(text.isEmpty() ? " " : "<html><body style='width:300px'>" + text.replace("&", "&amp;")
                    .replace("<", "&lt;").replace(">", "&gt;") + "</body></html>");
        }
        JLabel l = readouts.get(name);
        if (l != null && !text.equals(l.getText())) {
            l.setText(text);
        }
    }

    String get(String name) {
        if (notes.containsKey(name)) {
            Object plain = notes.get(name).getClientProperty(PLAIN);
            return plain == null ? "" : plain.toString();
        }
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
