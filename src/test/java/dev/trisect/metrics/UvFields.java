package dev.trisect.metrics;

/** Builds synthetic UV buffers and colour images for the metrics tests. */
final class UvFields {
    private UvFields() {
    }

    /** A texel-coordinate map of a pixel centre; returns (s, t) through {@code out}. */
    interface Map {
        void at(double x, double y, double[] out);
    }

    /** Which triangle id (0 = none) covers pixel (x, y). */
    interface Ids {
        int at(int x, int y);
    }

    /** An affine map s = a x + b y + c, t = d x + e y + f. */
    static Map affine(double a, double b, double c, double d, double e, double f) {
        return (x, y, out) -> {
            out[0] = a * x + b * y + c;
            out[1] = d * x + e * y + f;
        };
    }

    /**
     * A UV buffer with the map evaluated at each pixel centre shifted by (dx, dy) pixels, so that the
     * texture appears moved by (-dx, -dy) on screen relative to the unshifted buffer.
     */
    static double[] buffer(int w, int h, Ids ids, Map map, double dx, double dy) {
        double[] uv = new double[3 * w * h];
        double[] st = new double[2];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int k = 3 * (y * w + x);
                int id = ids.at(x, y);
                if (id != 0) {
                    map.at(x + 0.5 + dx, y + 0.5 + dy, st);
                    uv[k] = st[0];
                    uv[k + 1] = st[1];
                    uv[k + 2] = id;
                }
            }
        }
        return uv;
    }

    /** {@link #buffer} with one triangle, id 1, covering every pixel. */
    static double[] oneTriangle(int w, int h, Map map, double dx, double dy) {
        return buffer(w, h, (x, y) -> 1, map, dx, dy);
    }

    /** s = x, t = y at the pixel centres: an identity Jacobian. */
    static final Map IDENTITY = affine(1, 0, 0, 0, 1, 0);

    /** Pixel (x, y)'s [s, t, id] written into a UV buffer of width w. */
    static void set(double[] uv, int w, int x, int y, double s, double t, int id) {
        int k = 3 * (y * w + x);
        uv[k] = s;
        uv[k + 1] = t;
        uv[k + 2] = id;
    }

    /** An opaque colour image of one colour. */
    static int[] solid(int w, int h, int argb) {
        int[] image = new int[w * h];
        java.util.Arrays.fill(image, argb);
        return image;
    }
}
