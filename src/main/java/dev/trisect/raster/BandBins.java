package dev.trisect.raster;

import java.util.Arrays;

/**
 * Items sorted into the bands of rows of a frame, each band's list in item order: the one binning of
 * a frame's commands ({@link Commands}: per chunk for the fill, the frame's lines and quads, and per
 * {@link OutlinePlan} the overlay's edges). An item is given the rows its pixels can fall on; it is listed in every band
 * of {@code bandRows} rows that holds one of them.
 *
 * <p>Use: {@link #prepare} for n items, {@link #rows} or {@link #none} for each, {@link #build};
 * then band b's items are {@code items()[start(b) .. start(b + 1))}. Storage is kept from use to
 * use; {@link #shrink} gives it back.
 */
public final class BandBins {
    /** Band b's items are {@code items[start[b] .. start[b + 1])}. */
    private int[] start = new int[1];
    private int[] items = new int[0];
    private int[] firstBand = new int[0];
    private int[] lastBand = new int[0];
    /** List entries the last {@link #build} made. */
    private int entries;

    /** The number of bands of {@code bandRows} rows that a frame {@code height} rows high has. */
    public static int bandCount(int height, int bandRows) {
        return (height + bandRows - 1) / bandRows;
    }

    /** Makes room for {@code n} items, growing to at least twice the room held. */
    public void prepare(int n) {
        if (firstBand.length < n) {
            firstBand = new int[Math.max(n, 2 * firstBand.length)];
            lastBand = new int[firstBand.length];
        }
    }

    /** Item {@code i} can light rows {@code firstRow..lastRow} (inclusive, within the frame, not empty). */
    public void rows(int i, int firstRow, int lastRow, int bandRows) {
        firstBand[i] = firstRow / bandRows;
        lastBand[i] = lastRow / bandRows;
    }

    /** Item {@code i} lights no row of the frame. */
    public void none(int i) {
        firstBand[i] = 1;
        lastBand[i] = 0;
    }

    /** Lists items 0..n-1 in the bands {@link #rows} gave them, keeping their order within a band. */
    public void build(int n, int bands) {
        if (start.length < bands + 1) {
            start = new int[bands + 1];
        }
        Arrays.fill(start, 0, bands + 1, 0);
        int total = 0;
        for (int i = 0; i < n; i++) {
            for (int b = firstBand[i]; b <= lastBand[i]; b++) {
                start[b + 1]++;
            }
            total += lastBand[i] - firstBand[i] + 1;
        }
        for (int b = 0; b < bands; b++) {
            start[b + 1] += start[b];
        }
        if (items.length < total) {
            items = new int[Math.max(total, 2 * items.length)];
        }
        entries = total;
        // Fill each band's list in item order, using start as moving cursors, then restore.
        for (int i = 0; i < n; i++) {
            for (int b = firstBand[i]; b <= lastBand[i]; b++) {
                items[start[b]++] = i;
            }
        }
        for (int b = bands; b > 0; b--) {
            start[b] = start[b - 1];
        }
        start[0] = 0;
    }

    /** The lists of all bands, one after another (see {@link #start}). */
    public int[] items() {
        return items;
    }

    /** Where band {@code b}'s list starts in {@link #items()}; it ends where band b + 1's starts. */
    public int start(int b) {
        return start[b];
    }

    /** List entries the last {@link #build} made (an item in k bands counts k times). */
    public int entries() {
        return entries;
    }

    /** Room for list entries held now. */
    public int entryCapacity() {
        return items.length;
    }

    /**
     * Reallocates the per-item storage to hold {@code itemCapacity} items and the lists to at most
     * {@code entryCapacity} entries, giving the rest back to the garbage collector. The contents are
     * lost: call {@link #prepare} and {@link #build} again before reading.
     */
    public void shrink(int itemCapacity, int entryCapacity) {
        items = new int[Math.min(items.length, entryCapacity)];
        firstBand = new int[Math.min(firstBand.length, itemCapacity)];
        lastBand = new int[firstBand.length];
    }
}
