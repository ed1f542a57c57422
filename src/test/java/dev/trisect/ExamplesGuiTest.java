package dev.trisect;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.examples.ClickPicking;
import dev.trisect.examples.CubeWindow;
import dev.trisect.examples.EmbeddedView;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.render.RenderMode;
import dev.trisect.scene.Camera;
import dev.trisect.scene.SceneObject;
import dev.trisect.view.FrameInfo;
import dev.trisect.view.TrisectView;
import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.awt.Point;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.swing.AbstractButton;
import javax.swing.JCheckBox;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JRadioButton;
import javax.swing.JSlider;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The window examples of src/examples/java, run under an X server and driven as a user would. */
@Tag("gui")
class ExamplesGuiTest {
    private static Robot robot;
    private final List<FrameInfo> frames = new CopyOnWriteArrayList<>();

    @BeforeAll
    static void robot() throws Exception {
        robot = GuiTests.robot("ExamplesGuiTest");
    }

    @BeforeEach
    void display() {
        GuiTests.requireDisplay();
    }

    @AfterEach
    void closeWindows() throws Exception {
        edt(() -> {
            for (Frame f : Frame.getFrames()) {
                f.dispose();
            }
        });
    }

    private static <T extends Component> T find(Container in, Class<T> type, String text) {
        for (Component c : in.getComponents()) {
            if (type.isInstance(c) && (text == null || (c instanceof AbstractButton b && b.getText().startsWith(text)))) {
                return type.cast(c);
            }
            if (c instanceof Container inner) {
                T t = find(inner, type, text);
                if (t != null) {
                    return t;
                }
            }
        }
        return null;
    }

    private static JFrame window(String title) throws Exception {
        JFrame[] found = new JFrame[1];
        waitFor("the window " + title, () -> onEdt(() -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof JFrame f && title.equals(f.getTitle()) && f.isShowing()) {
                    found[0] = f;
                }
            }
            return found[0] != null;
        }));
        return found[0];
    }

    /** The view in {@code frame}, listened to. */
    private TrisectView view(JFrame frame) throws Exception {
        TrisectView view = onEdt(() -> find(frame.getContentPane(), TrisectView.class, null));
        assertNotNull(view);
        view.addFrameListener(frames::add);
        // These tests watch frames flow: keep them coming, as an animation does (a still view idles).
        view.addUpdateListener((step, number) -> true);
        waitFor("frames", () -> frames.size() >= 2);
        return view;
    }

    private FrameInfo frameAfterNow() throws Exception {
        long after = frames.get(frames.size() - 1).number() + 1;
        waitFor("a new frame", () -> frames.get(frames.size() - 1).number() > after);
        return frames.get(frames.size() - 1);
    }

    @Test
    void embeddedViewsControlsChangeThePathTheOverlayAndTheThreshold() throws Exception {
        JFrame frame = onEdt(EmbeddedView::open);
        TrisectView view = view(frame);
        edt(() -> find(frame.getContentPane(), JRadioButton.class, "Affine").doClick());
        assertEquals(RenderMode.AFFINE, frameAfterNow().settings().mode());
        edt(() -> find(frame.getContentPane(), JCheckBox.class, "Polygon borders").doClick());
        assertTrue(frameAfterNow().settings().borders(), "the overlay");
        edt(() -> find(frame.getContentPane(), JSlider.class, null).setValue(8));
        edt(() -> find(frame.getContentPane(), JRadioButton.class, "Tessellated").doClick());
        FrameInfo f = frameAfterNow();
        assertEquals(8, f.settings().tessellation().maxEdge(), 0, "the threshold");
        assertEquals(RenderMode.TESSELLATED, f.settings().mode());
        // The view's keys move the same controls: 2 selects the affine radio button.
        Point at = onEdt(() -> view.getLocationOnScreen());
        robot.mouseMove(at.x + 100, at.y + 100);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the keyboard", () -> onEdt(view::isFocusOwner));
        robot.keyPress(KeyEvent.VK_2);
        robot.keyRelease(KeyEvent.VK_2);
        waitFor("the radio button to follow the key", () -> onEdt(() ->
                find(frame.getContentPane(), JRadioButton.class, "Affine").isSelected()));
        waitFor("the frame rate shown", () -> onEdt(() -> {
            for (Component c : ((Container) frame.getContentPane().getComponent(1)).getComponents()) {
                if (c instanceof JLabel l && l.getText().contains("fps")) {
                    return true;
                }
            }
            return false;
        }));
    }

    @Test
    void cubeWindowShowsTheCrateOnItsGround() throws Exception {
        CubeWindow.main(new String[0]);
        JFrame frame = window("Cube");
        TrisectView view = view(frame);
        frameAfterNow();
        BufferedImage image = onEdt(view::frameImage);
        int crate = image.getRGB(image.getWidth() / 2, image.getHeight() / 2);
        int r = crate >> 16 & 0xFF;
        int g = crate >> 8 & 0xFF;
        int b = crate & 0xFF;
        assertTrue(r > g && g > b && r > 60, "the crate's wood at the centre: " + Integer.toHexString(crate));
        // Escape closes it, as Ctrl+Q and Ctrl+W do (and the demo's window).
        var at = onEdt(view::getLocationOnScreen);
        robot.mouseMove(at.x + 20, at.y + 20);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        GuiTests.waitFor("the keyboard", () -> onEdt(frame::isFocused));
        robot.keyPress(KeyEvent.VK_ESCAPE);
        robot.keyRelease(KeyEvent.VK_ESCAPE);
        GuiTests.waitFor("the window closed by Escape", () -> !onEdt(frame::isDisplayable));
    }

    @Test
    void clickPickingPaintsTheClickedObjectAndNamesIt() throws Exception {
        ClickPicking.main(new String[0]);
        JFrame frame = window("Click picking");
        TrisectView view = view(frame);
        SceneObject crate3 = view.getScene().objects().stream().filter(o -> "crate 3".equals(o.name()))
                .findFirst().orElseThrow();
        // Where crate 3's top face centre (1, 1, 0) is on screen, from the example's camera.
        int w = onEdt(view::getWidth);
        int h = onEdt(view::getHeight);
        Camera c = view.getCamera();
        double[] clip = new double[4];
        c.viewProjection(new Viewport(w, h)).transformPoint(1, 0.95, 0, clip, 0);
        int x = (int) Math.round((clip[0] / clip[3] + 1) / 2 * w);
        int y = (int) Math.round((1 - clip[1] / clip[3]) / 2 * h);
        Point at = onEdt(() -> view.getLocationOnScreen());
        robot.mouseMove(at.x + x, at.y + y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("crate 3 painted", () -> crate3.materials().get(0).rgb().isPresent());
        JLabel status = onEdt(() -> (JLabel) frame.getContentPane().getComponent(1));
        assertTrue(onEdt(status::getText).startsWith("crate 3, triangle "), onEdt(status::getText));
        assertEquals(new Vec3(0, 3, 5.5), c.eye(), "the example's camera, not moved by the click");
        // The pointer rests on crate 3: the frames draw its hover highlight.
        var engine = (dev.trisect.view.internal.ViewController) view.getClientProperty(
                dev.trisect.view.internal.ViewController.class);
        waitFor("crate 3 highlighted under the pointer", () -> engine.state().hovered() == crate3);
    }
}
