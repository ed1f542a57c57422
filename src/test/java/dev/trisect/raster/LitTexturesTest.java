package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** When {@link LitTextures} builds a lit copy, what it holds, when it drops one, and its threads. */
class LitTexturesTest {
    /** A 32x32 texture of random texels, alpha included: 1024 texels, so a key needs 256 pixels a frame. */
    private static Texture texture(long seed) {
        Random random = new Random(seed);
        int[] argb = new int[32 * 32];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = random.nextInt();
        }
        return new Texture("random " + seed, 32, 32, argb);
    }

    private static final Texture A = texture(1);
    private static final Texture B = texture(2);
    private static final long GREY = LitTextures.colourKey(30000, 40000, 50000);
    private static final long RED = LitTextures.colourKey(65536, 0, 0);

    /** One frame of {@code lane 0} wanting {@code colour} on material 0 (texture {@code t}) over {@code pixels}. */
    private static Texture frame(LitTextures cache, Texture t, long colour, long pixels) {
        cache.begin(new Texture[] {t});
        Texture copy = cache.lane(0).lit(0, colour, pixels);
        cache.end();
        return copy;
    }

    @Test
    void theCopyIsEveryTexelModulatedWithItsAlphaKept() {
        Texture lit = LitTextures.build(A, GREY);
        assertEquals(A.width(), lit.width());
        assertEquals(A.height(), lit.height());
        for (int i = 0; i < A.argb().length; i++) {
            int texel = A.argb()[i];
            assertEquals(Modulate.argb16(texel, 30000, 40000, 50000), lit.argb()[i]);
            assertEquals(texel >>> 24, lit.argb()[i] >>> 24);
        }
    }

    @Test
    void aFlatColourIsTheKeyOfItsChannelsInSixteenBitsAndUnpacksToThem() {
        Random random = new Random(27);
        for (int i = 0; i < 10_000; i++) {
            // Some channels beyond [0, 1]: a colour a hair outside is clamped as the modulation clamps it.
            double r = random.nextDouble() * 1.2 - 0.1;
            double g = i == 0 ? 1 : random.nextDouble();
            double b = i == 0 ? 0 : random.nextDouble();
            int[] want = {Modulate.f16(r), Modulate.f16(g), Modulate.f16(b)};
            double flat = PixelState.flatColour(r, g, b);
            assertEquals(LitTextures.colourKey(want[0], want[1], want[2]), (long) flat);
            assertEquals(flat, Math.rint(flat), "an integer, exact in a double");
            for (int k = 0; k < 3; k++) {
                assertEquals(want[k], LitTextures.channel16((long) flat, k));
                assertEquals(want[k] / 65536.0, PixelState.flatChannel(flat, k));
            }
        }
    }

    @Test
    void aKeyIsBuiltOnItsSecondAskingAndUsedFromTheNextFrame() {
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        assertNull(frame(cache, A, GREY, 256));
        assertEquals(0, cache.size(), "one asking builds nothing");
        assertNull(frame(cache, A, GREY, 256));
        assertEquals(1, cache.size(), "built after the second");
        assertEquals(4096, cache.bytes());
        Texture copy = frame(cache, A, GREY, 256);
        assertNotNull(copy);
        assertEquals(1, cache.hits());
        assertEquals(LitTextures.build(A, GREY).argb()[7], copy.argb()[7]);
        assertSame(copy, frame(cache, A, GREY, 1), "a built copy serves any triangle");
    }

    @Test
    void aColourThatChangesEveryFrameBuildsNothing() {
        // A moving light: each frame's colour is new.
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 40; f++) {
            assertNull(frame(cache, A, LitTextures.colourKey(1000 + f, 2000, 3000), 100_000));
        }
        assertEquals(0, cache.size());
    }

    @Test
    void tooLittleDemandBuildsNothing() {
        // 255 pixels a frame is under a quarter of 1024 texels; and runs under 32 pixels are not counted.
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 5; f++) {
            assertNull(frame(cache, A, GREY, 255));
        }
        assertEquals(0, cache.size());
        for (int f = 0; f < 5; f++) {
            cache.begin(new Texture[] {A, A});
            for (int run = 0; run < 100; run++) {
                // Alternating materials end each run at 31 pixels.
                cache.lane(0).lit(run % 2, GREY, 31);
            }
            cache.end();
        }
        assertEquals(0, cache.size());
    }

    @Test
    void runsAddUpAcrossMaterialsOfOneTextureAndAcrossLanes() {
        LitTextures cache = new LitTextures(2, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 2; f++) {
            cache.begin(new Texture[] {A, A});
            // 4 runs of 64 pixels, two per lane, on two materials showing A: 256 in all.
            for (int lane = 0; lane < 2; lane++) {
                cache.lane(lane).lit(0, GREY, 64);
                cache.lane(lane).lit(1, GREY, 64);
            }
            cache.end();
        }
        assertEquals(1, cache.size());
    }

    @Test
    void keysOfFramesInterleavedWithOthersAreBuilt() {
        // Frames of two scenes in turn (a side-by-side benchmark): each key is asked every other frame.
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 4; f++) {
            frame(cache, f % 2 == 0 ? A : B, GREY, 1000);
        }
        assertEquals(2, cache.size());
        // Asked once every WANT_WINDOW + 1 frames: too rarely.
        LitTextures rare = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 4 * (LitTextures.WANT_WINDOW + 1); f++) {
            frame(rare, f % (LitTextures.WANT_WINDOW + 1) == 0 ? A : B, RED, f % (LitTextures.WANT_WINDOW + 1) == 0 ? 1000 : 0);
        }
        assertEquals(0, rare.size());
    }

    @Test
    void aCopyUnusedForEightFramesIsDropped() {
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        frame(cache, A, GREY, 256);
        frame(cache, A, GREY, 256);
        assertEquals(1, cache.size());
        for (int f = 1; f < LitTextures.UNUSED_FRAMES; f++) {
            frame(cache, B, RED, 0);
            assertEquals(1, cache.size(), "kept after " + f + " frames unused");
        }
        frame(cache, B, RED, 0);
        assertEquals(0, cache.size());
        assertEquals(0, cache.bytes());
    }

    @Test
    void theBudgetKeepsTheMostRecentlyUsedAndRefusesWhatDoesNotFit() {
        // Room for one 32x32 copy.
        LitTextures cache = new LitTextures(1, 4096);
        frame(cache, A, GREY, 256);
        frame(cache, A, GREY, 256);
        assertEquals(1, cache.size());
        // B wanted twice while A's copy is not used: A's copy makes way.
        frame(cache, B, GREY, 256);
        assertEquals(1, cache.size());
        frame(cache, B, GREY, 256);
        assertEquals(1, cache.size());
        assertNotNull(frame(cache, B, GREY, 1), "B's copy replaced A's");
        // Both wanted in the same frames: B's copy is used, so A's finds no room.
        for (int f = 0; f < 3; f++) {
            cache.begin(new Texture[] {A, B});
            cache.lane(0).lit(0, GREY, 256);
            assertNotNull(cache.lane(0).lit(1, GREY, 256), "B's copy stays while used");
            cache.end();
            assertEquals(4096, cache.bytes());
        }
        LitTextures none = new LitTextures(1, 4095);
        frame(none, A, GREY, 256);
        frame(none, A, GREY, 256);
        assertEquals(0, none.size(), "a copy larger than the budget is not built");
    }

    @Test
    void aKeyThatCannotFitDropsNothing() {
        // Room for three 32x32 copies; A's and C's are in use when D (64x32, two copies' worth) is
        // wanted, so dropping B's alone would not make room: B's must stay.
        Texture c = texture(3);
        Texture d = new Texture("random 64x32", 64, 32, new int[64 * 32]);
        LitTextures cache = new LitTextures(1, 3 * 4096);
        for (int f = 0; f < 2; f++) {
            cache.begin(new Texture[] {A, B, c});
            for (int m = 0; m < 3; m++) {
                cache.lane(0).lit(m, GREY, 256);
            }
            cache.end();
        }
        assertEquals(3, cache.size());
        for (int f = 0; f < 3; f++) {
            cache.begin(new Texture[] {A, c, d});
            assertNotNull(cache.lane(0).lit(0, GREY, 256));
            assertNotNull(cache.lane(0).lit(1, GREY, 256));
            assertNull(cache.lane(0).lit(2, GREY, 512));
            cache.end();
            assertEquals(3, cache.size(), "nothing dropped for a key that does not fit");
        }
        assertNotNull(frame(cache, B, GREY, 1), "B's copy kept");
    }

    @Test
    void lanesFilledOnTheirOwnThreadsCountAsOne() throws InterruptedException {
        // Two threads, each on its own lane, each wanting half of what builds a key: built as when one
        // lane wants it all.
        LitTextures cache = new LitTextures(2, LitTextures.DEFAULT_BUDGET);
        for (int f = 0; f < 3; f++) {
            cache.begin(new Texture[] {A, B});
            Thread[] threads = new Thread[2];
            for (int k = 0; k < 2; k++) {
                LitTextures.Lane lane = cache.lane(k);
                threads[k] = new Thread(() -> {
                    for (int run = 0; run < 4; run++) {
                        lane.lit(run % 2, GREY, 64);
                    }
                });
                threads[k].start();
            }
            for (Thread t : threads) {
                t.join();
            }
            cache.end();
        }
        assertEquals(2, cache.size());
        assertEquals(8, cache.hits(), "each lane's four triangles drew from the copies in the third frame");
    }

    @Test
    void clearDropsEverything() {
        LitTextures cache = new LitTextures(1, LitTextures.DEFAULT_BUDGET);
        frame(cache, A, GREY, 256);
        cache.clear();
        frame(cache, A, GREY, 256);
        assertEquals(0, cache.size(), "the first asking was forgotten");
        frame(cache, A, GREY, 256);
        assertEquals(1, cache.size());
        cache.clear();
        assertEquals(0, cache.bytes());
        assertNull(frame(cache, A, GREY, 256));
    }
}
