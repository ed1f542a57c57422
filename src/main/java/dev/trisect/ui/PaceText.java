package dev.trisect.ui;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.view.FrameInfo;
import java.util.Locale;

/**
 * The words of the status bar's right side (how frames are drawn, their rate and size) and of P's
 * message: pure functions of the settings and the newest frame, so that they are tested without a
 * window.
 */
final class PaceText {
    private PaceText() {
    }

    /**
     * The right side of the status bar: how frames are drawn, then "FROZEN at frame n" or the frame
     * rate, then the frame's size.
     *
     * @param latest   the newest frame drawn, or null before the first
     * @param targetMs the frame-time target, 0 when off
     */
    static String pace(RenderSettings user, FrameInfo latest, double targetMs, boolean frozen) {
        String path = howDrawn(user, latest == null ? null : latest.settings(), targetMs);
        String size = latest == null ? "" : latest.width() + "x" + latest.height();
        return frozen
                ? String.format(Locale.ROOT, "%s  FROZEN at frame %d  %s", path, latest == null ? 0 : latest.number(), size)
                : String.format(Locale.ROOT, "%s  %.0f fps  %s", path, latest == null ? 0 : latest.framesPerSecond(), size);
    }

    /**
     * The status bar's name of how frames are drawn: the path, the split policy and its threshold where
     * the path uses them, and the texture filter ("tessellated, edge 32 px, trilinear").
     *
     * @param user     the settings in force
     * @param drawn    those the newest frame was drawn with (the budget may have chosen its threshold), or null
     * @param targetMs the frame-time target, 0 when off
     */
    static String howDrawn(RenderSettings user, RenderSettings drawn, double targetMs) {
        RenderSettings r = drawn != null && drawn.mode() == user.mode()
                && drawn.tessellation().policy() == user.tessellation().policy() ? drawn : user;
        return switch (user.mode()) {
            case TESSELLATED -> "tessellated, " + policy(r.tessellation())
                    + (targetMs > 0 ? " (auto)" : "") + ", " + user.filter().id();
            case SPANS -> "spans, max error " + number(user.knotError()) + " px, " + user.filter().id();
            default -> user.mode().id() + ", " + user.filter().id();
        };
    }

    /** A split policy and its threshold: "edge 32 px", "error 0.5 px". */
    static String policy(TessellationSettings t) {
        return t.policy().id() + " " + number(t.policy().threshold(t)) + " px";
    }

    /** A threshold as the tools show it: whole pixels without decimals, else up to three. */
    private static String number(double v) {
        return v == Math.rint(v) ? Long.toString(Math.round(v))
                : new java.math.BigDecimal(String.format(Locale.ROOT, "%.3f", v)).stripTrailingZeros().toPlainString();
    }

    /**
     * What P (or the Render menu's item) says in the status bar, so that the switch shows without the
     * developer tools: the policy now in force, and the key of the path that uses it when another shows.
     */
    static String policyChanged(RenderSettings r) {
        TessellationSettings t = r.tessellation();
        String what = (t.policy().measuresError() ? "Error (split while an edge's affine error bound is over "
                : "Edge (split while a piece's longest edge is over ") + number(t.policy().threshold(t)) + " px)";
        return "Split policy: " + what + (r.mode() == RenderMode.TESSELLATED ? ""
                : "; the tessellated path (3) uses it");
    }
}
