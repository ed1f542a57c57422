package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.content.SceneAsset;
import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.scene.internal.BlendOrder;
import dev.trisect.texture.Texture;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/**
 * Light and fog, as the OpenGL reference takes them (glref's {@code GLREF_*} variables): one
 * directional light, one point light, the scene's ambient colour, the shading of every material, and
 * fog. Shared by render, compare, bench and export.
 */
final class LightOptions {
    /** OpenGL's default scene ambient ({@code GL_LIGHT_MODEL_AMBIENT}), and glref's. */
    static final double DEFAULT_AMBIENT = 0.2;

    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    @Option(names = "--light", paramLabel = "dx,dy,dz", converter = DirectionConverter.class,
            description = "A directional light shining from this world-space direction (lights every material; "
                    + "see --shade).")
    Vec3 light;

    @Option(names = "--light-colour", paramLabel = "r,g,b", converter = ColourTriple.class,
            description = "The directional light's colour, r,g,b or one grey level, each at least 0 (1 is full "
                    + "intensity; more brightens) (default: 1,1,1).")
    Colour lightColour;

    @Option(names = "--point", paramLabel = "x,y,z", converter = Converters.Vec3Converter.class,
            description = "A point light at this world-space position.")
    Vec3 point;

    @Option(names = "--point-colour", paramLabel = "r,g,b", converter = ColourTriple.class,
            description = "The point light's colour, r,g,b or one grey level, each at least 0 (1 is full "
                    + "intensity; more brightens) (default: 1,1,1).")
    Colour pointColour;

    @Option(names = "--attenuation", paramLabel = "kc,kl,kq", converter = AttenuationConverter.class,
            description = "The point light's attenuation 1/(kc + kl d + kq d^2) (default: 1,0,0).")
    Vec3 attenuation;

    @Option(names = "--ambient", paramLabel = "r,g,b", converter = ColourTriple.class,
            description = "The scene's ambient light, a grey level or r,g,b (default with a light: 0.2).")
    Colour ambient;

    @Option(names = "--shade", paramLabel = "none|flat|smooth", converter = ShadeConverter.class,
            description = "How every material is lit (default: smooth with a light, none without).")
    Shading shade;

    @Option(names = "--fog", paramLabel = "linear,S,E|exp,D|exp2,D", converter = FogConverter.class,
            description = "OpenGL's fog by eye-space depth: linear from S to E, or exp/exp2 with density D.")
    Fog fog;

    @Option(names = "--fog-colour", paramLabel = "r,g,b", converter = ColourTriple.class,
            description = "The fog's colour, r,g,b or one grey level, each at least 0 (above 1 acts as 1) "
                    + "(default: 0,0,0).")
    Colour fogColour;

    /** Whether any light is given. */
    private boolean anyLight() {
        return light != null || point != null || ambient != null;
    }

    /** The first light or fog option given ({@code --light}, {@code --point}, ...), or null for none. */
    String given() {
        return light != null ? "--light" : point != null ? "--point" : ambient != null ? "--ambient"
                : shade != null ? "--shade" : fog != null ? "--fog" : null;
    }

    /** Checks the combinations; every message names the option. */
    void check() {
        if (lightColour != null && light == null) {
            throw InputException.usage("--light-colour applies to --light, which is not given");
        }
        if ((pointColour != null || attenuation != null) && point == null) {
            throw InputException.usage((pointColour != null ? "--point-colour" : "--attenuation")
                    + " applies to --point, which is not given");
        }
        if (attenuation != null) {
            double kc = attenuation.x();
            double kl = attenuation.y();
            double kq = attenuation.z();
            if (!(kc >= 0 && kl >= 0 && kq >= 0) || kc + kl + kq == 0) {
                throw InputException.usage("--attenuation needs kc,kl,kq at least 0 and not all 0, got "
                        + kc + "," + kl + "," + kq);
            }
        }
        if (light != null && light.normalize().length() == 0) {
            throw InputException.usage("--light needs a non-zero direction, got " + triple(light.x(), light.y(),
                    light.z()));
        }
        if (shade != null && shade != Shading.NONE && !anyLight()) {
            throw InputException.usage("--shade " + shade.name().toLowerCase(Locale.ROOT)
                    + " needs a light: give --light, --point or --ambient");
        }
        if (fogColour != null && fog == null) {
            throw InputException.usage("--fog-colour applies to --fog, which is not given");
        }
    }

    /**
     * One draw of {@code mesh}, world space = object space, every material lit as the options say,
     * with the lights and the fog: what compare and bench draw. Each material is written as its
     * texture's alpha says (opaque, alpha-tested, blended: {@link BlendOrder#states(Texture[])}), its
     * triangles in file order, as the view draws the model as one object.
     */
    Draws draws(Mesh mesh, Texture[] textures, Mat4 viewProjection) {
        return draws(mesh, textures, BlendOrder.states(textures), viewProjection);
    }

    /** As {@link #draws(Mesh, Texture[], Mat4)}, each material with the given pixel state (lit ones modulated). */
    Draws draws(Mesh mesh, Texture[] textures, int[] states, Mat4 viewProjection) {
        Draws d = new Draws();
        Surface[] surfaces = new Surface[mesh.materialCount()];
        Arrays.fill(surfaces, new Surface(shading(), Colour.WHITE, Colour.WHITE));
        d.add(mesh, textures, states, viewProjection, Mat4.identity(), surfaces);
        d.setLights(lights());
        d.setFog(fog().orElse(null));
        return d;
    }

    /**
     * As {@link #draws(Mesh, Texture[], Mat4)} for {@code scene}'s mesh drawn with {@code textures},
     * then its lines (if any) {@code lineWidth} pixels wide: what render and bench draw.
     */
    Draws draws(SceneAsset scene, Texture[] textures, Mat4 viewProjection, int lineWidth) {
        Draws d = draws(scene.mesh(), textures, viewProjection);
        if (!scene.lines().isEmpty()) {
            d.addLines(scene.lines(), viewProjection, lineWidth);
        }
        return d;
    }

    /** How every material is lit. */
    Shading shading() {
        check();
        return shade != null ? shade : anyLight() ? Shading.SMOOTH : Shading.NONE;
    }

    /** The lights, world space; {@link Lights#NONE} without any. */
    Lights lights() {
        check();
        if (!anyLight()) {
            return Lights.NONE;
        }
        Lights.Builder b = Lights.builder();
        Colour a = ambient != null ? ambient : Colour.grey(DEFAULT_AMBIENT);
        b.ambient(a.r(), a.g(), a.b());
        double[] black = new double[3];
        if (light != null) {
            Vec3 d = direction();
            b.directional(d.x(), d.y(), d.z(), black, rgb(lightColour));
        }
        if (point != null) {
            Vec3 k = attenuation != null ? attenuation : new Vec3(1, 0, 0);
            b.point(point.x(), point.y(), point.z(), black, rgb(pointColour), k.x(), k.y(), k.z());
        }
        return b.build();
    }

    /**
     * The --light direction, of any finite non-zero length as Light.directional takes: where its squared
     * length would underflow or overflow (1e-300 or 1e300) the unit vector, otherwise as given, bit for
     * bit, so that frames and glref's variables are unchanged.
     */
    private Vec3 direction() {
        double length = light.length();
        return length > 1e-150 && length < 1e150 ? light : light.normalize();
    }

    /** The fog, with its colour. */
    Optional<Fog> fog() {
        check();
        if (fog == null) {
            return Optional.empty();
        }
        Colour c = fogColour != null ? fogColour : Colour.BLACK;
        return Optional.of(new Fog(fog.mode(), fog.start(), fog.end(), fog.density(), c));
    }

    /**
     * The light and fog a frame was drawn with, for compare's and bench's JSON lines: nothing without a
     * light or fog option; with a light, its values in force (defaults included: the shading, the
     * ambient colour, each light's colour and the point light's attenuation); the fog with its colour.
     * Each light is a field as given (a direction is not normalised).
     */
    JsonObject json() {
        check();
        JsonObject j = new JsonObject();
        if (light != null) {
            j.put("light", new JsonObject().put("direction", list(light.x(), light.y(), light.z()))
                    .put("colour", list(lightColour != null ? lightColour : Colour.WHITE)));
        }
        if (point != null) {
            Vec3 k = attenuation != null ? attenuation : new Vec3(1, 0, 0);
            j.put("point", new JsonObject().put("position", list(point.x(), point.y(), point.z()))
                    .put("colour", list(pointColour != null ? pointColour : Colour.WHITE))
                    .put("attenuation", list(k.x(), k.y(), k.z())));
        }
        if (anyLight()) {
            j.put("ambient", list(ambient != null ? ambient : Colour.grey(DEFAULT_AMBIENT)));
        }
        if (anyLight() || shade != null) {
            j.put("shade", shading().name().toLowerCase(Locale.ROOT));
        }
        fog().ifPresent(f -> {
            JsonObject o = new JsonObject().put("mode", f.mode().name().toLowerCase(Locale.ROOT));
            if (f.mode() == Fog.Mode.LINEAR) {
                o.put("start", f.start()).put("end", f.end());
            } else {
                o.put("density", f.density());
            }
            j.put("fog", o.put("colour", list(f.colour())));
        });
        return j;
    }

    private static List<Double> list(Colour c) {
        return list(c.r(), c.g(), c.b());
    }

    private static List<Double> list(double x, double y, double z) {
        return List.of(x, y, z);
    }

    /**
     * The same light and fog for glref, as the {@code GLREF_*} environment variables its README lists
     * (in order; empty without light and fog). glref lights only with a directional or point light.
     */
    Map<String, String> glrefEnvironment() {
        check();
        Map<String, String> env = new LinkedHashMap<>();
        if ((light != null || point != null) && shading() != Shading.NONE) {
            if (light != null) {
                Vec3 d = direction();
                env.put("GLREF_LIGHT", triple(d.x(), d.y(), d.z()));
                if (lightColour != null) {
                    env.put("GLREF_LIGHT_COLOUR", triple(lightColour));
                }
            }
            if (point != null) {
                env.put("GLREF_POINT", triple(point.x(), point.y(), point.z()));
                if (pointColour != null) {
                    env.put("GLREF_POINT_COLOUR", triple(pointColour));
                }
                if (attenuation != null) {
                    env.put("GLREF_ATTEN", triple(attenuation.x(), attenuation.y(), attenuation.z()));
                }
            }
            env.put("GLREF_AMBIENT", triple(ambient != null ? ambient : Colour.grey(DEFAULT_AMBIENT)));
            env.put("GLREF_SHADE", shading() == Shading.FLAT ? "flat" : "smooth");
        }
        fog().ifPresent(f -> {
            env.put("GLREF_FOG", switch (f.mode()) {
                case LINEAR -> "linear," + f.start() + "," + f.end();
                case EXP -> "exp," + f.density();
                case EXP2 -> "exp2," + f.density();
            });
            env.put("GLREF_FOG_COLOUR", triple(f.colour()));
        });
        return env;
    }

    private static String triple(Colour c) {
        return triple(c.r(), c.g(), c.b());
    }

    private static String triple(double x, double y, double z) {
        return x + "," + y + "," + z;
    }

    private static double[] rgb(Colour c) {
        Colour k = c != null ? c : Colour.WHITE;
        return new double[] {k.r(), k.g(), k.b()};
    }

    /** {@code r,g,b}, or one grey level: finite and at least 0. */
    static final class ColourTriple implements ITypeConverter<Colour> {
        @Override
        public Colour convert(String value) {
            String[] parts = value.split(",", -1);
            try {
                if (parts.length == 1) {
                    return Colour.grey(Double.parseDouble(parts[0].trim()));
                }
                if (parts.length == 3) {
                    return new Colour(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()),
                            Double.parseDouble(parts[2].trim()));
                }
            } catch (IllegalArgumentException e) {
                // a malformed number or a bad channel: the message below
            }
            throw new TypeConversionException(Converters.quote(value) + " is not a colour: use r,g,b (or one grey "
                    + "level), finite numbers at least 0, e.g. 1,0.8,0.5");
        }
    }

    /** {@code dx,dy,dz}: the direction towards a light. */
    static final class DirectionConverter extends Converters.Vec3Converter {
        DirectionConverter() {
            super("a direction: use three finite numbers dx,dy,dz, e.g. 1,2,3");
        }
    }

    /** {@code kc,kl,kq}: a point light's attenuation (their signs are checked with the other options). */
    static final class AttenuationConverter extends Converters.Vec3Converter {
        AttenuationConverter() {
            super("an attenuation: use three finite numbers kc,kl,kq, e.g. 1,0.2,0.05");
        }
    }

    /** {@code none}, {@code flat} or {@code smooth}. */
    static final class ShadeConverter extends Converters.NamedConverter<Shading> {
        ShadeConverter() {
            super(Shading.values(), "shading");
        }
    }

    /** {@code linear,S,E}, {@code exp,D} or {@code exp2,D}; the colour is set apart. */
    static final class FogConverter implements ITypeConverter<Fog> {
        @Override
        public Fog convert(String value) {
            String[] parts = value.split(",", -1);
            String kind = parts[0].trim().toLowerCase(Locale.ROOT);
            try {
                if (kind.equals("linear") && parts.length == 3) {
                    return Fog.linear(Double.parseDouble(parts[1].trim()), Double.parseDouble(parts[2].trim()),
                            Colour.BLACK);
                }
                if ((kind.equals("exp") || kind.equals("exp2")) && parts.length == 2) {
                    double density = Double.parseDouble(parts[1].trim());
                    return kind.equals("exp") ? Fog.exp(density, Colour.BLACK) : Fog.exp2(density, Colour.BLACK);
                }
            } catch (NumberFormatException e) {
                // a malformed number: the message below
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(Converters.quote(value) + " is not a fog: " + e.getMessage());
            }
            throw new TypeConversionException(Converters.quote(value) + " is not a fog: use linear,START,END or "
                    + "exp,DENSITY or exp2,DENSITY, e.g. linear,10,80");
        }
    }
}
