package dev.trisect.mesh;

import dev.trisect.math.Vec3;
import java.util.Arrays;
import java.util.Objects;

/**
 * Line segments in object space, each with its own colour: what a scene draws as lines (OpenGL's
 * {@code GL_LINES}), an OBJ file's {@code l} elements, a wireframe. Immutable once built: make one with
 * {@link #builder()}.
 *
 * <p>Segments index points, as a mesh's triangles index positions, so a polyline shares its corners.
 * They are drawn in the order they were added, after the triangles of the frame, depth-tested against
 * them (a line on a face shows); docs/conventions.md, "Lines", has the rules of their pixels.
 *
 * <p>The arrays are handed out as they are, without copies, because the frame reads them per segment:
 * callers must not modify them.
 */
public final class Lines {
    /** No segments. */
    public static final Lines EMPTY = new Lines(new float[0], new int[0], new int[0]);

    private final float[] points;
    private final int[] segments;
    private final int[] colours;

    Lines(float[] points, int[] segments, int[] colours) {
        this.points = points;
        this.segments = segments;
        this.colours = colours;
    }

    /**
     * A builder of new lines.
     *
     * @return an empty builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * Number of segments.
     *
     * @return the segment count
     */
    public int segmentCount() {
        return colours.length;
    }

    /**
     * Number of points the segments index.
     *
     * @return the point count
     */
    public int pointCount() {
        return points.length / 3;
    }

    /**
     * The points, object space: x, y, z per point. Not a copy: do not modify.
     *
     * @return the points' coordinates
     */
    public float[] points() {
        return points;
    }

    /**
     * The segments' end points, two point indices per segment, in drawing order. Not a copy: do not
     * modify.
     *
     * @return the ends, {@code 2 * segmentCount()} indices
     */
    public int[] segments() {
        return segments;
    }

    /**
     * The colour of each segment, 0xRRGGBB. Not a copy: do not modify.
     *
     * @return one colour per segment
     */
    public int[] colours() {
        return colours;
    }

    /**
     * Whether there are no segments.
     *
     * @return true for no segments
     */
    public boolean isEmpty() {
        return colours.length == 0;
    }

    /**
     * Appends points, segments and colours to lines; the object handed out by {@link #build} is
     * independent of it. Not thread-safe.
     */
    public static final class Builder {
        private float[] points = new float[3 * 16];
        private int pointCount;
        private int[] segments = new int[2 * 16];
        private int[] colours = new int[16];
        private int segmentCount;

        private Builder() {
        }

        /**
         * Adds a point.
         *
         * @param x object space
         * @param y object space
         * @param z object space
         * @return the point's index
         * @throws IllegalArgumentException when a coordinate is not a finite float (NaN, infinite, or beyond
         *                                  the float range), as {@link MeshBuilder#position(double, double, double)} refuses it
         */
        public int point(double x, double y, double z) {
            if (!(MeshBuilder.isFloat(x) && MeshBuilder.isFloat(y) && MeshBuilder.isFloat(z))) {
                throw MeshBuilder.notFloat("line point", x, y, z);
            }
            if (3 * pointCount + 3 > points.length) {
                points = Arrays.copyOf(points, 2 * points.length);
            }
            points[3 * pointCount] = (float) x;
            points[3 * pointCount + 1] = (float) y;
            points[3 * pointCount + 2] = (float) z;
            return pointCount++;
        }

        /**
         * Adds a point.
         *
         * @param p object space
         * @return the point's index
         * @throws NullPointerException     when {@code p} is null
         * @throws IllegalArgumentException when a coordinate is not a finite float
         */
        public int point(Vec3 p) {
            Objects.requireNonNull(p, "point is null");
            return point(p.x(), p.y(), p.z());
        }

        /**
         * Adds a segment between two points added before.
         *
         * @param a   the index of one end
         * @param b   the index of the other end
         * @param rgb the colour, 0xRRGGBB (higher bits ignored)
         * @return this builder
         * @throws IndexOutOfBoundsException when an index is not a point added
         */
        public Builder segment(int a, int b, int rgb) {
            Objects.checkIndex(a, pointCount);
            Objects.checkIndex(b, pointCount);
            if (segmentCount == colours.length) {
                colours = Arrays.copyOf(colours, 2 * colours.length);
                segments = Arrays.copyOf(segments, 2 * colours.length);
            }
            segments[2 * segmentCount] = a;
            segments[2 * segmentCount + 1] = b;
            colours[segmentCount++] = rgb & 0xFFFFFF;
            return this;
        }

        /**
         * Adds a segment between two new points.
         *
         * @param a   one end, object space
         * @param b   the other end, object space
         * @param rgb the colour, 0xRRGGBB
         * @return this builder
         * @throws NullPointerException     when an end is null
         * @throws IllegalArgumentException when a coordinate is not a finite float
         */
        public Builder segment(Vec3 a, Vec3 b, int rgb) {
            int i = point(a);
            return segment(i, point(b), rgb);
        }

        /**
         * Adds a polyline: a segment between each two consecutive points of {@code corners} (added
         * before), all of one colour.
         *
         * @param rgb     the colour, 0xRRGGBB
         * @param corners point indices, at least two
         * @return this builder
         * @throws NullPointerException      when {@code corners} is null
         * @throws IllegalArgumentException  for fewer than two corners
         * @throws IndexOutOfBoundsException when an index is not a point added
         */
        public Builder polyline(int rgb, int... corners) {
            if (Objects.requireNonNull(corners, "corners is null").length < 2) {
                throw new IllegalArgumentException("a polyline needs at least 2 points, got " + corners.length);
            }
            for (int i = 1; i < corners.length; i++) {
                segment(corners[i - 1], corners[i], rgb);
            }
            return this;
        }

        /**
         * Adds a polyline through new points.
         *
         * @param rgb     the colour, 0xRRGGBB
         * @param corners the points, object space, at least two
         * @return this builder
         * @throws NullPointerException     when {@code corners} or one of them is null
         * @throws IllegalArgumentException for fewer than two corners, or a coordinate that is not a finite float
         */
        public Builder polyline(int rgb, Vec3... corners) {
            if (Objects.requireNonNull(corners, "corners is null").length < 2) {
                throw new IllegalArgumentException("a polyline needs at least 2 points, got " + corners.length);
            }
            int[] at = new int[corners.length];
            for (int i = 0; i < at.length; i++) {
                at[i] = point(corners[i]);
            }
            return polyline(rgb, at);
        }

        /**
         * Segments added so far.
         *
         * @return the count
         */
        public int segmentCount() {
            return segmentCount;
        }

        /**
         * The lines built so far, in trimmed copies.
         *
         * @return the lines
         */
        public Lines build() {
            return new Lines(Arrays.copyOf(points, 3 * pointCount), Arrays.copyOf(segments, 2 * segmentCount),
                    Arrays.copyOf(colours, segmentCount));
        }
    }
}
