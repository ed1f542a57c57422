package dev.trisect.scene.internal;

import dev.trisect.math.Mat4;
import dev.trisect.raster.PixelState;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * The order a frame draws its objects in, and each material's write: objects with a blended material
 * ({@link Material.AlphaMode#BLEND}) after all the others, farthest first by the eye depth (clip w) of
 * their mesh's centre (the middle of its bounding box), so that each blends over what is behind it; the
 * others in scene order. Triangles within one blended object are not sorted (docs/conventions.md,
 * "Transparency"); objects at one depth keep their scene order. The command line's one-object
 * frames ({@code render --obj}) take their materials' writes from {@link #states(Texture[])}.
 */
public final class BlendOrder {
    private BlendOrder() {
    }

    /**
     * {@code placed} in drawing order.
     *
     * @param viewProjection world space to clip space
     * @return the objects that blend nothing in their order, then those that blend, farthest first
     */
    static List<Scene.Placed> order(List<Scene.Placed> placed, Mat4 viewProjection) {
        List<Scene.Placed> opaque = new ArrayList<>(placed.size());
        List<Scene.Placed> blended = new ArrayList<>();
        for (Scene.Placed o : placed) {
            if (o.filled() && blends(o.materials())) {
                blended.add(o);
            } else {
                opaque.add(o);
            }
        }
        if (blended.isEmpty()) {
            return placed;
        }
        double[] w = new double[blended.size()];
        for (int k = 0; k < w.length; k++) {
            w[k] = depth(blended.get(k), viewProjection);
        }
        List<Integer> index = new ArrayList<>();
        for (int k = 0; k < w.length; k++) {
            index.add(k);
        }
        // Farthest first; a stable sort keeps scene order among equal depths.
        index.sort(Comparator.comparingDouble(k -> -w[k]));
        for (int k : index) {
            opaque.add(blended.get(k));
        }
        return opaque;
    }

    private static boolean blends(List<Material> materials) {
        for (Material m : materials) {
            if (m.alphaMode() == Material.AlphaMode.BLEND) {
                return true;
            }
        }
        return false;
    }

    /** The clip w of the centre of {@code o}'s mesh's bounding box, world-placed. */
    private static double depth(Scene.Placed o, Mat4 viewProjection) {
        float[] p = o.mesh().positions();
        if (p.length == 0) {
            return 0;
        }
        double[] lo = {p[0], p[1], p[2]};
        double[] hi = {p[0], p[1], p[2]};
        for (int i = 0; i < p.length; i += 3) {
            for (int c = 0; c < 3; c++) {
                lo[c] = Math.min(lo[c], p[i + c]);
                hi[c] = Math.max(hi[c], p[i + c]);
            }
        }
        double[] clip = new double[4];
        viewProjection.mul(o.world()).transformPoint((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2,
                clip, 0);
        return clip[3];
    }

    /**
     * The pixel state of each material: its write ({@link PixelState#ALPHA_TEST}, {@link PixelState#BLEND}
     * or opaque) with the texel as its colour.
     *
     * @return one state per material
     */
    static int[] states(List<Material> materials) {
        int[] states = new int[materials.size()];
        for (int i = 0; i < states.length; i++) {
            states[i] = state(materials.get(i).alphaMode());
        }
        return states;
    }

    /**
     * The pixel state of a material showing each texture, as a scene object's: its write from the texture's
     * alpha ({@link Material#alphaMode()}: opaque, alpha-tested or blended) with the texel as its colour.
     * What the command line draws an OBJ's materials with, so that {@code render --obj} and the view
     * write a model alike.
     *
     * @param textures one per material
     * @return one state per material
     */
    public static int[] states(Texture[] textures) {
        int[] states = new int[textures.length];
        for (int i = 0; i < states.length; i++) {
            states[i] = state(Material.of(textures[i]).alphaMode());
        }
        return states;
    }

    private static int state(Material.AlphaMode mode) {
        return switch (mode) {
            case OPAQUE -> PixelState.TEXEL | PixelState.OPAQUE;
            case ALPHA_TEST -> PixelState.TEXEL | PixelState.ALPHA_TEST;
            case BLEND -> PixelState.TEXEL | PixelState.BLEND;
        };
    }
}
