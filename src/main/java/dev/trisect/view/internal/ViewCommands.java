package dev.trisect.view.internal;

import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.texture.TextureFilter;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.KeyStroke;

/**
 * A view's commands, each one {@link Command} that its key, the host's menu item and the developer
 * tools' control share, so they always agree. Built and used on the event thread.
 */
public final class ViewCommands {
    public final Command devTools;
    public final Command borders;
    public final Command borderColour;
    /** Steps the texture filter: nearest, bilinear, trilinear, nearest... Named after the current one. */
    public final Command filter;
    public final Command orbit;
    public final Command reset;
    public final Command inspector;
    public final Command freeze;
    public final Command step;
    public final Command splitPolicy;
    public final Command copyInspection;
    /** The in-view statistics overlay (U). */
    public final Command statOverlay;
    /** Perspective, affine, tessellated, spans, by {@link RenderMode} ordinal. */
    public final List<Command> modes;
    /** Image, Difference, Split: what the view shows, by {@link ViewKind} ordinal. */
    public final List<Command> views;
    private final Map<String, Command> byId = new LinkedHashMap<>();
    private final ViewState state;

    ViewCommands(ViewController c) {
        state = c.state();
        devTools = add("dev-tools", Command.toggle("Developer tools", "Show or hide the developer tools window",
                key(KeyEvent.VK_F12), cmd -> c.showDevTools(cmd.selected())));
        borders = add("borders", Command.toggle("Polygon borders", "Outline every piece filled in yellow",
                key(KeyEvent.VK_B), cmd -> c.update(s -> s.withRender(s.render().withBorders(cmd.selected())))));
        borderColour = add("border-colour", Command.action("Border colour", "Next outline colouring: yellow; by "
                + "split depth; by error bound (fallback pieces magenta in each)", key(KeyEvent.VK_C), () -> {
                    BorderStyle.Colouring[] all = BorderStyle.Colouring.values();
                    BorderStyle now = state.settings().render().borderStyle();
                    c.selectBorderStyle(new BorderStyle(all[(now.colouring().ordinal() + 1) % all.length], now.fade()));
                }));
        filter = add("filter", Command.action("Texture filter", "Next texture filter: nearest, bilinear, trilinear "
                + "(OpenGL's GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR)", key(KeyEvent.VK_F), () -> {
                    TextureFilter[] all = TextureFilter.values();
                    c.selectFilter(all[(state.settings().render().filter().ordinal() + 1) % all.length]);
                }));
        orbit = add("auto-orbit", Command.toggle("Auto-orbit", "Circle the camera slowly round the point ahead; any "
                + "movement stops it", key(KeyEvent.VK_O), cmd -> state.input.orbit(cmd.selected())));
        reset = add("reset-camera", Command.action("Reset camera", "Put the camera back where it was set",
                key(KeyEvent.VK_R), () -> {
                    orbit.show(false);
                    state.input.requestReset();
                }));
        inspector = add("inspector", Command.toggle("Pixel inspector", "Show what the pixel under the mouse is made "
                + "of (click to pin it): triangle, piece, split level, depth, texel coordinates in both paths, exact "
                + "displacement, mip level and texel; with a crosshair and a magnifier", key(KeyEvent.VK_I),
                cmd -> c.inspector(cmd.selected())));
        freeze = add("freeze", Command.toggle("Freeze frame", "Stop on this frame: the camera and the comparison hold "
                + "still so it can be inspected; settings still apply to it", key(KeyEvent.VK_SPACE),
                cmd -> state.freeze.freeze(cmd.selected())));
        step = add("step", Command.action("Step one frame", "Draw the next frame, 1/60 s on, and stay frozen",
                key(KeyEvent.VK_PERIOD), () -> {
                    freeze.show(true);
                    state.freeze.step();
                }));
        splitPolicy = add("split-policy", Command.action("Split policy", "Switch the tessellated path's split policy "
                + "between Edge (longest screen edge over Max edge) and Error (affine error bound over Max error)",
                key(KeyEvent.VK_P), () -> {
                    SplitPolicy next = state.settings().render().tessellation().policy() == SplitPolicy.EDGE
                            ? SplitPolicy.ERROR : SplitPolicy.EDGE;
                    c.update(s -> s.withRender(s.render().withTessellation(s.render().tessellation()
                            .withPolicy(next))));
                }));
        copyInspection = add("copy-inspection", Command.action("Copy inspector readout", "Copy the pixel inspector's "
                + "numbers of the inspected pixel to the clipboard as text", KeyStroke.getKeyStroke(KeyEvent.VK_C,
                java.awt.event.InputEvent.CTRL_DOWN_MASK), c::copyInspection));
        statOverlay = add("stat-overlay", Command.toggle("Statistics overlay", "Show over the view: frames per "
                + "second, the frame's milliseconds by stage (geometry, tessellation, fill, overlay), pieces and "
                + "fallback pieces, and the path, policy, threshold and filter", key(KeyEvent.VK_U), cmd -> {
                    state.statOverlay(cmd.selected());
                    // A still view draws (and paints) once more, with or without it.
                    state.demand.request();
                }));
        String[] modeTips = {
            "Per-pixel perspective: u/w, v/w, 1/w interpolated and divided at every pixel (the reference)",
            "Affine: u, v interpolated linearly on screen (fast, visibly warped)",
            "Tessellated: split into small pieces, each filled affinely",
            "Spans: exact texel coordinates at knots along each row, affine between them; the knots spaced so "
                    + "that no pixel is more than Max error from the per-pixel path"};
        List<Command> m = new ArrayList<>();
        for (RenderMode mode : RenderMode.values()) {
            String name = mode.id().substring(0, 1).toUpperCase(Locale.ROOT) + mode.id().substring(1);
            m.add(add(mode.id(), Command.toggle(name, modeTips[mode.ordinal()], key(KeyEvent.VK_1 + mode.ordinal()),
                    cmd -> c.selectMode(mode))));
        }
        modes = Collections.unmodifiableList(m);
        String[][] viewNames = {
            {"Image", "Show this path's image"},
            {"Difference", "Show the displacement against the per-pixel path as a heat map (opens the developer tools)"},
            {"Split", "This path left of a divider, the per-pixel path right of it (opens the developer tools)"}};
        List<Command> v = new ArrayList<>();
        for (ViewKind k : ViewKind.values()) {
            v.add(add("view-" + k.name().toLowerCase(Locale.ROOT), Command.toggle(viewNames[k.ordinal()][0],
                    viewNames[k.ordinal()][1], key(KeyEvent.VK_F5 + k.ordinal()), cmd -> c.selectView(k))));
        }
        views = Collections.unmodifiableList(v);
    }

    private static KeyStroke key(int code) {
        return KeyStroke.getKeyStroke(code, 0);
    }

    private Command add(String id, Command c) {
        byId.put(id, c);
        return c;
    }

    /** The command of this id ({@code "borders"}, {@code "view-split"}, ...), or null. */
    public Command byId(String id) {
        return byId.get(id);
    }

    /** Binds every command's key to it in these maps (a view's, or the developer tools' around their controls). */
    public void bind(InputMap keys, ActionMap actions) {
        for (Map.Entry<String, Command> e : byId.entrySet()) {
            keys.put(e.getValue().key(), e.getKey());
            actions.put(e.getKey(), e.getValue());
        }
    }

    /** Every command, in the order they were made. */
    public List<Command> all() {
        return List.copyOf(byId.values());
    }

    /** Shows the settings in force in every command's state and name (after anything changed them). */
    void sync(ViewSettings s) {
        RenderSettings r = s.render();
        for (Command c : modes) {
            c.show(c == modes.get(r.mode().ordinal()));
        }
        for (Command c : views) {
            c.show(c == views.get(s.view().ordinal()));
        }
        borders.show(r.borders());
        // Moving by hand or a camera set by the program ends the auto-orbit.
        orbit.show(state.input.orbit());
        filter.putValue(Action.NAME, "Texture filter: " + r.filter().id());
        borderColour.putValue(Action.NAME, "Border colour: " + r.borderStyle().colouring().id());
        splitPolicy.putValue(Action.NAME, "Split policy: " + r.tessellation().policy().id());
    }
}
