package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Lines;
import dev.trisect.raster.Commands;
import dev.trisect.raster.LineSetup;
import dev.trisect.raster.Segments;

/**
 * The lines' geometry, before the fill: every segment of the frame's line draws to clip space by its
 * draw's model-view-projection, clipped there against the near and far planes (a segment crossing the
 * near plane is cut, never dropped) and a guard band {@link ChunkGeometry#GUARD_PIXELS} beyond the
 * screen's sides, projected, set up once ({@link LineSetup}) and listed as a {@link Commands#LINE}
 * command, in draw and segment order; the list is binned into the fill's bands, where each band draws
 * its lines after its triangles ({@link BandPass}), so the image does not depend on the thread count.
 */
final class LineGeometry {
    /**
     * What the lines' geometry did.
     *
     * @param segments segments set up (after clipping; those that may light a pixel)
     * @param nanos    wall time of it
     */
    record Result(long segments, long nanos) {
        static final Result NONE = new Result(0, 0);
    }

    private final Segments segments = new Segments();
    private final LineSetup setup = new LineSetup();
    /** The frame's lines as commands: what the fill draws after each band's triangles. */
    private final Commands commands = new Commands().segments(segments);
    private double[] clip = new double[0];
    /** The segment being clipped: x, y, z, w of each end. */
    private final double[] ends = new double[8];
    /** Per segment set up: its line draw and its index in that draw's lines. */
    private int[] origins = new int[64];

    /** The lines of the frame last set up, binned into the fill's bands. */
    Commands commands() {
        return commands;
    }

    /** Sets up and bins the lines of {@code draws} for a frame of {@code width x height} pixels. */
    Result setUp(Draws draws, int width, int height) {
        commands.clear();
        segments.begin(width, height);
        if (draws.lineDrawCount() == 0) {
            commands.bin(height, FrameRenderer.BAND_ROWS);
            return Result.NONE;
        }
        long start = System.nanoTime();
        Viewport viewport = new Viewport(width, height);
        double gx = 1 + 2.0 * ChunkGeometry.GUARD_PIXELS / width;
        double gy = 1 + 2.0 * ChunkGeometry.GUARD_PIXELS / height;
        for (int d = 0; d < draws.lineDrawCount(); d++) {
            Lines lines = draws.lines(d);
            transform(lines, draws.lineTransform(d));
            int[] ends = lines.segments();
            int[] colours = lines.colours();
            int lineWidth = draws.lineWidth(d);
            double nearer = 1 + draws.lineNearer(d);
            for (int s = 0; s < colours.length; s++) {
                if (clip(ends[2 * s], ends[2 * s + 1], gx, gy)) {
                    double[] e = this.ends;
                    int ref = segments.count();
                    if (setup.add(segments, viewport.screenX(e[0], e[3]), viewport.screenY(e[1], e[3]),
                            nearer / e[3], viewport.screenX(e[4], e[7]), viewport.screenY(e[5], e[7]),
                            nearer / e[7], lineWidth, colours[s])) {
                        commands.add(Commands.LINE, ref, segments.firstRow(ref), segments.lastRow(ref) + 1);
                        if (2 * ref + 2 > origins.length) {
                            origins = java.util.Arrays.copyOf(origins, 2 * origins.length);
                        }
                        origins[2 * ref] = d;
                        origins[2 * ref + 1] = s;
                    }
                }
            }
        }
        commands.bin(height, FrameRenderer.BAND_ROWS);
        return new Result(segments.count(), System.nanoTime() - start);
    }

    /**
     * Where segment {@code ref} of the frame last set up came from.
     *
     * @return {line draw index (as {@link Draws#lines(int)}), segment index in that draw's lines}
     */
    int[] origin(int ref) {
        return new int[] {origins[2 * ref], origins[2 * ref + 1]};
    }

    private void transform(Lines lines, Mat4 mvp) {
        float[] p = lines.points();
        int n = lines.pointCount();
        if (clip.length < 4 * n) {
            clip = new double[4 * n];
        }
        for (int i = 0; i < n; i++) {
            mvp.transformPoint(p[3 * i], p[3 * i + 1], p[3 * i + 2], clip, 4 * i);
        }
    }

    /**
     * Copies the ends of the segment between points a and b into {@link #ends}, clipped to the near and
     * far planes and the guard band.
     *
     * @return false when nothing of it is left, or its ends are not finite
     */
    private boolean clip(int a, int b, double gx, double gy) {
        double[] e = ends;
        System.arraycopy(clip, 4 * a, e, 0, 4);
        System.arraycopy(clip, 4 * b, e, 4, 4);
        for (double v : e) {
            if (!Double.isFinite(v)) {
                return false;
            }
        }
        // Each plane as a distance that is >= 0 inside: z + w (near), w - z (far), then the guard band.
        for (int plane = 0; plane < 6; plane++) {
            double d0 = distance(plane, e, 0, gx, gy);
            double d1 = distance(plane, e, 4, gx, gy);
            if (d0 < 0 && d1 < 0) {
                return false;
            }
            if (d0 < 0) {
                cut(e, 0, d0 / (d0 - d1));
            } else if (d1 < 0) {
                cut(e, 4, d1 / (d1 - d0));
            }
        }
        return e[3] > 0 && e[7] > 0;
    }

    private static double distance(int plane, double[] e, int at, double gx, double gy) {
        double x = e[at];
        double y = e[at + 1];
        double z = e[at + 2];
        double w = e[at + 3];
        return switch (plane) {
            case 0 -> z + w;
            case 1 -> w - z;
            case 2 -> gx * w - x;
            case 3 -> gx * w + x;
            case 4 -> gy * w - y;
            default -> gy * w + y;
        };
    }

    /** Moves the end at {@code at} the fraction t of the way to the other end. */
    private static void cut(double[] e, int at, double t) {
        int other = 4 - at;
        for (int k = 0; k < 4; k++) {
            e[at + k] += t * (e[other + k] - e[at + k]);
        }
    }
}
