package dev.trisect.ui;

import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.MouseEvent;
import javax.swing.Action;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JToolTip;

/**
 * The demo's menu items, whose tooltips open beside the item — right of the menu, or left of it where
 * the screen has no room on the right — and never below the mouse, where Swing puts them by default:
 * there a tooltip covered the next item and took its click (Built-in scene's tip over Floor). Submenus
 * ({@code JMenu}) carry no tooltip, since their own items open where it would show. Event thread only.
 */
final class MenuItems {
    /** Gap between an item and its tooltip, pixels. */
    static final int GAP = 4;

    private MenuItems() {
    }

    static JMenuItem item(Action a) {
        return new JMenuItem(a) {
            private static final long serialVersionUID = 1L;

            @Override
            public Point getToolTipLocation(MouseEvent e) {
                return beside(this);
            }
        };
    }

    static JCheckBoxMenuItem check(Action a) {
        return new JCheckBoxMenuItem(a) {
            private static final long serialVersionUID = 1L;

            @Override
            public Point getToolTipLocation(MouseEvent e) {
                return beside(this);
            }
        };
    }

    static JRadioButtonMenuItem radio(Action a) {
        return new JRadioButtonMenuItem(a) {
            private static final long serialVersionUID = 1L;

            @Override
            public Point getToolTipLocation(MouseEvent e) {
                return beside(this);
            }
        };
    }

    /**
     * Where {@code item}'s tooltip goes, in its own coordinates: level with its top, just right of it,
     * or just left of it when the right would run off its screen (Swing would then push the tip back
     * over the menu).
     */
    static Point beside(JComponent item) {
        Dimension tip = tipSize(item);
        Point right = new Point(item.getWidth() + GAP, 0);
        if (!item.isShowing()) {
            return right;
        }
        GraphicsConfiguration gc = item.getGraphicsConfiguration();
        Rectangle screen = gc == null ? null : gc.getBounds();
        int x = item.getLocationOnScreen().x;
        if (screen != null && x + item.getWidth() + GAP + tip.width > screen.x + screen.width) {
            return new Point(-GAP - tip.width, 0);
        }
        return right;
    }

    /** The size of {@code item}'s tooltip as Swing will show it. */
    static Dimension tipSize(JComponent item) {
        JToolTip tip = item.createToolTip();
        tip.setTipText(item.getToolTipText());
        return tip.getPreferredSize();
    }
}
