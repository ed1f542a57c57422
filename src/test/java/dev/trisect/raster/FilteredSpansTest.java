package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.internal.Sampler;
import dev.trisect.texture.internal.TexelLanes;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The bilinear and trilinear span loops: per-piece and per-pixel level of detail, tiling, blur. */
class FilteredSpansTest {
    private static final int W = 96;
    private static final int H = 64;

    private static int[] all(ScreenTriangles t) {
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        return order;
    }

    private static Framebuffer fill(ScreenTriangles t, Texture[] textures, TextureFilter filter, boolean perspective) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        fb.clearRows(0, H, 0);
        Rasterizer r = new Rasterizer();
        r.filter(filter);
        r.fill(fb, t, all(t), 0, t.count(), textures, perspective, 0, 0, W, H);
        return fb;
    }

    private static Texture noise(int w, int h, long seed) {
        Random rnd = new Random(seed);
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = 0xFF000000 | rnd.nextInt(0x1000000);
        }
        return new Texture("noise", w, h, px);
    }

    /** A one-texel black and white checker, w x h. */
    private static Texture checker(int w, int h) {
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = ((i % w + i / w) & 1) == 0 ? 0xFF000000 : 0xFFFFFFFF;
        }
        return new Texture("checker", w, h, px);
    }

    @Test
    void anAffineMapGetsTheSameLevelPerPixelAsPerPiece() {
        // All corners at the same depth: the perspective loop (per-pixel level of detail from the exact
        // derivatives) and the affine loop (one level per piece) sample the same levels with the same
        // weights; positions differ only by fixed-point stepping (< 2^-32 texel), so at most 1/255.
        Random rnd = new Random(8);
        Texture[] textures = {noise(64, 64, 1), noise(37, 23, 2)};
        for (int k = 0; k < 40; k++) {
            ScreenTriangles t = new ScreenTriangles();
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            double scale = Math.pow(2, rnd.nextDouble() * 8 - 3);
            t.add(x, y, 1, 0, 0,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 1, 20 * scale, 3 * scale,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 1, -5 * scale, 25 * scale,
                    k, k % 2);
            Framebuffer perPixel = fill(t, textures, TextureFilter.TRILINEAR, true);
            Framebuffer perPiece = fill(t, textures, TextureFilter.TRILINEAR, false);
            assertArrayEquals(perPixel.depth(), perPiece.depth());
            int[] a = perPixel.colour();
            int[] b = perPiece.colour();
            for (int i = 0; i < a.length; i++) {
                for (int shift = 0; shift < 24; shift += 8) {
                    int d = Math.abs((a[i] >>> shift & 0xFF) - (b[i] >>> shift & 0xFF));
                    assertTrue(d <= 1, "triangle " + k + " pixel " + i + ": " + Integer.toHexString(a[i]) + " vs "
                            + Integer.toHexString(b[i]));
                }
            }
        }
    }

    @Test
    void fallbackPiecesTakeThePerPixelLevelInTheAffinePath() {
        // A piece flagged for the per-pixel fallback, in a frame filled affinely, gets exactly what the
        // perspective path gives it: division and the per-pixel level of detail.
        Random rnd = new Random(9);
        Texture[] textures = {noise(64, 64, 6)};
        for (int k = 0; k < 20; k++) {
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            double[] c = {x, y, 0.05 + rnd.nextDouble(), 0, 0,
                x + rnd.nextGaussian() * 40, y + rnd.nextGaussian() * 40, 0.05 + rnd.nextDouble(), 300, 20,
                x + rnd.nextGaussian() * 40, y + rnd.nextGaussian() * 40, 0.05 + rnd.nextDouble(), -30, 250};
            ScreenTriangles flagged = new ScreenTriangles();
            flagged.add(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12], c[13], c[14],
                    k, 0, true);
            ScreenTriangles plain = new ScreenTriangles();
            plain.add(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12], c[13], c[14],
                    k, 0);
            assertArrayEquals(fill(plain, textures, TextureFilter.TRILINEAR, true).colour(),
                    fill(flagged, textures, TextureFilter.TRILINEAR, false).colour(), "triangle " + k);
        }
    }

    @Test
    void perPixelBilinearIsThePackedRuleAndWithinOneOfTheExactBlend() {
        // Every pixel of perspective triangles on power-of-two and odd textures (the two loops of the
        // per-pixel bilinear fill): the colour is LaneSampler's rule at the pixel's own texel
        // coordinates (the UV output) bit for bit, and each channel is within 1/255 of the exact blend of
        // the rule before the packed one (Sampler.bilinear, 16-bit weights).
        Random rnd = new Random(31);
        Texture[] textures = {noise(64, 64, 3), noise(37, 23, 4), noise(1, 1, 5)};
        int pixels = 0;
        int differ = 0;
        for (int k = 0; k < 60; k++) {
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            ScreenTriangles t = new ScreenTriangles();
            t.add(x, y, 1, rnd.nextGaussian() * 50, rnd.nextGaussian() * 50,
                    x + rnd.nextGaussian() * 40, y + rnd.nextGaussian() * 40, 0.05 + rnd.nextDouble(), 90, -20,
                    x + rnd.nextGaussian() * 40, y + rnd.nextGaussian() * 40, 0.05 + rnd.nextDouble(), -30, 70,
                    k, k % 3);
            Framebuffer fb = fill(t, textures, TextureFilter.BILINEAR, true);
            Texture tex = textures[k % 3];
            TexelLanes lanes = TexelLanes.of(tex.mipChain());
            for (int i = 0; i < W * H; i++) {
                if (fb.uv()[3 * i + 2] == 0) {
                    continue;
                }
                double s = fb.uv()[3 * i];
                double tt = fb.uv()[3 * i + 1];
                long px = (long) Math.floor(s * Sampler.ONE) - Sampler.ONE / 2;
                long py = (long) Math.floor(tt * Sampler.ONE) - Sampler.ONE / 2;
                int want = TexelLanes.argb(LaneSampler.bilinear(lanes.lanes(), 0, lanes.stride(0), tex.width(),
                        tex.height(), px, py));
                int got = fb.colour()[i];
                assertEquals(Integer.toHexString(want), Integer.toHexString(got), "triangle " + k + " pixel " + i);
                int exact = Sampler.bilinear(tex.argb(), tex.width(), tex.height(), Sampler.position(s),
                        Sampler.position(tt));
                for (int shift = 0; shift < 24; shift += 8) {
                    assertTrue(Math.abs((got >>> shift & 0xFF) - (exact >>> shift & 0xFF)) <= 1,
                            "triangle " + k + " pixel " + i);
                }
                pixels++;
                differ += got == exact ? 0 : 1;
            }
        }
        assertTrue(pixels > 10_000 && differ > 0, pixels + " pixels, " + differ + " differ from the exact blend");
    }

    @Test
    void minifiedCheckerAveragesToGrey() {
        // 7.3 texels per pixel: lambda = 2.87, and every level from 1 on of a one-texel checker is the grey
        // (0 + 255 + 0 + 255) / 4 = 127.5, rounded to 128. Bilinear on level 0 alias instead.
        ScreenTriangles t = new ScreenTriangles();
        t.add(0, 0, 1, 0, 0, 90, 0, 1, 657, 0, 0, 60, 1, 0, -438, 0, 0);
        Texture[] textures = {checker(64, 64)};
        for (boolean perspective : new boolean[] {true, false}) {
            int[] tri = fill(t, textures, TextureFilter.TRILINEAR, perspective).colour();
            int[] bi = fill(t, textures, TextureFilter.BILINEAR, perspective).colour();
            int greyTri = 0;
            int greyBi = 0;
            int covered = 0;
            for (int i = 0; i < tri.length; i++) {
                if (tri[i] != 0xFF000000 || bi[i] != 0xFF000000) {
                    covered++;
                    greyTri += tri[i] == 0xFF808080 ? 1 : 0;
                    greyBi += bi[i] == 0xFF808080 ? 1 : 0;
                }
            }
            assertTrue(covered > 2000);
            assertEquals(covered, greyTri, "trilinear, perspective " + perspective);
            assertTrue(greyBi < covered / 2, "bilinear stays on level 0, perspective " + perspective);
        }
    }

    /**
     * The per-pixel trilinear colour by the documented rule, from the rasterizer's planes: lambda exact
     * (in 1/256) at the columns that are multiples of {@link FilteredSpans#LOD_RUN}, linear between
     * unless the run changes it by more than {@link FilteredSpans#MAX_LOD_STEP} or is not
     * {@link FilteredSpans#nearlyLinear} (then exact at the
     * pixel), and the generic {@link Sampler} calls per level.
     */
    private static int expectedTrilinear(Rasterizer r, MipChain mips, int x, int y) {
        double q = r.setup().qPlane.base + r.setup().qPlane.dy * y + r.setup().qPlane.dx * x;
        double s = (r.setup().sPlane.base + r.setup().sPlane.dy * y + r.setup().sPlane.dx * x) / q;
        double t = (r.setup().tPlane.base + r.setup().tPlane.dy * y + r.setup().tPlane.dx * x) / q;
        double lambda = interpolatedLambda(r, mips, x, y);
        int selection = Double.isNaN(lambda)
                ? Lod.selectOfSquared(Lod.rhoSquared(s, t, 1 / q, r.setup().sPlane.dx, r.setup().tPlane.dx, r.setup().qPlane.dx),
                Lod.rhoSquared(s, t, 1 / q, r.setup().sPlane.dy, r.setup().tPlane.dy, r.setup().qPlane.dy), mips.maxLevel())
                : Lod.select((int) lambda, mips.maxLevel());
        int d = Lod.level(selection);
        long c = level(mips, d, s, t);
        if (Lod.weight(selection) != 0) {
            c = LaneSampler.lerp(c, level(mips, d + 1, s, t), Lod.weight(selection));
        }
        return TexelLanes.argb(c);
    }

    /** The bilinear sample of level d at level-0 texel coordinates, by the general (floorMod) sampler. */
    private static long level(MipChain mips, int d, double s, double t) {
        TexelLanes lanes = TexelLanes.of(mips);
        return LaneSampler.bilinear(lanes.lanes(), lanes.offset(d), lanes.stride(d), mips.width(d), mips.height(d),
                Sampler.position(s * mips.scaleS(d)), Sampler.position(t * mips.scaleT(d)));
    }

    /**
     * The documented interpolated lambda at pixel (x, y), in 1/256 (an integer), or NaN where the rule
     * takes the exact lambda: lambda along x and along y exact at the run's first column and the next
     * run's ({@link Lod#fixed}), each stepped linearly (rounded down), the larger of the two.
     */
    private static double interpolatedLambda(Rasterizer r, MipChain mips, int x, int y) {
        int run = LodRuns.LOD_RUN;
        int a = x - Math.floorMod(x, run);
        int[] la = axisLambdas(r, mips, a, y);
        int[] lb = axisLambdas(r, mips, a + run, y);
        if (la == null || lb == null || Math.abs(lb[0] - la[0]) > LodRuns.MAX_LOD_STEP
                || Math.abs(lb[1] - la[1]) > LodRuns.MAX_LOD_STEP
                || !LodRuns.nearlyLinear(a, r.setup().qPlane.base + r.setup().qPlane.dy * y, r.setup().sPlane.base + r.setup().sPlane.dy * y,
                r.setup().tPlane.base + r.setup().tPlane.dy * y, r.setup().qPlane.dx, r.setup().sPlane.dx, r.setup().sPlane.dy, r.setup().tPlane.dx, r.setup().tPlane.dy,
                r.setup().qPlane.dx, r.setup().qPlane.dy, true)) {
            return Double.NaN;
        }
        return Math.max(la[0] + Math.floorDiv((lb[0] - la[0]) * (x - a), run),
                la[1] + Math.floorDiv((lb[1] - la[1]) * (x - a), run));
    }

    /** lambda along x and along y at (x, y) in 1/256, or null where 1/w is not positive or a lambda is NaN. */
    private static int[] axisLambdas(Rasterizer r, MipChain mips, int x, int y) {
        double q = r.setup().qPlane.base + r.setup().qPlane.dy * y + r.setup().qPlane.dx * x;
        if (!(q > 0)) {
            return null;
        }
        double s = (r.setup().sPlane.base + r.setup().sPlane.dy * y + r.setup().sPlane.dx * x) / q;
        double t = (r.setup().tPlane.base + r.setup().tPlane.dy * y + r.setup().tPlane.dx * x) / q;
        int lx = Lod.fixedOfSquared(Lod.rhoSquared(s, t, 1 / q, r.setup().sPlane.dx, r.setup().tPlane.dx, r.setup().qPlane.dx),
                mips.maxLevel());
        int ly = Lod.fixedOfSquared(Lod.rhoSquared(s, t, 1 / q, r.setup().sPlane.dy, r.setup().tPlane.dy, r.setup().qPlane.dy),
                mips.maxLevel());
        return lx == Lod.NO_LAMBDA || ly == Lod.NO_LAMBDA ? null : new int[] {lx, ly};
    }

    private static double clamp(double lambda, MipChain mips) {
        return Math.max(0, Math.min(mips.maxLevel(), lambda));
    }

    @Test
    void perPixelLevelOfDetailIsExactAtRunStartsAndLinearBetween() {
        // Steeply foreshortened triangles (depth ratios up to 20 across them), on power-of-two and other
        // textures: every pixel is the documented rule's colour, bit for bit, and where lambda is
        // interpolated it stays within 0.012 of the exact one (as it selects levels: clamped to the range
        // of levels), the documented bound 3/256 (LodRuns.nearlyLinear).
        Random rnd = new Random(10);
        Texture[] textures = {noise(64, 64, 7), noise(48, 20, 8)};
        double worst = 0;
        int interpolatedPixels = 0;
        int exactPixels = 0;
        for (int k = 0; k < 30; k++) {
            ScreenTriangles t = new ScreenTriangles();
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            t.add(x, y, 1, 0, 0,
                    x + rnd.nextGaussian() * 50, y + rnd.nextGaussian() * 50, 0.05 + rnd.nextDouble(), 700, 40,
                    x + rnd.nextGaussian() * 50, y + rnd.nextGaussian() * 50, 0.05 + rnd.nextDouble(), -60, 500,
                    k, k % 2);
            double[] result = checkLevelOfDetail(t, textures, k % 2, "triangle " + k);
            worst = Math.max(worst, result[0]);
            interpolatedPixels += (int) result[1];
            exactPixels += (int) result[2];
        }
        // Runs this steep are often curved beyond the chord bound (nearlyLinear), so a large share is exact.
        assertTrue(interpolatedPixels > exactPixels, interpolatedPixels + " interpolated, " + exactPixels + " exact");
        assertTrue(exactPixels > 0, "some runs are too curved to interpolate");
        assertTrue(worst < 0.012, "worst lambda error " + worst);
    }

    /**
     * Fills one perspective triangle (material {@code texture}) with trilinear filtering, checks every
     * pixel against the documented rule, bit for bit, and
     * returns {worst error of an interpolated lambda (clamped to the levels), interpolated pixels,
     * exact pixels}.
     */
    private static double[] checkLevelOfDetail(ScreenTriangles t, Texture[] textures, int texture, String what) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.clearRows(0, H, 0);
        Rasterizer r = new Rasterizer();
        r.filter(TextureFilter.TRILINEAR);
        r.fill(fb, t, all(t), 0, 1, textures, true, 0, 0, W, H);
        if (r.setup().rowEnd <= r.setup().rowStart || r.spans().length < 2 * (r.setup().rowEnd - r.setup().rowStart)) {
            // Nothing set up: the triangle covers no pixel centre of the frame.
            return new double[3];
        }
        MipChain mips = textures[texture].mipChain();
        double worst = 0;
        int interpolatedPixels = 0;
        int exactPixels = 0;
        for (int py = r.setup().rowStart, j = 0; py < r.setup().rowEnd; py++, j += 2) {
            for (int px = r.spans()[j]; px < r.spans()[j + 1]; px++) {
                assertEquals(Integer.toHexString(expectedTrilinear(r, mips, px, py)),
                        Integer.toHexString(fb.colour()[py * W + px]), what + " pixel " + px + "," + py);
                double q = r.setup().qPlane.base + r.setup().qPlane.dy * py + r.setup().qPlane.dx * px;
                double exact = Lod.lambdaPerspective((r.setup().sPlane.base + r.setup().sPlane.dy * py + r.setup().sPlane.dx * px) / q,
                        (r.setup().tPlane.base + r.setup().tPlane.dy * py + r.setup().tPlane.dx * px) / q, 1 / q, r.setup().sPlane.dx, r.setup().sPlane.dy,
                        r.setup().tPlane.dx, r.setup().tPlane.dy, r.setup().qPlane.dx, r.setup().qPlane.dy);
                double interpolated = interpolatedLambda(r, mips, px, py) / 256;
                if (Double.isNaN(interpolated)) {
                    exactPixels++;
                } else {
                    // The lambda that selects levels: clamped to [0, last level].
                    worst = Math.max(worst, Math.abs(clamp(interpolated, mips) - clamp(exact, mips)));
                    interpolatedPixels++;
                }
            }
        }
        return new double[] {worst, interpolatedPixels, exactPixels};
    }

    @Test
    void interpolatedLevelOfDetailStaysWithinItsBoundOnEdgeOnSliversAndSteepTriangles() {
        // Triangles of a 3D view space projected with perspective (focal length 60 pixels), whose
        // lambda along y can dip and rise within a run of 8 columns where the texture's derivative
        // along y nearly vanishes: random steep ones (depths spread 0.3x to 3x) and slivers seen nearly
        // edge-on (their plane almost contains the view ray). Every pixel is the documented rule's
        // colour, and every interpolated lambda is within the documented 3/256 level of the exact one:
        // the chord bound (1/256) plus the two quantizations to 1/256.
        Random rnd = new Random(99);
        Texture[] textures = {noise(256, 256, 7)};
        double[] totals = new double[6];
        for (int k = 0; k < 3000; k++) {
            boolean sliver = k % 2 == 1;
            double[] v = new double[15];
            double cx = rnd.nextGaussian() * 2;
            double cy = rnd.nextGaussian() * 2;
            double cz = 0.2 + rnd.nextDouble() * 10;
            // A sliver's plane holds the ray to its first corner and a random direction, tilted by a little.
            double len = Math.sqrt(cx * cx + cy * cy + cz * cz);
            double ex = rnd.nextGaussian();
            double ey = rnd.nextGaussian();
            double ez = rnd.nextGaussian();
            double tilt = 0.03 * rnd.nextGaussian();
            double so = rnd.nextInt(3) == 0 ? 0 : rnd.nextGaussian() * 300;
            double to = rnd.nextInt(3) == 0 ? 0 : rnd.nextGaussian() * 300;
            for (int c = 0; c < 3; c++) {
                double px;
                double py;
                double pz;
                if (sliver) {
                    double along = c == 2 ? rnd.nextDouble() * 3 * len : 0;
                    double side = c == 0 ? 0 : rnd.nextGaussian() * 2;
                    px = cx + along * cx / len + side * ex + tilt * ey * c;
                    py = cy + along * cy / len + side * ey + tilt * ez * c;
                    pz = cz + along * cz / len + side * ez + tilt * ex * c;
                } else {
                    px = cx + rnd.nextGaussian() * 3;
                    py = cy + rnd.nextGaussian() * 0.3;
                    pz = cz * (0.3 + rnd.nextDouble() * 2.7);
                }
                pz = Math.max(pz, 0.05);
                v[5 * c] = W / 2.0 + 60 * px / pz;
                v[5 * c + 1] = H / 2.0 - 60 * py / pz;
                v[5 * c + 2] = 1 / pz;
                v[5 * c + 3] = so + rnd.nextGaussian() * 200;
                v[5 * c + 4] = to + rnd.nextGaussian() * 200;
            }
            ScreenTriangles t = new ScreenTriangles();
            t.add(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], k, 0);
            double[] result = checkLevelOfDetail(t, textures, 0, (sliver ? "sliver " : "triangle ") + k);
            int o = sliver ? 3 : 0;
            totals[o] = Math.max(totals[o], result[0]);
            totals[o + 1] += result[1];
            totals[o + 2] += result[2];
        }
        String summary = "steep: worst " + totals[0] + " over " + totals[1] + " interpolated, " + totals[2]
                + " exact; slivers: worst " + totals[3] + " over " + totals[4] + " interpolated, " + totals[5] + " exact";
        // Not vacuous: both kinds cover pixels, most interpolated, some runs too curved to be.
        assertTrue(totals[1] > totals[2] && totals[2] > 0, summary);
        assertTrue(totals[4] > 200 && totals[5] > 0, summary);
        assertTrue(totals[0] < 3.0 / 256 && totals[3] < 3.0 / 256, summary);
    }

    @Test
    void fillingInTilesGivesTheSamePixels() {
        Random rnd = new Random(5);
        ScreenTriangles t = new ScreenTriangles();
        for (int k = 0; k < 60; k++) {
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            t.add(x, y, 0.1 + rnd.nextDouble(), 3 * x, 5 * y,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 0.1 + rnd.nextDouble(), 170, -4,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 0.1 + rnd.nextDouble(), -9, 400,
                    k, k % 2);
        }
        Texture[] textures = {noise(16, 16, 3), noise(5, 7, 4)};
        for (TextureFilter filter : new TextureFilter[] {TextureFilter.BILINEAR, TextureFilter.TRILINEAR}) {
            for (boolean perspective : new boolean[] {true, false}) {
                Framebuffer whole = fill(t, textures, filter, perspective);
                Framebuffer tiled = new Framebuffer(W, H);
                tiled.recordUv(true);
                tiled.clearRows(0, H, 0);
                Rasterizer r = new Rasterizer();
                r.filter(filter);
                for (int ty = 0; ty < H; ty += 7) {
                    for (int tx = 0; tx < W; tx += 11) {
                        r.fill(tiled, t, all(t), 0, t.count(), textures, perspective, tx, ty,
                                Math.min(W, tx + 11), Math.min(H, ty + 7));
                    }
                }
                assertArrayEquals(whole.colour(), tiled.colour(), filter + " " + perspective);
                assertArrayEquals(whole.uv(), tiled.uv());
                // The UV output does not depend on the filter.
                assertArrayEquals(fill(t, textures, TextureFilter.NEAREST, perspective).uv(), whole.uv());
            }
        }
    }
}
