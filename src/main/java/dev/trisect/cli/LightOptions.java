package dev.trisect.cli;

import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.texture.Texture;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/**
 * Fog, as the OpenGL reference takes it (glref's {@code GLREF_FOG*} variables). Shared by render,
 * compare, bench and export.
 */
final class LightOptions {
    @Option(names = "--fog", paramLabel = "linear,S,E|exp,D|exp2,D", converter = FogConverter.class,
            description = "OpenGL's fog by eye-space depth: linear from S to E, or exp/exp2 with density D.")
    Fog fog;

    @Option(names = "--fog-colour", paramLabel = "r,g,b", converter = ColourTriple.class,
            description = "The fog's colour, 0..1 per channel (default: 0,0,0).")
    Colour fogColour;

    /** Checks the combinations; every message names the option. */
    void check() {
        if (fogColour != null && fog == null) {
            throw dev.trisect.base.InputException.usage("--fog-colour applies to --fog, which is not given");
        }
    }

    /** One draw of {@code mesh}, with the fog: what compare and bench draw. */
    Draws draws(Mesh mesh, Texture[] textures, Mat4 viewProjection) {
        Draws d = new Draws();
        d.add(mesh, textures, viewProjection);
        return apply(d);
    }

    /** {@code draws} with the fog. */
    Draws apply(Draws draws) {
        draws.setFog(fog().orElse(null));
        return draws;
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
     * The same fog for glref, as the {@code GLREF_*} environment variables its README lists (in
     * order; empty without fog).
     */
    Map<String, String> glrefEnvironment() {
        check();
        Map<String, String> env = new LinkedHashMap<>();
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
        return c.r() + "," + c.g() + "," + c.b();
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
