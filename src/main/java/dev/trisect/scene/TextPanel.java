package dev.trisect.scene;

import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.texture.Texture;
import dev.trisect.texture.internal.GlyphAtlas;
import java.awt.Font;
import java.util.Arrays;
import java.util.Objects;

/**
 * A grid of characters on a flat panel in the scene, each cell with its own colour and background (as
 * Sixth 3D's {@code TextCanvas}): a console, a sign, a table. The panel is an ordinary
 * {@link SceneObject} ({@link #object()}), a rectangle in its x-y plane facing +z, centred on its
 * origin, one {@code rowHeight} per row; place, turn and group it as any object. Its texture holds
 * one cell of {@code font}'s line height by its widest advance per character (a monospaced font gives
 * a true grid), each glyph drawn as AWT draws it without antialiasing, and is drawn anew, and given to
 * the object, after each change. Thread-safe.
 *
 * <pre>{@code
 * TextPanel panel = new TextPanel(20, 4, new Font(Font.MONOSPACED, Font.PLAIN, 16), 0.2);
 * panel.write(0, 0, "HP  100", 0x00FF00, 0x000000);
 * scene.add(panel.object());
 * }</pre>
 */
public final class TextPanel {
    private final int columns;
    private final int rows;
    private final GlyphAtlas atlas;
    private final int cellWidth;
    private final int cellHeight;
    private final int[] codePoints;
    private final int[] colours;
    private final int[] backgrounds;
    private final SceneObject object;

    /**
     * A panel of blank cells on black.
     *
     * @param columns   characters across, 1..1024
     * @param rows      characters down, 1..1024
     * @param font      the font; its size is a cell's height in texels
     * @param rowHeight world units per row (the panel is {@code rows * rowHeight} high)
     * @throws NullPointerException     when {@code font} is null
     * @throws IllegalArgumentException for a size out of range, a font size outside 1 to 512 pixels, or a
     *                                  row height not positive and finite
     */
    public TextPanel(int columns, int rows, Font font, double rowHeight) {
        GlyphAtlas.checkFont(font);
        if (columns < 1 || rows < 1 || columns > 1024 || rows > 1024) {
            throw new IllegalArgumentException("a text panel is 1 to 1024 cells a side, got " + columns + "x" + rows);
        }
        if (!(rowHeight > 0 && Double.isFinite(rowHeight))) {
            throw new IllegalArgumentException("row height must be positive and finite, got " + rowHeight);
        }
        this.columns = columns;
        this.rows = rows;
        this.atlas = GlyphAtlas.of(font);
        this.cellHeight = atlas.lineHeight();
        this.cellWidth = Math.max(1, atlas.glyph('M').advance());
        this.codePoints = new int[columns * rows];
        Arrays.fill(codePoints, ' ');
        this.colours = new int[columns * rows];
        Arrays.fill(colours, 0xFFFFFF);
        this.backgrounds = new int[columns * rows];
        double height = rows * rowHeight;
        double width = height * columns * cellWidth / (rows * (double) cellHeight);
        this.object = new SceneObject(quad(width, height), Material.of(texture()));
    }

    /** A w x h rectangle in the x-y plane, facing +z, centred, its texture upright. */
    private static Mesh quad(double w, double h) {
        MeshBuilder b = new MeshBuilder();
        int p0 = b.position(-w / 2, -h / 2, 0);
        int p1 = b.position(w / 2, -h / 2, 0);
        int p2 = b.position(w / 2, h / 2, 0);
        int p3 = b.position(-w / 2, h / 2, 0);
        int t0 = b.uv(0, 0);
        int t1 = b.uv(1, 0);
        int t2 = b.uv(1, 1);
        int t3 = b.uv(0, 1);
        b.triangle(p0, p1, p2, t0, t1, t2);
        b.triangle(p0, p2, p3, t0, t2, t3);
        return b.build();
    }

    /**
     * The panel as an object of the scene.
     *
     * @return the object, the same one for the panel's life
     */
    public SceneObject object() {
        return object;
    }

    /**
     * Characters across.
     *
     * @return the columns
     */
    public int columns() {
        return columns;
    }

    /**
     * Characters down.
     *
     * @return the rows
     */
    public int rows() {
        return rows;
    }

    /**
     * Writes {@code text} into row {@code row} from column {@code column} on, one character a cell, in
     * these colours; what does not fit the row is dropped. Shown from the next frame on.
     *
     * @param column     first cell's column, from 0 at the left
     * @param row        the row, from 0 at the top
     * @param text       the characters (code points)
     * @param rgb        their colour, 0xRRGGBB
     * @param background their cells' background, 0xRRGGBB
     * @throws NullPointerException      when {@code text} is null
     * @throws IndexOutOfBoundsException when the cell is outside the panel
     */
    public synchronized void write(int column, int row, String text, int rgb, int background) {
        Objects.requireNonNull(text, "text is null");
        if (column < 0 || row < 0 || column >= columns || row >= rows) {
            throw new IndexOutOfBoundsException("cell (" + column + ", " + row + ") is outside the panel's "
                    + columns + "x" + rows);
        }
        int c = column;
        for (int k = 0; k < text.length() && c < columns; k = text.offsetByCodePoints(k, 1), c++) {
            int i = row * columns + c;
            codePoints[i] = text.codePointAt(k);
            colours[i] = rgb & 0xFFFFFF;
            backgrounds[i] = background & 0xFFFFFF;
        }
        object.setMaterial(Material.of(texture()));
    }

    /**
     * Blanks every cell onto {@code background}. Shown from the next frame on.
     *
     * @param background 0xRRGGBB
     */
    public synchronized void clear(int background) {
        Arrays.fill(codePoints, ' ');
        Arrays.fill(backgrounds, background & 0xFFFFFF);
        object.setMaterial(Material.of(texture()));
    }

    /**
     * The character in a cell.
     *
     * @param column from 0 at the left
     * @param row    from 0 at the top
     * @return its code point (a space when blank)
     */
    public synchronized int charAt(int column, int row) {
        return codePoints[row * columns + column];
    }

    /** The cells drawn into a new texture: backgrounds, then each glyph in its cell's colour. */
    private Texture texture() {
        int w = columns * cellWidth;
        int h = rows * cellHeight;
        int[] argb = new int[w * h];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < columns; c++) {
                int i = r * columns + c;
                int x0 = c * cellWidth;
                int y0 = r * cellHeight;
                for (int y = 0; y < cellHeight; y++) {
                    Arrays.fill(argb, (y0 + y) * w + x0, (y0 + y) * w + x0 + cellWidth, 0xFF000000 | backgrounds[i]);
                }
                GlyphAtlas.Glyph g = atlas.glyph(codePoints[i]);
                int gx = x0 + g.left();
                int gy = y0 + atlas.ascent() + g.top();
                for (int y = 0; y < g.height(); y++) {
                    for (int x = 0; x < g.width(); x++) {
                        int px = gx + x;
                        int py = gy + y;
                        // Ink beyond its cell is cut off there, so that cells never bleed into each other.
                        if (px >= x0 && px < x0 + cellWidth && py >= y0 && py < y0 + cellHeight
                                && g.texels()[(g.y() + y) * GlyphAtlas.WIDTH + g.x() + x] != 0) {
                            argb[py * w + px] = 0xFF000000 | colours[i];
                        }
                    }
                }
            }
        }
        return new Texture("text panel " + columns + "x" + rows, w, h, argb);
    }
}
