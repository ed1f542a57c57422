package dev.trisect.ui;

import javax.swing.JLabel;

/**
 * The status bar's message. A resting hint stays; a standing warning (a cap reached, over budget)
 * takes the hint's place for as long as the frames on screen earn it; a passing message (a
 * screenshot saved, a command copied) shows for {@link #PASSING_NANOS} over either and then gives
 * way to the warning, or the hint when there is none, so nothing stale lingers. The warning is kept
 * apart from passing messages because the frames repeat it several times a second: were it shown
 * as a message, each repeat would cover the one message the user is waiting for. A message too long
 * for the bar is cut with an ellipsis by the label and shown whole in its tooltip. Event thread only.
 */
final class StatusLine {
    /** How long a passing message stays, nanoseconds. */
    static final long PASSING_NANOS = 8_000_000_000L;

    private final JLabel label;
    private String resting = " ";
    /** The standing warning, or null when the frame on screen has none. */
    private String warning;
    private long clearAt = Long.MAX_VALUE;

    StatusLine(JLabel label) {
        this.label = label;
    }

    /** Sets the message that shows when nothing else does, and shows it now unless a warning stands. */
    void rest(String message) {
        resting = message;
        show(standing());
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
            show(standing());
            clearAt = Long.MAX_VALUE;
        }
    }

    /**
     * Sets the standing warning, or clears it with null; call with each frame's warning. It shows at
     * once unless a passing message is showing, which keeps its time and then gives way to it.
     */
    void warn(String message) {
        warning = message;
        if (clearAt == Long.MAX_VALUE) {
            show(standing());
        }
    }

    /** What shows when no passing message does. */
    private String standing() {
        return warning != null ? warning : resting;
    }

    String text() {
        return label.getText();
    }

    private void show(String message) {
        label.setText(message);
        label.setToolTipText(message.isBlank() ? null : message);
    }
}
