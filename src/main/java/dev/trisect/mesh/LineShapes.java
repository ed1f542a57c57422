package dev.trisect.mesh;

import java.util.HashSet;
import java.util.Set;

/**
 * Ready-made {@link Lines}: a mesh's wireframe, axes, a ground grid and a wire box (as Sixth 3D's
 * {@code WireframeCube} and jMonkeyEngine's debug shapes). All in object space, y up.
 */
public final class LineShapes {
    /** The axes' colours: x red, y green, z blue. */
    public static final int X_RED = 0xFF0000;
    /** The y axis's colour. */
    public static final int Y_GREEN = 0x00FF00;
    /** The z axis's colour. */
    public static final int Z_BLUE = 0x0000FF;

    private LineShapes() {
    }

    /**
     * The edges of a mesh's triangles, each edge two triangles share once (as a wireframe draws it),
     * in the order the triangles first meet them; edges joining a position to itself are left out. The
     * segments index the mesh's own positions, so no coordinate is copied.
     *
     * @param mesh the mesh
     * @param rgb  the colour, 0xRRGGBB
     * @return the edges
     */
    public static Lines edges(Mesh mesh, int rgb) {
        int[] corners = mesh.cornerPositions();
        int triangles = mesh.triangleCount();
        int[] segments = new int[6 * triangles];
        int count = 0;
        Set<Long> seen = new HashSet<>(4 * triangles);
        for (int t = 0; t < triangles; t++) {
            for (int k = 0; k < 3; k++) {
                int a = corners[3 * t + k];
                int b = corners[3 * t + (k + 1) % 3];
                if (a != b && seen.add((long) Math.min(a, b) << 32 | Math.max(a, b))) {
                    segments[2 * count] = a;
                    segments[2 * count + 1] = b;
                    count++;
                }
            }
        }
        int[] colours = new int[count];
        java.util.Arrays.fill(colours, rgb & 0xFFFFFF);
        return new Lines(mesh.positions(), java.util.Arrays.copyOf(segments, 2 * count), colours);
    }

    /**
     * The three axes from the origin, {@code length} long: x red, y green, z blue.
     *
     * @param length each axis's length, object units
     * @return three segments
     */
    public static Lines axes(double length) {
        Lines.Builder b = Lines.builder();
        int o = b.point(0, 0, 0);
        b.segment(o, b.point(length, 0, 0), X_RED);
        b.segment(o, b.point(0, length, 0), Y_GREEN);
        b.segment(o, b.point(0, 0, length), Z_BLUE);
        return b.build();
    }

    /**
     * A square grid on the plane y = 0, centred on the origin: {@code cells + 1} lines each way.
     *
     * @param size  the side, object units
     * @param cells cells along each side, at least 1
     * @param rgb   the colour, 0xRRGGBB
     * @return {@code 2 * (cells + 1)} segments
     * @throws IllegalArgumentException when {@code cells} is below 1
     */
    public static Lines grid(double size, int cells, int rgb) {
        if (cells < 1) {
            throw new IllegalArgumentException("a grid needs at least 1 cell, got " + cells);
        }
        Lines.Builder b = Lines.builder();
        double h = size / 2;
        for (int i = 0; i <= cells; i++) {
            double at = -h + size * i / cells;
            b.segment(b.point(at, 0, -h), b.point(at, 0, h), rgb);
            b.segment(b.point(-h, 0, at), b.point(h, 0, at), rgb);
        }
        return b.build();
    }

    /**
     * The 12 edges of a box centred on the origin (as {@link Primitives#box} is).
     *
     * @param sizeX side along x, object units
     * @param sizeY side along y
     * @param sizeZ side along z
     * @param rgb   the colour, 0xRRGGBB
     * @return 12 segments on 8 points
     */
    public static Lines box(double sizeX, double sizeY, double sizeZ, int rgb) {
        Lines.Builder b = Lines.builder();
        int[] p = new int[8];
        for (int i = 0; i < 8; i++) {
            p[i] = b.point((i & 1) == 0 ? -sizeX / 2 : sizeX / 2, (i & 2) == 0 ? -sizeY / 2 : sizeY / 2,
                    (i & 4) == 0 ? -sizeZ / 2 : sizeZ / 2);
        }
        for (int i = 0; i < 8; i++) {
            for (int bit = 1; bit < 8; bit <<= 1) {
                if ((i & bit) == 0) {
                    b.segment(p[i], p[i | bit], rgb);
                }
            }
        }
        return b.build();
    }
}
