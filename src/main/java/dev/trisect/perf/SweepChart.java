package dev.trisect.perf;

import dev.trisect.io.ImageFiles;
import dev.trisect.io.OutputBatch;
import dev.trisect.render.SplitPolicy;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws a {@link Sweep.Result} as a PNG with XChart: one panel per split policy, the threshold on the
 * x axis, the tessellated path's median frame time on the left axis against the per-pixel
 * and affine paths as flat reference lines, and the exact displacement (largest and p99) on the right
 * axis; the error panel also has the span path's time and largest displacement at each max error.
 * Where the tessellated line crosses the per-pixel line is the break-even threshold.
 */
public final class SweepChart {
    /** Size of one panel, pixels. */
    static final int PANEL_WIDTH = 720;
    static final int PANEL_HEIGHT = 480;

    private SweepChart() {
    }

    /** Writes the chart as part of {@code batch}: the file appears when the batch is committed. */
    public static void write(OutputBatch batch, Sweep.Result result, String title, Path out) {
        BufferedImage edge = panel(result, SplitPolicy.EDGE, title + " - edge policy", "max edge (px)");
        BufferedImage error = panel(result, SplitPolicy.ERROR, title + " - error policy", "max error (px)");
        int w = edge.getWidth() + error.getWidth();
        int h = Math.max(edge.getHeight(), error.getHeight());
        BufferedImage both = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = both.createGraphics();
        try {
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, w, h);
            g.drawImage(edge, 0, 0, null);
            g.drawImage(error, edge.getWidth(), 0, null);
        } finally {
            g.dispose();
        }
        ImageFiles.write(batch, out, w, h, both.getRGB(0, 0, w, h, null, 0, w));
    }

    /** One policy's panel. */
    static BufferedImage panel(Sweep.Result result, SplitPolicy policy, String title, String xTitle) {
        List<Sweep.Point> points = result.of(policy);
        XYChart chart = new XYChartBuilder().width(PANEL_WIDTH).height(PANEL_HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle("median frame time (ms)").build();
        XYStyler styler = chart.getStyler();
        styler.setLegendPosition(Styler.LegendPosition.OutsideS);
        styler.setChartBackgroundColor(Color.WHITE);
        styler.setYAxisGroupPosition(1, Styler.YAxisPosition.Right);
        chart.setYAxisGroupTitle(1, "displacement (px)");
        if (points.isEmpty()) {
            return BitmapEncoder.getBufferedImage(chart);
        }
        // Linear axes: XChart labels only the decades of a logarithmic one, which a sweep rarely spans.
        styler.setYAxisMin(0, 0.0);
        styler.setYAxisMin(1, 0.0);
        double[] x = new double[points.size()];
        double[] ms = new double[x.length];
        double[] max = new double[x.length];
        double[] p99 = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            Sweep.Point p = points.get(i);
            x[i] = p.threshold();
            ms[i] = p.times().medianMs();
            max[i] = finite(p.maxDisplacement());
            p99[i] = finite(p.p99Displacement());
        }
        double[] ends = {x[0], x[x.length - 1]};
        XYSeries t = chart.addSeries("tessellated ms", x, ms);
        t.setMarker(SeriesMarkers.CIRCLE);
        t.setLineColor(new Color(0x1f77b4));
        t.setMarkerColor(new Color(0x1f77b4));
        reference(chart, String.format(Locale.ROOT, "per-pixel %.2f ms", result.perspective().times().medianMs()),
                ends, result.perspective().times().medianMs(), new Color(0xd62728));
        reference(chart, String.format(Locale.ROOT, "affine %.2f ms", result.affine().times().medianMs()),
                ends, result.affine().times().medianMs(), new Color(0x2ca02c));
        displacement(chart.addSeries("max displacement px", x, max), SeriesMarkers.DIAMOND, new Color(0x9467bd));
        displacement(chart.addSeries("p99 displacement px", x, p99), SeriesMarkers.TRIANGLE_UP,
                new Color(0xff7f0e));
        List<Sweep.Point> spans = policy == SplitPolicy.ERROR ? result.spans() : List.of();
        if (!spans.isEmpty()) {
            double[] sx = new double[spans.size()];
            double[] sms = new double[sx.length];
            double[] smax = new double[sx.length];
            for (int i = 0; i < sx.length; i++) {
                sx[i] = spans.get(i).threshold();
                sms[i] = spans.get(i).times().medianMs();
                smax[i] = finite(spans.get(i).maxDisplacement());
            }
            XYSeries s = chart.addSeries("spans ms", sx, sms);
            s.setMarker(SeriesMarkers.SQUARE);
            s.setLineColor(new Color(0x17becf));
            s.setMarkerColor(new Color(0x17becf));
            displacement(chart.addSeries("spans max displacement px", sx, smax), SeriesMarkers.CROSS,
                    new Color(0x8c564b));
        }
        return BitmapEncoder.getBufferedImage(chart);
    }

    /** A displacement series: right axis, dotted. */
    private static void displacement(XYSeries s, Marker marker, Color colour) {
        s.setYAxisGroup(1);
        s.setMarker(marker);
        s.setLineStyle(SeriesLines.DOT_DOT);
        s.setLineColor(colour);
        s.setMarkerColor(colour);
    }

    private static void reference(XYChart chart, String name, double[] ends, double value, Color colour) {
        XYSeries s = chart.addSeries(name, ends, new double[] {value, value});
        s.setMarker(SeriesMarkers.NONE);
        s.setLineStyle(SeriesLines.DASH_DASH);
        s.setLineColor(colour);
    }

    /** XChart cannot plot NaN; a displacement that could not be measured is drawn at 0. */
    private static double finite(double v) {
        return Double.isFinite(v) ? v : 0;
    }
}
