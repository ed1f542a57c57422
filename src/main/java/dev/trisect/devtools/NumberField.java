package dev.trisect.devtools;

import dev.trisect.base.internal.ErrorLine;
import java.awt.Font;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.SwingConstants;

/**
 * A typed number beside a slider (or alone): it shows the value in force, and a number typed into
 * it applies on Enter or when the field loses the keyboard. Text that is not a number in its range
 * gets a one-line message naming the field, the text and the range, and the field shows the value in
 * force again; the next number it accepts gets a message too ("Max edge: 16 px"), which takes the
 * refusal's place in a status bar. Escape drops the typing. Event thread only.
 */
final class NumberField extends JTextField {
    private static final long serialVersionUID = 1L;

    private final String name;
    private final String unit;
    private final double min;
    private final double max;
    private final transient DoubleConsumer apply;
    private final transient Consumer<String> problem;
    private double shown = Double.NaN;
    private String format = "%.2f";
    /** Whether the last text committed was refused: the next accepted one then says so, replacing the refusal. */
    private boolean refused;

    /**
     * @param name    the field's name in messages ("Max error")
     * @param unit    its unit, shown after the number and accepted after a typed one ("px", "%", "ms"; may be empty)
     * @param min     smallest value accepted; negative infinity for none (the value's user then refuses
     *                what it must, infinities among it)
     * @param max     largest value accepted; positive infinity for none
     * @param apply   given each accepted value
     * @param problem given the one-line message about text that is not accepted, and the one about the
     *                next accepted value after it
     */
    NumberField(String name, String unit, double min, double max, DoubleConsumer apply, Consumer<String> problem) {
        super(7);
        this.name = name;
        this.unit = unit;
        this.min = min;
        this.max = max;
        this.apply = apply;
        this.problem = problem;
        setHorizontalAlignment(SwingConstants.RIGHT);
        setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        addActionListener(e -> {
            commit();
            // Ready for the next number: typing replaces this one.
            selectAll();
        });
        addFocusListener(new FocusAdapter() {
            @Override
            public void focusGained(FocusEvent e) {
                selectAll();
            }

            @Override
            public void focusLost(FocusEvent e) {
                if (!e.isTemporary()) {
                    commit();
                }
            }
        });
        getInputMap().put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), "trisect-revert");
        getActionMap().put("trisect-revert", new javax.swing.AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                show(shown);
            }
        });
    }

    /**
     * Plain keys type into the field: they never reach the commands bound around it (1 to 4, B, the
     * space bar...), which would otherwise act on a digit typed into a number. Keys that type nothing
     * (F12, F5, Escape, the arrows) and those with Ctrl or Alt still do.
     */
    @Override
    protected boolean processKeyBinding(KeyStroke ks, KeyEvent e, int condition, boolean pressed) {
        if (super.processKeyBinding(ks, e, condition, pressed)) {
            return true;
        }
        boolean typing = e.getKeyChar() != KeyEvent.CHAR_UNDEFINED && !Character.isISOControl(e.getKeyChar())
                && (e.getModifiersEx() & (InputEvent.CTRL_DOWN_MASK | InputEvent.ALT_DOWN_MASK
                | InputEvent.META_DOWN_MASK)) == 0;
        return condition == WHEN_FOCUSED && typing;
    }

    /** Shows whole numbers (counts, pixels on an integer slider) or this many decimals. */
    NumberField decimals(int places) {
        format = "%." + places + "f";
        return this;
    }

    /** Shows {@code value} as the value in force, without applying it. */
    void show(double value) {
        shown = value;
        String text = text(value);
        if (!text.equals(getText())) {
            setText(text);
        }
    }

    String text(double value) {
        // Beyond a billion, fixed decimals would fill the field with digits (a fog's end may be 1e300).
        String number = Math.abs(value) >= 1e9 ? String.format(Locale.ROOT, "%.6g", value)
                : String.format(Locale.ROOT, format, value);
        return Double.isNaN(value) ? "" : number + (unit.isEmpty() ? "" : " " + unit);
    }

    /** Applies the typed text if it is a number in range (and differs from the value shown), else says why. */
    void commit() {
        String typed = getText().trim();
        if (typed.equals(text(shown))) {
            return;
        }
        Double v = parse(typed, unit);
        if (v == null || !(v >= min && v <= max)) {
            problem.accept(ErrorLine.of(String.format(Locale.ROOT, "%s: \"%s\" is not a number%s; kept %s",
                    name, typed, range(), text(shown))));
            show(shown);
            refused = true;
            return;
        }
        apply.accept(v);
        if (refused) {
            refused = false;
            problem.accept(name + ": " + text(v));
        }
    }

    /** The number in {@code typed}, which may end in {@code unit}; null if there is none. */
    static Double parse(String typed, String unit) {
        String t = typed.trim();
        if (!unit.isEmpty() && t.endsWith(unit)) {
            t = t.substring(0, t.length() - unit.length()).trim();
        }
        if (t.isEmpty() || !t.matches("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?")) {
            return null;
        }
        return Double.parseDouble(t);
    }

    /** The range in a refusal: " from 2 to 128 px", " of at least 0", or nothing for any number. */
    private String range() {
        String u = unit.isEmpty() ? "" : " " + unit;
        if (min == Double.NEGATIVE_INFINITY && max == Double.POSITIVE_INFINITY) {
            return "";
        }
        if (max == Double.POSITIVE_INFINITY) {
            return " of at least " + plain(min) + u;
        }
        return " from " + plain(min) + " to " + plain(max) + u;
    }

    private static String plain(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
