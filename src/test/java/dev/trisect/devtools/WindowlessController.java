package dev.trisect.devtools;

import dev.trisect.content.DemoScenes;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;

/** A view controller of the boxes scene with no window behind it, for the tools' tests (event thread). */
final class WindowlessController {
    private WindowlessController() {
    }

    /** The controller: its surface repaints, inspects and shows nothing; one rendering thread. */
    static ViewController boxes() {
        return new ViewController(new ViewState(DemoScenes.boxes()), new ViewController.Surface() {
            @Override
            public void repaint() {
            }

            @Override
            public void inspector(boolean on) {
            }

            @Override
            public void showDevTools(boolean on) {
            }
        }, 1);
    }
}
