package dev.trisect.devtools;

import java.awt.Dimension;
import java.awt.Rectangle;

/**
 * Where the tools window goes, given the view's window: docked to its right where the screen has
 * room, else to its left, else (the view's window fills the screen's width) over the view's right
 * edge, from the view's top to no lower than the view's bottom, so that whatever the window holds
 * below the view — a status bar — stays in sight. The tools window follows each move and resize of
 * the view's window ({@link DevToolsWindow}). All rectangles in screen pixels.
 */
final class DevToolsDock {
    /** The least height the tools window is given, pixels (a scroll bar shows the rest). */
    static final int MIN_HEIGHT = 200;

    private DevToolsDock() {
    }

    /**
     * The tools window's bounds.
     *
     * @param main   the view's window
     * @param view   the view inside it, on screen
     * @param wanted the tools window's size for all its content (a width it needs; the height it would like)
     * @param usable the screen less its panels
     */
    static Rectangle place(Rectangle main, Rectangle view, Dimension wanted, Rectangle usable) {
        int right = usable.x + usable.width;
        int bottom = usable.y + usable.height;
        int w = Math.min(wanted.width, usable.width);
        if (main.x + main.width + w <= right || main.x - w >= usable.x) {
            // Beside: level with the window's top, as tall as it wants and the screen allows.
            int x = main.x + main.width + w <= right ? main.x + main.width : main.x - w;
            int y = Math.max(usable.y, Math.min(main.y, bottom - MIN_HEIGHT));
            return new Rectangle(x, y, w, Math.min(wanted.height, bottom - y));
        }
        // Over the view's right edge, never below the view's bottom (the status bar under it stays clear).
        int y = Math.max(usable.y, view.y);
        int limit = Math.min(bottom, view.y + view.height);
        int x = Math.max(usable.x, Math.min(right, view.x + view.width) - w);
        return new Rectangle(x, y, w, Math.max(0, Math.min(wanted.height, limit - y)));
    }
}
