package dev.trisect.texture;

import dev.trisect.texture.internal.BitmapFont;
import dev.trisect.texture.internal.Pixels;

/**
 * Textures made from code, for tests and demo scenes: no files, and deterministic (integer arithmetic,
 * {@link StrictMath} where a sine is needed), so the same call gives the same texels on every machine.
 *
 * <p>All sizes are in texels and work for any value in {@code 1..}{@link Texture#MAX_SIDE}, powers of
 * two or not. As everywhere in Trisect, UV (0, 0) is the bottom-left of the image (its last row) and
 * v grows upwards; "column from the left" and "row from the bottom" below are in those terms.
 */
public final class ProceduralTextures {
    /** Cells per side of {@link #uvGrid}. */
    static final int GRID_CELLS = 8;
    /** The UV grid's two cell colours; the cell at UV (0, 0) has the first. */
    static final int GRID_CELL_A = 0xFFE9E4D6;
    static final int GRID_CELL_B = 0xFFB9C9DA;
    /** The UV grid's grid lines. */
    static final int GRID_LINE = 0xFF4A5466;
    /** The UV grid's diagonal u = v (red) and u + v = 1 (blue), and its circle (green). */
    static final int GRID_DIAGONAL = 0xFFD23A2E;
    static final int GRID_ANTI_DIAGONAL = 0xFF2E5BD2;
    static final int GRID_CIRCLE = 0xFF1F9A45;
    /** The UV grid's cell labels; used for nothing else, so tests can find the labels. */
    static final int GRID_LABEL = 0xFF161616;

    private static final int FRAME_WOOD = 0xFF8A5A2E;
    private static final int BRACE_WOOD = 0xFF9A6A38;
    private static final int PLANK_WOOD = 0xFFB98A52;

    private ProceduralTextures() {
    }

    /**
     * The labelled UV grid, meant for floors and walls where affine warping must be obvious: 8x8 cells
     * in two alternating colours with thin grid lines, the two diagonals of the whole image (u = v in red,
     * u + v = 1 in blue) and a green circle of radius 0.375 around its centre, so any bending of straight
     * lines or of the circle stands out. Each cell is labelled with its column letter {@code A-H} from the
     * left and row number {@code 1-8} from the bottom, so {@code A1} sits at UV (0, 0) and {@code H8} at
     * (1, 1); the labels read upright when v points up. Labels are left out when the cells are too small
     * for them (under 16 texels, i.e. a size under 128).
     *
     * @param size width and height in texels
     * @return the texture
     */
    public static Texture uvGrid(int size) {
        Pixels.requireSide("UV grid size", size);
        int[] argb = new int[size * size];
        for (int y = 0; y < size; y++) {
            int row = Pixels.partOf(size - 1 - y, GRID_CELLS, size);
            for (int x = 0; x < size; x++) {
                int column = Pixels.partOf(x, GRID_CELLS, size);
                argb[y * size + x] = gridCellColour(column, row);
            }
        }
        int line = Math.max(1, size / 256);
        for (int k = 0; k <= GRID_CELLS; k++) {
            // Lines are centred on the cell boundaries; the outer ones are halved so tiles join up.
            int start = Pixels.partStart(k, GRID_CELLS, size) - line / 2;
            Pixels.fillRect(argb, size, size, start, 0, start + line, size, GRID_LINE);
            Pixels.fillRect(argb, size, size, 0, size - start - line, size, size - start, GRID_LINE);
        }
        drawGridMarks(argb, size);
        drawGridLabels(argb, size);
        return new Texture("uv-grid-" + size, size, size, argb);
    }

    private static int gridCellColour(int column, int row) {
        return ((column + row) & 1) == 0 ? GRID_CELL_A : GRID_CELL_B;
    }

    /** The diagonals and the circle, tested at each texel's centre in texel units. */
    private static void drawGridMarks(int[] argb, int size) {
        double halfWidth = Math.max(0.75, size / 256.0);
        double centre = size / 2.0;
        double radius = size * 0.375;
        double diagonalLimit = halfWidth * Math.sqrt(2.0); // |s - t| for a perpendicular distance halfWidth
        for (int y = 0; y < size; y++) {
            double t = size - (y + 0.5); // texel coordinate v * H, from the bottom
            for (int x = 0; x < size; x++) {
                double s = x + 0.5;
                double fromCentre = Math.sqrt((s - centre) * (s - centre) + (t - centre) * (t - centre));
                if (Math.abs(fromCentre - radius) < halfWidth) {
                    argb[y * size + x] = GRID_CIRCLE;
                }
                if (Math.abs(s + t - size) < diagonalLimit) {
                    argb[y * size + x] = GRID_ANTI_DIAGONAL;
                }
                if (Math.abs(s - t) < diagonalLimit) {
                    argb[y * size + x] = GRID_DIAGONAL;
                }
            }
        }
    }

    /**
     * Each label sits centred in its cell. A halo of the cell colour one font pixel wide keeps it legible
     * where a line or mark runs under it, while the mark stays visible between the letters.
     */
    private static void drawGridLabels(int[] argb, int size) {
        int cell = size / GRID_CELLS;
        if (cell < 16) {
            return; // no room for a legible label
        }
        int scale = Math.max(1, cell / 20);
        int textWidth = BitmapFont.textWidth("A1", scale);
        int textHeight = BitmapFont.textHeight(scale);
        for (int column = 0; column < GRID_CELLS; column++) {
            int left = Pixels.partStart(column, GRID_CELLS, size);
            int right = Pixels.partStart(column + 1, GRID_CELLS, size);
            for (int row = 0; row < GRID_CELLS; row++) {
                // Rows count from the bottom; convert the cell's extent to image rows (row 0 at the top).
                int top = size - Pixels.partStart(row + 1, GRID_CELLS, size);
                int bottom = size - Pixels.partStart(row, GRID_CELLS, size);
                int x = (left + right - textWidth) / 2;
                int y = (top + bottom - textHeight) / 2;
                String label = "" + (char) ('A' + column) + (row + 1);
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) {
                        BitmapFont.drawText(argb, size, size, x + dx * scale, y + dy * scale, label, scale,
                                gridCellColour(column, row));
                    }
                }
                BitmapFont.drawText(argb, size, size, x, y, label, scale, GRID_LABEL);
            }
        }
    }

    /**
     * A checkerboard of {@code cells x cells} squares; the square at UV (0, 0), the bottom-left, has
     * colour {@code argbA}. Square edges fall on {@code ceil(k * size / cells)} texels, so sizes that are
     * not multiples of {@code cells} give squares differing by at most one texel.
     *
     * @param size  width and height in texels
     * @param cells squares per side, {@code 1..size}
     * @param argbA colour of the bottom-left square and every second one from it, 0xAARRGGBB
     * @param argbB colour of the squares that alternate with those, 0xAARRGGBB
     * @return the texture
     */
    public static Texture checker(int size, int cells, int argbA, int argbB) {
        Pixels.requireSide("checker size", size);
        if (cells < 1 || cells > size) {
            throw new IllegalArgumentException("checker cells " + cells + " is outside 1.." + size);
        }
        int[] argb = new int[size * size];
        for (int y = 0; y < size; y++) {
            int row = Pixels.partOf(size - 1 - y, cells, size);
            for (int x = 0; x < size; x++) {
                argb[y * size + x] = ((Pixels.partOf(x, cells, size) + row) & 1) == 0 ? argbA : argbB;
            }
        }
        return new Texture("checker-" + size + "-" + cells, size, size, argb);
    }

    /**
     * A wooden crate face: five vertical planks inside a frame of darker boards, with a diagonal brace
     * from the bottom-left to the top-right corner and a nail at each corner of the frame.
     *
     * @param size width and height in texels
     * @return the texture
     */
    public static Texture crate(int size) {
        Pixels.requireSide("crate size", size);
        int[] argb = new int[size * size];
        int frame = Math.max(1, size / 8);
        int seam = Math.max(1, size / 128);
        int planks = 5;
        double braceHalfWidth = frame * 0.5 * Math.sqrt(2.0);
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                int toSide = Math.min(x, size - 1 - x);
                int toEdge = Math.min(y, size - 1 - y);
                // Brace along s = t (bottom-left to top-right), measured at the texel centre.
                double s = x + 0.5;
                double t = size - (y + 0.5);
                int colour;
                if (Math.min(toSide, toEdge) < frame) {
                    // The nearest outer edge decides the board, which mitres the corners.
                    boolean horizontalBoard = toEdge < toSide;
                    colour = horizontalBoard
                            ? wood(FRAME_WOOD, x, y, size, y < size / 2 ? 11 : 12)
                            : wood(FRAME_WOOD, y, x, size, x < size / 2 ? 13 : 14);
                    if (toSide == toEdge || Math.min(toSide, toEdge) == frame - 1) {
                        colour = Pixels.shade(colour, 0.6);
                    }
                } else if (Math.abs(s - t) < braceHalfWidth) {
                    colour = wood(BRACE_WOOD, (int) ((s + t) / 2), (int) (s - t + size), size, 15);
                    if (braceHalfWidth - Math.abs(s - t) < 1) {
                        colour = Pixels.shade(colour, 0.6);
                    }
                } else {
                    int plank = Pixels.partOf(x, planks, size);
                    colour = wood(PLANK_WOOD, y, x, size, 20 + plank);
                    if (x - Pixels.partStart(plank, planks, size) < seam) {
                        colour = Pixels.shade(colour, 0.55);
                    }
                }
                argb[y * size + x] = colour;
            }
        }
        int nail = Math.max(1, frame / 4);
        for (int corner = 0; corner < 4; corner++) {
            int cx = (corner & 1) == 0 ? frame / 2 : size - 1 - frame / 2;
            int cy = (corner & 2) == 0 ? frame / 2 : size - 1 - frame / 2;
            Pixels.fillRect(argb, size, size, cx - nail / 2, cy - nail / 2, cx - nail / 2 + nail,
                    cy - nail / 2 + nail, 0xFF3A3A3A);
        }
        return new Texture("crate-" + size, size, size, argb);
    }

    /**
     * Wood grain running along {@code along} (texels): a colour shaded by wavy stripes that vary across
     * the grain, and a little per-texel noise.
     */
    private static int wood(int base, int along, int across, int size, int seed) {
        double a = along / (double) size;
        double c = across / (double) size;
        double wave = StrictMath.sin(2 * Math.PI * (a * 1.5 + (seed % 7) / 7.0)) * 0.04;
        double stripes = 0.5 + 0.5 * StrictMath.sin(2 * Math.PI * ((c + wave) * 48 + seed));
        double factor = 0.86 + 0.12 * stripes + 0.03 * Pixels.noise(along, across, seed);
        return Pixels.shade(base, factor);
    }

    /**
     * A brick wall in running bond: 8 courses of 4 bricks, every other course shifted by half a brick,
     * light mortar joints, each brick a slightly different red. Tiles seamlessly in both directions.
     *
     * @param width  width in texels
     * @param height height in texels
     * @return the texture
     */
    public static Texture bricks(int width, int height) {
        Pixels.requireSide("bricks width", width);
        Pixels.requireSide("bricks height", height);
        int courses = 8;
        int perCourse = 4;
        int mortar = Math.max(1, Math.min(width / perCourse, height / courses) / 8);
        int[] argb = new int[width * height];
        for (int y = 0; y < height; y++) {
            int fromBottom = height - 1 - y;
            int course = Pixels.partOf(fromBottom, courses, height);
            boolean inBedJoint = fromBottom - Pixels.partStart(course, courses, height) < mortar;
            // Odd courses are shifted by half a brick; wrapping keeps the pattern tileable.
            int shift = (course & 1) == 0 ? 0 : width / (2 * perCourse);
            for (int x = 0; x < width; x++) {
                int shifted = Math.floorMod(x + shift, width);
                int brick = Pixels.partOf(shifted, perCourse, width);
                boolean inHeadJoint = shifted - Pixels.partStart(brick, perCourse, width) < mortar;
                int colour;
                if (inBedJoint || inHeadJoint) {
                    colour = Pixels.shade(0xFFC9C2B4, 1 + 0.05 * Pixels.noise(x, y, 1));
                } else {
                    double tone = 0.08 * Pixels.noise(brick, course, 2);
                    int base = Pixels.rgb(172 * (1 + tone), 74 * (1 + tone * 1.5), 52 * (1 + tone));
                    colour = Pixels.shade(base, 1 + 0.06 * Pixels.noise(x, y, 3));
                }
                argb[y * width + x] = colour;
            }
        }
        return new Texture("bricks-" + width + "x" + height, width, height, argb);
    }

    /**
     * A globe for a UV sphere, in equirectangular layout: u runs over longitude from -180 to 180 degrees
     * (0 at u = 0.5), v over latitude from -90 (v = 0) to 90 degrees (v = 1). Blue ocean, a meridian
     * and parallel every 30 degrees, the equator in red and the prime meridian in yellow, polar caps,
     * and labels ({@code 0}, {@code 30E}, ..., {@code 30N}, ...) when the image is large enough.
     *
     * @param width  width in texels (2:1 with the height looks right)
     * @param height height in texels
     * @return the texture
     */
    public static Texture globe(int width, int height) {
        Pixels.requireSide("globe width", width);
        Pixels.requireSide("globe height", height);
        int meridians = 12;
        int parallels = 6;
        int[] argb = new int[width * height];
        for (int y = 0; y < height; y++) {
            int fromBottom = height - 1 - y;
            double latitude = (fromBottom + 0.5) / height * 180 - 90;
            double ocean = 0.75 + 0.25 * StrictMath.cos(Math.toRadians(latitude));
            int background = Math.abs(latitude) > 75 ? 0xFFEEF3F7 : Pixels.rgb(40 * ocean, 96 * ocean, 170 * ocean);
            for (int x = 0; x < width; x++) {
                argb[y * width + x] = background;
            }
        }
        int line = Math.max(1, Math.min(width / 512, height / 256));
        for (int k = 0; k <= meridians; k++) {
            int start = Pixels.partStart(k, meridians, width) - line / 2;
            int colour = k == meridians / 2 ? 0xFFF2C230 : 0xFFBFD4EA;
            Pixels.fillRect(argb, width, height, start, 0, start + line, height, colour);
        }
        for (int k = 1; k < parallels; k++) {
            int start = Pixels.partStart(k, parallels, height) - line / 2;
            int colour = k == parallels / 2 ? 0xFFE0402F : 0xFFBFD4EA;
            Pixels.fillRect(argb, width, height, 0, height - start - line, width, height - start, colour);
        }
        drawGlobeLabels(argb, width, height, meridians, parallels);
        return new Texture("globe-" + width + "x" + height, width, height, argb);
    }

    /** Longitudes just above the equator, latitudes just right of the prime meridian. */
    private static void drawGlobeLabels(int[] argb, int width, int height, int meridians, int parallels) {
        int scale = Math.min(width / meridians, height / parallels) / 32;
        if (scale < 1) {
            return;
        }
        int label = 0xFFFFFFFF;
        int equatorY = height - Pixels.partStart(parallels / 2, parallels, height);
        int gap = 2 * scale;
        for (int k = 0; k < meridians; k++) {
            int degrees = k * 360 / meridians - 180;
            String text = degrees == 0 || degrees == -180 ? Integer.toString(Math.abs(degrees))
                    : Math.abs(degrees) + (degrees > 0 ? "E" : "W");
            int x = Pixels.partStart(k, meridians, width) + gap;
            BitmapFont.drawText(argb, width, height, x, equatorY - gap - BitmapFont.textHeight(scale), text,
                    scale, label);
        }
        int meridianX = Pixels.partStart(meridians / 2, meridians, width) + gap;
        for (int k = 1; k < parallels; k++) {
            int degrees = k * 180 / parallels - 90;
            if (degrees == 0) {
                continue; // the equator is labelled by the longitudes
            }
            String text = Math.abs(degrees) + (degrees > 0 ? "N" : "S");
            int y = height - Pixels.partStart(k, parallels, height) + gap;
            BitmapFont.drawText(argb, width, height, meridianX, y, text, scale, label);
        }
    }
}
