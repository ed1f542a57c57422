package dev.trisect.ui;

import dev.trisect.content.DemoScenes;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.SwingUtilities;

/**
 * Checks the frame budget as a user sees it: the demo at 1280x720 with the developer tools open, Auto on
 * with each target from 10 to 100 ms in turn, and after 5 s the frames per second the status bar shows
 * against 1000 / target — within 15 %, or the tools' Frame budget section says why not (the controller is
 * held by your threshold, the finest threshold or the piece budget); where 5 s hold fewer frames than
 * one of the controller's windows it waits for its first decision. Prints one row per target and exits
 * 1 if any target is neither met nor explained. A timing check, so not a test: run by
 * {@code scripts/auto-target.sh} (needs a display; on a shared machine expect the rates to move).
 */
public final class AutoTargetCheck {
    private static final double[] TARGETS = {10, 16.7, 25, 40, 60, 100};
    /** Seconds each target is given before the status bar is read. */
    private static final int SETTLE_SECONDS = 5;

    private AutoTargetCheck() {
    }

    public static void main(String[] args) throws Exception {
        int threads = args.length > 0 ? Integer.parseInt(args[0]) : Runtime.getRuntime().availableProcessors();
        DemoWindow window = DemoApp.openForTest(DemoScenes.demo(), threads);
        int failures = 0;
        try {
            SwingUtilities.invokeAndWait(() -> {
                window.frame().setSize(1280, 720 + window.frame().getHeight() - window.view().getHeight());
                window.view().showDevTools(true);
            });
            ViewController c = (ViewController) window.view().getClientProperty(ViewController.class);
            System.out.println("target_ms  wanted_fps  status_fps  off_by  verdict    frame size / why");
            for (double target : TARGETS) {
                SwingUtilities.invokeAndWait(() -> window.view().setFrameTimeTarget(target));
                Thread.sleep(SETTLE_SECONDS * 1000L);
                // On a loaded machine 5 s may hold fewer frames than one window of the controller: wait
                // (up to 30 s more) until it has decided once, and say how long that took.
                for (int wait = 0; wait < 60 && !decided(c.state().budgetChoice()); wait++) {
                    Thread.sleep(500);
                }
                String[] pace = new String[1];
                SwingUtilities.invokeAndWait(() -> pace[0] = window.paceText());
                double fps = fps(pace[0]);
                double wanted = 1000 / target;
                double off = fps / wanted - 1;
                ViewState.BudgetChoice choice = c.state().budgetChoice();
                boolean met = Math.abs(off) <= 0.15;
                boolean explained = choice != null && choice.limit() != dev.trisect.perf.BudgetController.Limit.TARGET;
                String verdict = met ? "met" : explained ? "explained" : "FAILED";
                failures += met || explained ? 0 : 1;
                System.out.printf(Locale.ROOT, "%9.1f  %10.1f  %10.1f  %+5.0f%%  %-9s  %s / %s%n", target, wanted, fps,
                        100 * off, verdict, size(pace[0]), choice == null ? "(no choice)" : choice.why());
            }
        } finally {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
        System.exit(failures == 0 ? 0 : 1);
    }

    private static boolean decided(ViewState.BudgetChoice c) {
        return c != null && !Double.isNaN(c.medianMs());
    }

    /**
     * The frames per second in the status bar's right side ("tessellated, ...  24 fps  1280x720"), or
     * from the frame's time where frames come too slowly for a rate ("... 2131.6 ms a frame ...").
     */
    static double fps(String pace) {
        Matcher m = Pattern.compile("([0-9.]+) fps").matcher(pace);
        if (m.find()) {
            return Double.parseDouble(m.group(1));
        }
        Matcher ms = Pattern.compile("([0-9.]+) ms a frame").matcher(pace);
        return ms.find() ? 1000 / Double.parseDouble(ms.group(1)) : Double.NaN;
    }

    private static String size(String pace) {
        Matcher m = Pattern.compile("(\\d+x\\d+)\\s*$").matcher(pace);
        return m.find() ? m.group(1) : "?";
    }
}
