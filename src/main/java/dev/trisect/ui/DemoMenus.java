package dev.trisect.ui;

import dev.trisect.view.TrisectView;
import dev.trisect.view.ViewAction;
import java.awt.Component;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.event.MenuEvent;
import javax.swing.event.MenuListener;

/**
 * The demo's menu bar: the view's own commands ({@link TrisectView#action}) in File, View, Render and
 * Help, and the demo's ({@link DemoCommands#table}) each in the menu its entry names, after the menu's
 * own items; a Scene menu shows when some entry asks for one. Event thread only.
 */
final class DemoMenus {
    private DemoMenus() {
    }

    static JMenuBar bar(TrisectView view, FileMenu fileMenu, List<DemoCommands.Entry> table) {
        JMenu file = menu("File", KeyEvent.VK_F);
        fileMenu.addTo(file);
        JMenu viewMenu = menu("View", KeyEvent.VK_V);
        viewMenu.add(MenuItems.check(view.action(ViewAction.DEV_TOOLS)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.BORDERS)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.BORDER_COLOUR)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.STAT_OVERLAY)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.AUTO_ORBIT)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.RESET_CAMERA)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.TEXTURE_FILTER)));
        viewMenu.addSeparator();
        viewMenu.add(MenuItems.check(view.action(ViewAction.PIXEL_INSPECTOR)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.COPY_INSPECTION)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.FREEZE)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.STEP)));
        viewMenu.addSeparator();
        radioGroup(view, viewMenu, ViewAction.SHOW_IMAGE, ViewAction.SHOW_DIFFERENCE, ViewAction.SHOW_SPLIT);
        JMenu render = menu("Render", KeyEvent.VK_R);
        radioGroup(view, render, ViewAction.PERSPECTIVE, ViewAction.AFFINE, ViewAction.TESSELLATED, ViewAction.SPANS);
        render.addSeparator();
        render.add(MenuItems.item(view.action(ViewAction.SPLIT_POLICY)));
        JMenu scene = menu("Scene", KeyEvent.VK_S);
        JMenu help = menu("Help", KeyEvent.VK_H);
        List<JMenu> menus = List.of(file, viewMenu, render, scene, help);
        // The demo's commands after each menu's own: one separator before the group (File's before each).
        for (DemoCommands.Menu place : DemoCommands.Menu.values()) {
            JMenu m = menus.get(place.ordinal());
            boolean first = true;
            for (DemoCommands.Entry e : table) {
                if (e.menu() == place) {
                    if (m.getMenuComponentCount() > 0 && (first || place == DemoCommands.Menu.FILE)) {
                        m.addSeparator();
                    }
                    first = false;
                    m.add(e.check() ? MenuItems.check(e.action()) : MenuItems.item(e.action()));
                }
            }
        }
        JMenuBar bar = new JMenuBar();
        List<JMenu> shown = new ArrayList<>();
        for (JMenu m : menus) {
            if (m.getMenuComponentCount() > 0) {
                bar.add(m);
                shown.add(m);
                // A check whose state lives elsewhere (the fog, which the developer tools set too) shows it.
                m.addMenuListener(new MenuListener() {
                    @Override
                    public void menuSelected(MenuEvent e) {
                        DemoCommands.showStates(table);
                    }

                    @Override
                    public void menuDeselected(MenuEvent e) {
                    }

                    @Override
                    public void menuCanceled(MenuEvent e) {
                    }
                });
            }
        }
        for (JMenu m : shown) {
            for (Component item : m.getMenuComponents()) {
                if (item instanceof JMenuItem i && i.getToolTipText() != null) {
                    i.setToolTipText(wrapped(i.getToolTipText()));
                }
            }
        }
        return bar;
    }

    private static JMenu menu(String name, int mnemonic) {
        JMenu m = new JMenu(name);
        m.setMnemonic(mnemonic);
        return m;
    }

    /** A tooltip in lines of at most 64 characters, so that none runs across the screen. */
    static String wrapped(String tip) {
        StringBuilder out = new StringBuilder("<html>");
        int line = 0;
        for (String word : tip.replace("&", "&amp;").replace("<", "&lt;").split(" ")) {
            boolean breakHere = line > 0 && line + 1 + word.length() > 64;
            out.append(breakHere ? "<br>" : line > 0 ? " " : "").append(word);
            line = (breakHere || line == 0 ? 0 : line + 1) + word.length();
        }
        return out.append("</html>").toString();
    }

    private static void radioGroup(TrisectView view, JMenu menu, ViewAction... actions) {
        ButtonGroup group = new ButtonGroup();
        for (ViewAction a : actions) {
            JRadioButtonMenuItem item = MenuItems.radio(view.action(a));
            group.add(item);
            menu.add(item);
        }
    }
}
