package dev.trisect.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import java.util.zip.CRC32;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import dev.trisect.texture.internal.BitmapFont;
import dev.trisect.texture.internal.Pixels;

class ProceduralTexturesTest {
    /**
     * The label-coloured pixels of a UV grid cell, cropped to their bounding box, as rows of '#' and '.'
     * ("" when there are none).
     *
     * @param row cell row from the bottom, as the label numbers them (0 for row 1)
     */
    private static String labelIn(Texture grid, int column, int row) {
        int size = grid.width();
        int left = Pixels.partStart(column, 8, size);
        int right = Pixels.partStart(column + 1, 8, size);
        int top = size - Pixels.partStart(row + 1, 8, size);
        int bottom = size - Pixels.partStart(row, 8, size);
        return cropped(grid.argb(), size, left, top, right, bottom, ProceduralTextures.GRID_LABEL);
    }

    /** Text as BitmapFont draws it, cropped the same way. */
    private static String rendered(String text, int scale) {
        int width = BitmapFont.textWidth(text, scale) + 2;
        int height = BitmapFont.textHeight(scale) + 2;
        int[] argb = new int[width * height];
        BitmapFont.drawText(argb, width, height, 1, 1, text, scale, ProceduralTextures.GRID_LABEL);
        return cropped(argb, width, 0, 0, width, height, ProceduralTextures.GRID_LABEL);
    }

    private static String cropped(int[] argb, int stride, int left, int top, int right, int bottom, int colour) {
        int minX = right;
        int maxX = left - 1;
        int minY = bottom;
        int maxY = top - 1;
        for (int y = top; y < bottom; y++) {
            for (int x = left; x < right; x++) {
                if (argb[y * stride + x] == colour) {
                    minX = Math.min(minX, x);
                    maxX = Math.max(maxX, x);
                    minY = Math.min(minY, y);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        StringBuilder picture = new StringBuilder();
        for (int y = minY; y <= maxY; y++) {
            for (int x = minX; x <= maxX; x++) {
                picture.append(argb[y * stride + x] == colour ? '#' : '.');
            }
            picture.append('\n');
        }
        return picture.toString();
    }

    private static boolean showsLabel(Texture grid, int column, int row, String label) {
        String found = labelIn(grid, column, row);
        for (int scale = 1; scale <= 8; scale++) {
            if (found.equals(rendered(label, scale))) {
                return true;
            }
        }
        return false;
    }

    @ParameterizedTest(name = "size {0}")
    @ValueSource(ints = {128, 300, 512, 1000})
    void uvGridLabelsNameTheirCellsFromTheBottomLeft(int size) {
        Texture grid = ProceduralTextures.uvGrid(size);
        assertTrue(showsLabel(grid, 0, 0, "A1"), "A1 in the bottom-left cell, upright");
        assertTrue(showsLabel(grid, 7, 0, "H1"), "H1 in the bottom-right cell");
        assertTrue(showsLabel(grid, 0, 7, "A8"), "A8 in the top-left cell");
        assertTrue(showsLabel(grid, 7, 7, "H8"), "H8 in the top-right cell");
        assertTrue(showsLabel(grid, 3, 4, "D5"), "D5: fourth column, fifth row from the bottom");
        assertFalse(showsLabel(grid, 0, 0, "A8"), "the bottom-left cell is not A8");
    }

    @Test
    void uvGridMarksSitWhereTheirUvSays() {
        Texture grid = ProceduralTextures.uvGrid(512);
        assertEquals(ProceduralTextures.GRID_CELL_A, grid.sampleUv(0.02, 0.11), "A1 has the first colour");
        assertEquals(ProceduralTextures.GRID_CELL_B, grid.sampleUv(0.14, 0.02), "B1 has the second");
        assertEquals(ProceduralTextures.GRID_DIAGONAL, grid.sampleUv(0.26, 0.26), "red on u = v");
        assertEquals(ProceduralTextures.GRID_ANTI_DIAGONAL, grid.sampleUv(0.26, 0.74), "blue on u + v = 1");
        assertEquals(ProceduralTextures.GRID_CIRCLE, grid.sampleUv(0.51, 0.875), "green circle, radius 0.375");
        assertEquals(ProceduralTextures.GRID_LINE, grid.argb()[grid.texelIndex(64.5, 200.5)], "line at u = 1/8");
        assertEquals(ProceduralTextures.GRID_LINE, grid.argb()[grid.texelIndex(200.5, 64.5)], "line at v = 1/8");
    }

    @ParameterizedTest(name = "size {0}")
    @ValueSource(ints = {1, 2, 7, 64, 127, 300, 513})
    void uvGridWorksForAnySize(int size) {
        Texture grid = ProceduralTextures.uvGrid(size);
        assertEquals(size, grid.width());
        assertEquals(size, grid.height());
        assertTrue(Arrays.stream(grid.argb()).allMatch(texel -> texel >>> 24 == 0xFF), "opaque");
        boolean labelled = Arrays.stream(grid.argb()).anyMatch(texel -> texel == ProceduralTextures.GRID_LABEL);
        assertEquals(size >= 128, labelled, "labels only where cells have room for them");
    }

    @Test
    void checkerStartsAtTheBottomLeftAndSplitsOddSizesEvenly() {
        int a = 0xFFAAAAAA;
        int b = 0xFF555555;
        Texture checker = ProceduralTextures.checker(5, 2, a, b);
        StringBuilder picture = new StringBuilder();
        for (int i = 0; i < checker.argb().length; i++) {
            picture.append(checker.argb()[i] == a ? 'A' : checker.argb()[i] == b ? 'B' : '?');
            picture.append(i % 5 == 4 ? "/" : "");
        }
        // Row 0 is the top; the bottom-left square (UV 0, 0) is A; squares of 3 and 2 texels.
        assertEquals("BBBAA/BBBAA/AAABB/AAABB/AAABB/", picture.toString());
    }

    @Test
    void globeMarksEquatorAndPrimeMeridian() {
        Texture globe = ProceduralTextures.globe(1024, 512);
        assertEquals(0xFFE0402F, globe.sampleUv(0.3, 0.5), "equator at v = 0.5");
        assertEquals(0xFFF2C230, globe.sampleUv(0.5, 0.3), "prime meridian at u = 0.5");
    }

    @Test
    void bricksHaveMortarAlongTheBottomAndRedBricksAbove() {
        Texture bricks = ProceduralTextures.bricks(256, 128);
        for (int x = 0; x < 256; x++) {
            int texel = bricks.argb()[127 * 256 + x];
            assertTrue((texel >> 8 & 0xFF) > 150, "light mortar in the bottom row at x " + x);
        }
        int inBrick = bricks.sampleUv(0.2, 1.5 / 16);
        assertTrue((inBrick >> 16 & 0xFF) > (inBrick >> 8 & 0xFF) + 50, "a red brick above the bottom joint");
    }

    @Test
    void crateHasNailsInTheFrameCorners() {
        Texture crate = ProceduralTextures.crate(256);
        int frame = 256 / 8;
        assertEquals(0xFF3A3A3A, crate.argb()[(frame / 2) * 256 + frame / 2], "top-left nail");
        assertEquals(0xFF3A3A3A, crate.argb()[(255 - frame / 2) * 256 + 255 - frame / 2], "bottom-right nail");
    }

    @ParameterizedTest(name = "{0}x{1}")
    @ValueSource(ints = {1, 3, 100, 301})
    void everyTextureWorksForAnySizeAndIsOpaque(int size) {
        List<Texture> textures = List.of(ProceduralTextures.checker(size, 1, 0xFF000000, 0xFFFFFFFF),
                ProceduralTextures.crate(size), ProceduralTextures.bricks(size, size / 2 + 1),
                ProceduralTextures.globe(2 * size, size));
        for (Texture texture : textures) {
            assertEquals(texture.width() * texture.height(), texture.argb().length, texture.name());
            assertTrue(Arrays.stream(texture.argb()).allMatch(texel -> texel >>> 24 == 0xFF), texture.name());
        }
    }

    private static long crc(Texture texture) {
        ByteBuffer bytes = ByteBuffer.allocate(texture.argb().length * 4);
        bytes.asIntBuffer().put(texture.argb());
        CRC32 crc = new CRC32();
        crc.update(bytes);
        return crc.getValue();
    }

    /**
     * The same texels on every machine: these checksums were taken once, so a difference means the
     * output changed. If a texture is changed on purpose, look at it and take the new checksum.
     */
    @Test
    void texelsAreTheSameOnEveryRun() {
        List<Supplier<Texture>> makers = List.of(() -> ProceduralTextures.uvGrid(300),
                () -> ProceduralTextures.checker(50, 7, 0xFF102030, 0xFFF0E0D0), () -> ProceduralTextures.crate(200),
                () -> ProceduralTextures.bricks(300, 150), () -> ProceduralTextures.globe(400, 200));
        long[] expected = {3089263342L, 98288042L, 3547476484L, 3513688248L, 2296463454L};
        for (int i = 0; i < makers.size(); i++) {
            Texture texture = makers.get(i).get();
            assertEquals(expected[i], crc(texture), texture.name() + " checksum");
        }
    }

    @Test
    void badSizesAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.uvGrid(0));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.uvGrid(Texture.MAX_SIDE + 1));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.checker(8, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.checker(8, 9, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.crate(-1));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.bricks(8, 0));
        assertThrows(IllegalArgumentException.class, () -> ProceduralTextures.globe(Texture.MAX_SIDE + 1, 8));
    }
}
