package dev.trisect.ui;

import java.awt.Window;
import javax.swing.JDialog;
import javax.swing.JEditorPane;
import javax.swing.JScrollPane;
import javax.swing.WindowConstants;

/**
 * Every key and mouse gesture of the demo, in one table: the F1 help panel shows it, and docs/demo.md's
 * "Moving around" table is this table in Markdown ({@link #markdown}; {@code DemoHelpTest} fails when the
 * two differ and prints the table to paste). Event thread only for the panel.
 */
final class DemoHelp {
    /** {input, what it does}, in the order shown. */
    static final String[][] ROWS = {
        {"W A S D or the arrow keys", "move forward, left, back, right"},
        {"E / Page Up, Q / Page Down", "move up, down"},
        {"Shift (held)", "move five times faster"},
        {"drag with the mouse", "look around"},
        {"mouse wheel", "move down (toward you) or up (away)"},
        {"R", "put the camera back where the scene starts"},
        {"F", "next texture filter: nearest, bilinear, trilinear (the demo opens with trilinear)"},
        {"O", "auto-orbit: circle slowly round the point ahead, so warping can be watched hands-free; any movement "
            + "stops it"},
        {"B", "polygon borders on/off"},
        {"U", "statistics overlay on/off: frames per second, the frame's milliseconds by stage (geometry, "
            + "tessellation, fill, overlay), pieces and fallback pieces, path, policy, threshold and filter"},
        {"M", "uncapped frame rate on/off: frames drawn continuously with no cap, so the status bar's fps is the "
            + "rate the view can reach (otherwise a still scene draws no frames and the bar says \"idle\")"},
        {"C", "next border colouring: yellow, by split depth, by error bound (turns the borders on)"},
        {"I", "pixel inspector on/off: it follows the mouse; a click (without dragging) pins it to a pixel, another "
            + "click frees it"},
        {"Shift+click (inspector on)", "pin that pixel to a list of up to four whose readouts update every frame; "
            + "Shift+click it again to unpin it"},
        {"Ctrl+C", "copy the pixel inspector's readout as text"},
        {"Space", "freeze: stop on this frame (camera and comparison); settings still apply to the frozen frame"},
        {". (period)", "step: draw the next frame, 1/60 s on, and stay frozen"},
        {"F5 / F6 / F7", "view: Image / Difference (heat map) / Split; F6 and F7 open the developer tools"},
        {"1 / 2 / 3 / 4", "texturing path: perspective, affine, tessellated, spans"},
        {"P", "split policy: Edge or Error (Render menu: Split policy: …); the status bar says which"},
        {"L", "lighting: off, flat, smooth (a lamp from the camera, a warm light circling the scene, a dim ambient), on from the lighting shown"},
        {"G", "fog on/off: linear, towards the sky's colour; off whatever fog shows (the developer tools' too)"},
        {"X", "labels on the scene's things, an axes gizmo at the origin and a glass pane on/off (off at start, so "
            + "that the frame is the command line's)"},
        {"Z", "wireframe: filled, filled with the edges over it, wire alone"},
        {"H", "frame-rate HUD on/off: frames per second and milliseconds a frame, drawn by the engine in the "
            + "frame's bottom-left corner"},
        {"F12", "developer tools"},
        {"F1", "this table of keys and mouse gestures, in a panel"},
        {"Ctrl+O", "open an OBJ model"},
        {"Ctrl+S", "save the frame on screen as a PNG"},
        {"Ctrl+Q, Ctrl+W, Escape", "exit"}};

    private DemoHelp() {
    }

    /** The table as docs/demo.md shows it. */
    static String markdown() {
        StringBuilder b = new StringBuilder("| input | does |\n|---|---|\n");
        for (String[] r : ROWS) {
            b.append("| ").append(r[0]).append(" | ").append(r[1]).append(" |\n");
        }
        return b.toString();
    }

    /** The table as the help panel shows it. */
    static String html() {
        StringBuilder b = new StringBuilder("<html><body style='font-family:sans-serif'><table cellpadding='3'>");
        for (String[] r : ROWS) {
            b.append("<tr><td valign='top'><b>").append(escape(r[0])).append("</b></td><td>").append(escape(r[1]))
                    .append("</td></tr>");
        }
        return b.append("</table></body></html>").toString();
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** The help panel: a window beside {@code owner} holding the table; it does not take the view's keys away. */
    static JDialog panel(Window owner) {
        JDialog d = new JDialog(owner, "Trisect \u2014 keys and mouse (F1)");
        d.setDefaultCloseOperation(WindowConstants.HIDE_ON_CLOSE);
        JEditorPane text = new JEditorPane("text/html", html());
        text.setEditable(false);
        text.setFocusable(false);
        text.setCaretPosition(0);
        d.add(new JScrollPane(text));
        d.setFocusableWindowState(false);
        d.setSize(640, 560);
        return d;
    }
}
