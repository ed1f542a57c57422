package dev.trisect.view;

import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import java.awt.BorderLayout;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

/**
 * A window holding one {@link TrisectView}, for the quick case:
 *
 * <pre>{@code
 * ViewFrame.open("My scene", scene, Camera.looking(new Vec3(3, 2, 4), Vec3.ZERO));
 * }</pre>
 *
 * <p>It closes (and stops rendering) with its close button; the program ends when its last window
 * closes. F12 opens the developer tools beside it.
 */
public final class ViewFrame extends JFrame {
    private static final long serialVersionUID = 1L;

    private final TrisectView view;

    /** A window titled {@code title} around {@code view}, sized to the view's preferred size. Event thread. */
    public ViewFrame(String title, TrisectView view) {
        super(title);
        this.view = view;
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        getContentPane().add(view, BorderLayout.CENTER);
        pack();
        setLocationByPlatform(true);
    }

    /** The view in this window. */
    public TrisectView view() {
        return view;
    }

    /**
     * Opens a window titled {@code title} showing {@code scene} from {@code camera}, with the fly
     * controls, and returns it. Any thread (it builds the window on the event thread and waits for it).
     */
    public static ViewFrame open(String title, Scene scene, Camera camera) {
        AtomicReference<ViewFrame> frame = new AtomicReference<>();
        Runnable build = () -> {
            TrisectView view = new TrisectView(scene);
            view.setCamera(camera);
            ViewFrame f = new ViewFrame(title, view);
            f.setVisible(true);
            f.view().requestFocusInWindow();
            frame.set(f);
        };
        if (SwingUtilities.isEventDispatchThread()) {
            build.run();
        } else {
            try {
                SwingUtilities.invokeAndWait(build);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while opening the window", e);
            } catch (java.lang.reflect.InvocationTargetException e) {
                Throwable cause = e.getCause();
                if (cause instanceof RuntimeException re) {
                    throw re;
                }
                if (cause instanceof Error err) {
                    throw err;
                }
                throw new IllegalStateException(cause);
            }
        }
        return frame.get();
    }
}
