package dev.trisect.raster;

import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * Lit copies of textures, kept from frame to frame (the idea of Quake's surface cache: texels lit once
 * and reused): for a texture and one colour, the texture with every texel modulated by that colour
 * ({@link Modulate#argb16}, alpha kept). A triangle whose colour is one colour ({@link PixelState#CONSTANT})
 * and whose texture is sampled nearest is then drawn by the plain texel loop over the copy: the nearest
 * texel of the copy is, bit for bit, the modulated nearest texel, so the pixels are those of the
 * modulating loop without its per-pixel multiply. Filtered sampling keeps the modulating loops:
 * modulating before filtering would round differently.
 *
 * <p>When a copy is built — the rule (docs/conventions.md, "Light"). Per frame and per (texture,
 * colour), the <em>demand</em> is the covered pixels of the triangles wanting that key, counted in
 * runs (consecutive triangles of one thread with the same material and colour; a run shorter than
 * {@link #minRun} pixels is not counted, so demand is a lower bound and a scene of tiny triangles of
 * distinct colours costs a comparison per triangle). A key is built, between frames, when its demand
 * in the frame just drawn reaches a quarter of the texture's texels ({@link #PIXELS_PER_TEXEL}: the
 * build's per-texel multiply then pays back within four frames of use) and it had such a demand in
 * another of the last {@link #WANT_WINDOW} frames too: a key is built on its second asking, so a
 * moving light, whose colours change every frame, builds nothing. A copy not used for
 * {@link #UNUSED_FRAMES} frames is dropped, and the copies never hold more than the budget's bytes
 * (the least recently used go first; a key that does not fit is not built); a texture gets at most
 * {@link #MAX_PER_TEXTURE} copies.
 *
 * <p>Threads: one {@link Lane} per filling thread, touched by that thread alone during a frame; this
 * object changes only in {@link #begin}, {@link #end} and {@link #clear}, between frames, on the thread
 * that renders.
 * One per renderer.
 */
public final class LitTextures {
    /** A key is built when a frame's demand for it is at least its texture's texels divided by this. */
    static final int PIXELS_PER_TEXEL = 4;
    /** A key wanted again within this many frames is built. */
    static final int WANT_WINDOW = 8;
    /** A copy not used for this many frames is dropped. */
    static final int UNUSED_FRAMES = 8;
    /** The most copies of one texture (colours) kept at once. */
    static final int MAX_PER_TEXTURE = 16;
    /** The copies' bytes a renderer keeps by default: 32 MiB. */
    public static final long DEFAULT_BUDGET = 32L << 20;
    /** The most runs a lane notes per frame; later ones are not counted. */
    private static final int MAX_RUNS = 256;

    /** A texture and a colour ({@link #colourKey}); the texture compared by identity. */
    private record Key(Texture texture, long colour) {
    }

    /** A built copy. */
    private static final class Entry {
        final Key key;
        final Texture lit;
        long lastUsed;

        Entry(Key key, Texture lit, long frame) {
            this.key = key;
            this.lit = lit;
            this.lastUsed = frame;
        }
    }

    private final long budget;
    private final Lane[] lanes;
    private final List<Entry> entries = new ArrayList<>();
    /** Keys wanted enough in a recent frame and not built, with that frame. */
    private final Map<Key, Long> wanted = new HashMap<>();
    /** Frames ended. */
    private long frame;
    private long bytes;
    /** Triangles drawn from a copy in the last frame. */
    private long hits;
    /** The frame's textures, by material index, from {@link #begin}. */
    private Texture[] textures = new Texture[0];
    /** Per material of the frame: the colours of its texture's copies, and their entry indices. */
    private long[][] colours = new long[0][];
    private int[][] entryOf = new int[0][];
    /** Per material: the fewest pixels a run must cover to be counted. */
    private int[] minRuns = new int[0];

    /**
     * @param threads the threads that fill, one {@link Lane} each
     * @param budget  the most bytes the copies may hold
     */
    public LitTextures(int threads, long budget) {
        if (threads < 1 || budget < 0) {
            throw new IllegalArgumentException("threads must be at least 1 and the budget not negative, got "
                    + threads + " and " + budget);
        }
        this.budget = budget;
        lanes = new Lane[threads];
        for (int i = 0; i < threads; i++) {
            lanes[i] = new Lane(this);
        }
    }

    /** The lane of filling thread {@code thread}, for its {@link Rasterizer#lit}. */
    public Lane lane(int thread) {
        return lanes[thread];
    }

    /**
     * Starts a frame whose materials show {@code frameTextures} (by material index): each material's
     * copies are looked up once here, so that a triangle's look-up is a scan of a few colours.
     *
     * @param frameTextures read during the frame, not kept after {@link #end}; null past the frame's materials
     */
    public void begin(Texture[] frameTextures) {
        int n = frameTextures.length;
        textures = frameTextures;
        colours = new long[n][];
        entryOf = new int[n][];
        minRuns = new int[n];
        Map<Texture, List<Integer>> byTexture = new java.util.IdentityHashMap<>();
        for (int e = 0; e < entries.size(); e++) {
            byTexture.computeIfAbsent(entries.get(e).key.texture(), k -> new ArrayList<>()).add(e);
        }
        for (int m = 0; m < n; m++) {
            Texture t = frameTextures[m];
            if (t == null) {
                continue; // room beyond the frame's materials
            }
            minRuns[m] = minRun(t);
            List<Integer> es = byTexture.get(t);
            if (es != null) {
                colours[m] = new long[es.size()];
                entryOf[m] = new int[es.size()];
                for (int i = 0; i < es.size(); i++) {
                    entryOf[m][i] = es.get(i);
                    colours[m][i] = entries.get(es.get(i)).key.colour();
                }
            }
        }
        for (Lane lane : lanes) {
            lane.reset(entries.size());
        }
    }

    /**
     * Ends the frame begun by {@link #begin}: notes which copies were used, builds the keys the rule
     * admits, and drops the copies unused for {@link #UNUSED_FRAMES} frames. On the rendering thread,
     * after every filling thread is done.
     */
    public void end() {
        frame++;
        hits = 0;
        Map<Key, Long> demand = new HashMap<>();
        for (Lane lane : lanes) {
            lane.flush();
            hits += lane.hits;
            for (int e = 0; e < entries.size(); e++) {
                if (lane.used[e]) {
                    entries.get(e).lastUsed = frame;
                }
            }
            for (int r = 0; r < lane.runs; r++) {
                Key key = new Key(textures[lane.runMaterials[r]], lane.runColours[r]);
                demand.merge(key, lane.runPixels[r], Long::sum);
            }
        }
        entries.removeIf(e -> frame - e.lastUsed >= UNUSED_FRAMES && drop(e));
        wanted.values().removeIf(f -> frame - f > WANT_WINDOW);
        for (Map.Entry<Key, Long> d : demand.entrySet()) {
            Key key = d.getKey();
            Texture t = key.texture();
            if (d.getValue() * PIXELS_PER_TEXEL < (long) t.width() * t.height() || built(key)) {
                continue;
            }
            Long before = wanted.put(key, frame);
            if (before != null && makeRoom(t)) {
                wanted.remove(key);
                entries.add(new Entry(key, build(t, key.colour()), frame));
                bytes += 4L * t.width() * t.height();
            }
        }
        textures = new Texture[0];
    }

    /** Whether {@code key} has a copy. */
    private boolean built(Key key) {
        for (Entry e : entries) {
            if (e.key.equals(key)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Makes room for one more copy of {@code t}, dropping the least recently used copies not used in
     * this frame while the budget is short; whether there is room. When even dropping all of those
     * would not make room, drops nothing.
     */
    private boolean makeRoom(Texture t) {
        long need = 4L * t.width() * t.height();
        int same = 0;
        for (Entry e : entries) {
            same += e.key.texture() == t ? 1 : 0;
        }
        if (same >= MAX_PER_TEXTURE || need > budget) {
            return false;
        }
        // Nothing is dropped unless dropping every copy not used in this frame would make room:
        // otherwise a key that cannot fit would cost other copies each frame it is asked.
        long freeable = 0;
        for (Entry e : entries) {
            freeable += e.lastUsed < frame ? 4L * e.lit.width() * e.lit.height() : 0;
        }
        if (bytes - freeable + need > budget) {
            return false;
        }
        while (bytes + need > budget) {
            Entry oldest = null;
            for (Entry e : entries) {
                if (e.lastUsed < frame && (oldest == null || e.lastUsed < oldest.lastUsed)) {
                    oldest = e;
                }
            }
            if (oldest == null) {
                return false;
            }
            entries.remove(oldest);
            drop(oldest);
        }
        return true;
    }

    /** Accounts for {@code e} leaving; true, for {@code removeIf}. */
    private boolean drop(Entry e) {
        bytes -= 4L * e.lit.width() * e.lit.height();
        return true;
    }

    /** {@code t} with every texel modulated by {@code colour} ({@link #colourKey}), alpha kept. */
    static Texture build(Texture t, long colour) {
        int r16 = channel16(colour, 0);
        int g16 = channel16(colour, 1);
        int b16 = channel16(colour, 2);
        int[] src = t.argb();
        int[] lit = new int[src.length];
        for (int i = 0; i < src.length; i++) {
            lit[i] = Modulate.argb16(src[i], r16, g16, b16);
        }
        return new Texture(t.name() + " lit", t.width(), t.height(), lit);
    }

    /** Colour (r16, g16, b16), each 0..{@link Modulate#ONE}, as one number: 17 bits each. */
    static long colourKey(int r16, int g16, int b16) {
        return (long) r16 << 34 | (long) g16 << 17 | b16;
    }

    /** Channel {@code k} (0 red, 1 green, 2 blue) of a {@link #colourKey}: 0..{@link Modulate#ONE}. */
    static int channel16(long colour, int k) {
        return (int) (colour >>> 17 * (2 - k)) & 0x1FFFF;
    }

    /** The fewest covered pixels a run of triangles showing {@code t} must have to be counted. */
    static int minRun(Texture t) {
        return Math.max(32, t.width() * t.height() >> 8);
    }

    /** Drops every copy and every noted wanting: for when the scene is replaced. */
    public void clear() {
        entries.clear();
        wanted.clear();
        bytes = 0;
    }

    /** How many copies are kept. */
    public int size() {
        return entries.size();
    }

    /** The bytes the copies hold. */
    public long bytes() {
        return bytes;
    }

    /** Triangle fills (one per band a triangle crosses) drawn from a copy in the frame last ended. */
    public long hits() {
        return hits;
    }

    /**
     * One filling thread's side of the cache: looks up a triangle's copy and counts what the frame
     * wants. Touched by its thread alone between {@link LitTextures#begin} and {@link LitTextures#end}.
     */
    public static final class Lane {
        private final LitTextures owner;
        /** The run: consecutive triangles with one material and colour, its entry (or -1) and pixels. */
        private int runMaterial = -1;
        private long runColour;
        private int runEntry = -1;
        private Texture runLit;
        private long runCovered;
        /** The runs counted this frame. */
        private final int[] runMaterials = new int[MAX_RUNS];
        private final long[] runColours = new long[MAX_RUNS];
        private final long[] runPixels = new long[MAX_RUNS];
        private int runs;
        private boolean[] used = new boolean[0];
        private long hits;

        private Lane(LitTextures owner) {
            this.owner = owner;
        }

        private void reset(int entryCount) {
            runMaterial = -1;
            runEntry = -1;
            runLit = null;
            runCovered = 0;
            runs = 0;
            hits = 0;
            if (used.length < entryCount) {
                used = new boolean[entryCount];
            }
            java.util.Arrays.fill(used, false);
        }

        /**
         * The copy of {@code material}'s texture modulated by the colour in {@code t} (its colourKey),
         * or null when there is none: the triangle's covered pixels, from {@code spans}, are
         * then counted as demand for it.
         */
        Texture lit(int material, TriangleSetup t, int[] spans) {
            Texture copy = start(material, t.colourKey);
            if (copy == null) {
                long covered = 0;
                for (int j = 0, rows = 2 * (t.rowEnd - t.rowStart); j < rows; j += 2) {
                    covered += spans[j + 1] - spans[j];
                }
                runCovered += covered;
            }
            return copy;
        }

        /** As {@link #lit(int, TriangleSetup, int[])} for a triangle of colour {@code colour} covering {@code covered} pixels. */
        Texture lit(int material, long colour, long covered) {
            Texture copy = start(material, colour);
            if (copy == null) {
                runCovered += covered;
            }
            return copy;
        }

        /** Continues the run, or ends it and starts one of {@code material} and {@code colour}; its copy or null. */
        private Texture start(int material, long colour) {
            if (material != runMaterial || colour != runColour) {
                flush();
                runMaterial = material;
                runColour = colour;
                runEntry = owner.find(material, colour);
                runLit = null;
                if (runEntry >= 0) {
                    used[runEntry] = true;
                    runLit = owner.entries.get(runEntry).lit;
                }
            }
            if (runLit != null) {
                hits++;
            }
            return runLit;
        }

        /** Counts the current run when it wants a copy and is long enough; ends it. */
        private void flush() {
            if (runMaterial >= 0 && runEntry < 0 && runs < MAX_RUNS && runCovered >= owner.minRuns[runMaterial]) {
                runMaterials[runs] = runMaterial;
                runColours[runs] = runColour;
                runPixels[runs] = runCovered;
                runs++;
            }
            runMaterial = -1;
            runEntry = -1;
            runLit = null;
            runCovered = 0;
        }
    }

    /** The entry of {@code material}'s texture modulated by {@code colour}, or -1. */
    private int find(int material, long colour) {
        long[] cs = colours[material];
        if (cs != null) {
            for (int i = 0; i < cs.length; i++) {
                if (cs[i] == colour) {
                    return entryOf[material][i];
                }
            }
        }
        return -1;
    }
}
