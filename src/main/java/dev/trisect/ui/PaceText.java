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
     * How long without a new frame before the status bar says the view idles, nanoseconds; at least three
     * times the last frame's time, so that frames slower than this (a loaded machine) are not "idle".
     */
    static final long IDLE_NANOS = 700_000_000L;

    /**
     * The right side of the status bar: how frames are drawn, then "FROZEN at frame n", the frame rate,
     * or — where there is no rate to show — the last frame's time, then the frame's size. A view that
     * draws only when something changes has no rate while it idles: it said "0 fps" there.
     *
     * @param latest   the newest frame drawn, or null before the first
     * @param sinceNanos nanoseconds since {@code latest} came
     * @param targetMs the frame-time target, 0 when off
     */
    static String pace(RenderSettings user, FrameInfo latest, long sinceNanos, double targetMs, boolean frozen) {
        String path = howDrawn(user, latest == null ? null : latest.settings(), targetMs);
        if (latest == null) {
            return path;
        }
        String size = latest.width() + "x" + latest.height();
        String rate;
        if (frozen) {
            rate = "FROZEN at frame " + latest.number();
        } else if (sinceNanos >= Math.max(IDLE_NANOS, 3e6 * latest.frameMillis())) {
            // No frame for a while, and longer than slow frames take to come: nothing is being drawn.
            rate = String.format(Locale.ROOT, "idle, last frame %.1f ms", latest.frameMillis());
        } else if (latest.framesPerSecond() <= 0) {
            // Frames are coming, but not yet for a whole second: their time, not a rate of 0.
            rate = String.format(Locale.ROOT, "%.1f ms a frame", latest.frameMillis());
        } else {
            rate = fps(latest.framesPerSecond());
        }
        return path + "  " + rate + "  " + size;
    }

    /**
     * {@code pace} ({@link #pace}) as it fits {@code room} pixels, each text's width given by {@code width}:
     * whole, else without how frames are drawn (the menus and the tools show that too), so that the rate
     * and the size stay in sight; a narrow window cut the whole text at its start ("ed, edge 32 px...").
     */
    static String fit(String pace, java.util.function.ToIntFunction<String> width, int room) {
        int cut = pace.indexOf("  ");
        return width.applyAsInt(pace) <= room || cut < 0 ? pace : pace.substring(cut + 2);
    }

    /** A frame rate, "60 fps", in tenths under 10: a loaded machine's 0.4 fps read "0 fps" while frames came. */
    static String fps(double fps) {
        return String.format(Locale.ROOT, fps < 9.95 ? "%.1f fps" : "%.0f fps", fps);
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
