package dev.trisect.ui;

import javax.swing.JLabel;

/**
 * The status bar's message. A resting hint stays; a passing message (a screenshot saved, a command
 * copied) shows for {@link #PASSING_NANOS} and then gives way to the hint again, so nothing stale
 * lingers. A message too long for the bar is cut with an ellipsis by the label and shown whole in
 * its tooltip. Event thread only.
 */
final class StatusLine {
    /** How long a passing message stays, nanoseconds. */
    static final long PASSING_NANOS = 8_000_000_000L;

    private final JLabel label;
    private String resting = " ";
    private long clearAt = Long.MAX_VALUE;

    StatusLine(JLabel label) {
        this.label = label;
    }

    /** Sets the message that shows when nothing else does, and shows it now. */
    void rest(String message) {
        resting = message;
        show(message);
        clearAt = Long.MAX_VALUE;
    }

    /** Shows a message that clears itself after a while ({@code now} from {@link System#nanoTime}). */
    void pass(String message, long now) {
        show(message);
        clearAt = now + PASSING_NANOS;
    }

    /** Clears a passing message once its time is up; call a few times a second. */
    void tick(long now) {
        if (now - clearAt >= 0) {
            show(resting);
            clearAt = Long.MAX_VALUE;
        }
    }

    /** Gives way to the resting hint now if a passing message starting with {@code prefix} shows. */
    void withdraw(String prefix) {
        if (clearAt != Long.MAX_VALUE && label.getText().startsWith(prefix)) {
            show(resting);
            clearAt = Long.MAX_VALUE;
        }
    }

    String text() {
        return label.getText();
    }

    private void show(String message) {
        label.setText(message);
        label.setToolTipText(message.isBlank() ? null : message);
    }
}
