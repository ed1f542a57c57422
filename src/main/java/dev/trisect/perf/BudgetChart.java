package dev.trisect.perf;

import dev.trisect.io.ImageFiles;
import dev.trisect.io.OutputBatch;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws a {@link BudgetRun.Trace} as a PNG with XChart: frame time and the target on the left axis,
 * the threshold the controller chose (and its ceiling) on the right, against the frame number.
 */
public final class BudgetChart {
    private BudgetChart() {
    }

    /** Writes the chart as part of {@code batch}: the file appears when the batch is committed. */
    public static void write(OutputBatch batch, BudgetRun.Trace trace, String title, Path out) {
        int n = trace.ms().length;
        double[] frame = new double[n];
        double[] target = new double[n];
        double[] ceiling = new double[n];
        for (int i = 0; i < n; i++) {
            frame[i] = i;
            target[i] = trace.targetMs();
            ceiling[i] = trace.ceiling();
        }
        String unit = trace.policy().id();
        XYChart chart = new XYChartBuilder().width(960).height(480).title(title).xAxisTitle("frame")
                .yAxisTitle("frame time (ms)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setChartBackgroundColor(Color.WHITE);
        chart.getStyler().setMarkerSize(0);
        chart.getStyler().setYAxisMin(0, 0.0);
        chart.getStyler().setYAxisMin(1, 0.0);
        chart.getStyler().setYAxisGroupPosition(1, Styler.YAxisPosition.Right);
        chart.setYAxisGroupTitle(1, "max " + unit + " threshold (px)");
        line(chart.addSeries("frame ms", frame, trace.ms()), new Color(0x1f77b4), SeriesLines.SOLID, 0);
        line(chart.addSeries("target ms", frame, target), new Color(0x1f77b4), SeriesLines.DASH_DASH, 0);
        line(chart.addSeries("threshold px", frame, trace.thresholds()), new Color(0xd62728), SeriesLines.SOLID, 1);
        line(chart.addSeries("ceiling px", frame, ceiling), new Color(0xd62728), SeriesLines.DASH_DASH, 1);
        BufferedImage image = BitmapEncoder.getBufferedImage(chart);
        ImageFiles.write(batch, out, image.getWidth(), image.getHeight(),
                image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth()));
    }

    private static void line(XYSeries s, Color colour, java.awt.BasicStroke style, int group) {
        s.setMarker(SeriesMarkers.NONE);
        s.setLineColor(colour);
        s.setLineStyle(style);
        s.setYAxisGroup(group);
    }
}
