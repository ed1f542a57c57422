package dev.trisect.view;

/**
 * The commands a {@link TrisectView} offers, each a Swing {@code Action} with its name, tooltip, key
 * and (for the on/off ones) its state in {@code Action.SELECTED_KEY}, from
 * {@link TrisectView#action}. Put them in menus and tool bars: the menu item, the key and the
 * developer tools' control are one command and always agree. The keys work while the view has the
 * keyboard (a click in the view gives it).
 */
public enum ViewAction {
    /** F12: show or hide the developer tools window. */
    DEV_TOOLS("dev-tools"),
    /** B: outline every piece filled (the polygon borders). */
    BORDERS("borders"),
    /** C: the next outline colouring (yellow, by split depth, by error bound); turns the borders on. */
    BORDER_COLOUR("border-colour"),
    /** F: the next texture filter (nearest, bilinear, trilinear). */
    TEXTURE_FILTER("filter"),
    /** 1: the per-pixel perspective path. */
    PERSPECTIVE("perspective"),
    /** 2: the affine path. */
    AFFINE("affine"),
    /** 3: the tessellated path. */
    TESSELLATED("tessellated"),
    /** 4: the span path (exact knots along each row, affine between them, within Max error). */
    SPANS("spans"),
    /** P: switch the tessellated path's split policy between edge and error. */
    SPLIT_POLICY("split-policy"),
    /** O: circle the camera slowly round the point ahead; any movement stops it. */
    AUTO_ORBIT("auto-orbit"),
    /** R: put the camera back where it was last set. */
    RESET_CAMERA("reset-camera"),
    /** I: the pixel inspector (follows the mouse; a click pins it). */
    PIXEL_INSPECTOR("inspector"),
    /** Space: freeze on this frame. */
    FREEZE("freeze"),
    /** Period: draw one more frame, 1/60 s on, and stay frozen. */
    STEP("step"),
    /** F5: show the image. */
    SHOW_IMAGE("view-image"),
    /** F6: show the displacement against the per-pixel path as a heat map (opens the developer tools). */
    SHOW_DIFFERENCE("view-difference"),
    /** F7: this path left of a divider, the per-pixel path right of it (opens the developer tools). */
    SHOW_SPLIT("view-split"),
    /** Ctrl+C: copy the pixel inspector's readout to the clipboard as text. */
    COPY_INSPECTION("copy-inspection"),
    /**
     * U: the statistics overlay over the view: frames per second, the frame's milliseconds by stage,
     * pieces, and the path, split policy, threshold and texture filter.
     */
    STAT_OVERLAY("stat-overlay");

    final String id;

    ViewAction(String id) {
        this.id = id;
    }
}
