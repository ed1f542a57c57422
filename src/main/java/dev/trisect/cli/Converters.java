package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.render.CullMode;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPoint;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.TextureFilter;
import java.io.File;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** Parsers for option values, each failing with a message that says what a good value looks like. */
final class Converters {
    private Converters() {
    }

    /** A frame size {@code WxH}, each side 1..16384 pixels. */
    record Size(int width, int height) {
        Viewport viewport() {
            return new Viewport(width, height);
        }

        @Override
        public String toString() {
            return width + "x" + height;
        }
    }

    /**
     * A value as a message quotes it (see {@link InputException#quote}): Jazzer found a newline in a
     * value splitting the usage message.
     */
    /** What Java reads in place of command-line bytes its file-name encoding cannot decode. */
    private static final char REPLACEMENT = (char) 0xFFFD;

    static String quote(String value) {
        return InputException.quote(value, 60);
    }

    static final class SizeConverter implements ITypeConverter<Size> {
        @Override
        public Size convert(String value) {
            String[] parts = value.trim().toLowerCase(Locale.ROOT).split("x", -1);
            if (parts.length == 2) {
                try {
                    int w = Integer.parseInt(parts[0].trim());
                    int h = Integer.parseInt(parts[1].trim());
                    if (w >= 1 && h >= 1 && w <= Viewport.MAX_SIDE && h <= Viewport.MAX_SIDE) {
                        return new Size(w, h);
                    }
                } catch (NumberFormatException e) {
                    // fall through to the message
                }
            }
            throw new TypeConversionException(quote(value) + " is not a frame size: use WxH with each side 1.."
                    + Viewport.MAX_SIDE + " pixels, e.g. 1280x720");
        }
    }

    /** Three finite numbers; the message names what they are (a point unless a subclass says otherwise). */
    static class Vec3Converter implements ITypeConverter<Vec3> {
        private final String what;

        Vec3Converter() {
            this("a point: use three finite numbers x,y,z, e.g. 0,1.7,6");
        }

        /** @param what what the value is and how to write it, after "is not" in the message */
        Vec3Converter(String what) {
            this.what = what;
        }

        @Override
        public Vec3 convert(String value) {
            String[] parts = value.split(",", -1);
            if (parts.length == 3) {
                try {
                    Vec3 v = new Vec3(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()),
                            Double.parseDouble(parts[2].trim()));
                    if (v.isFinite()) {
                        return v;
                    }
                } catch (NumberFormatException e) {
                    // fall through to the message
                }
            }
            throw new TypeConversionException(quote(value) + " is not " + what);
        }
    }

    /**
     * The name of a file to write. A name the user ended with a separator ({@code out.png/}) names a
     * directory, and is refused: {@link java.nio.file.Path} drops the separator, so {@code out.png/}
     * would otherwise write the file {@code out.png} where the user meant a folder, or typed one
     * character too many.
     */
    static final class OutputFileConverter implements ITypeConverter<Path> {
        @Override
        public Path convert(String value) {
            if (value.endsWith("/") || value.endsWith(File.separator)) {
                throw new TypeConversionException(quote(value) + " ends with a separator, so it names a directory: "
                        + "give the name of the file to write");
            }
            return path(value);
        }
    }

    /**
     * A file name as a path, or the message docs/reading-limits.md promises when Java cannot map it to
     * one: under a locale that is not UTF-8 ({@code LANG=C}) a name outside ASCII cannot be a path
     * (picocli's own message named the exception and the interface).
     */
    static Path path(String value) {
        Path path;
        try {
            path = Path.of(value);
        } catch (InvalidPathException e) {
            throw new TypeConversionException("invalid file name " + quote(value) + ": Java cannot map it to a path "
                    + "under this locale (file names in " + System.getProperty("sun.jnu.encoding")
                    + "); run under a UTF-8 locale, e.g. LANG=C.UTF-8");
        }
        // Java reads command-line bytes that are not valid in the locale's encoding (caf\xE9 under UTF-8) as
        // U+FFFD, so the path would name another file: an output went to a file named caf, U+FFFD, .png, and
        // an input was "no such file" beside the file itself. A real U+FFFD in a file name is not worth that.
        if (value.indexOf(REPLACEMENT) >= 0) {
            throw new TypeConversionException("invalid file name " + quote(value) + ": it is not valid "
                    + System.getProperty("sun.jnu.encoding") + ", this locale's encoding of file names (Java reads "
                    + "the bytes it cannot decode as U+FFFD and would name another file); rename the file");
        }
        return path;
    }

    /** A finite number &gt; 0. */
    static final class PositiveConverter implements ITypeConverter<Double> {
        @Override
        public Double convert(String value) {
            try {
                double d = Double.parseDouble(value.trim());
                if (d > 0 && Double.isFinite(d)) {
                    return d;
                }
            } catch (NumberFormatException e) {
                // fall through to the message
            }
            throw new TypeConversionException(quote(value) + " is not a positive number");
        }
    }

    /** A frame piece budget: a whole number at least 1, or {@code auto} (0, scaled with the frame). */
    static final class FramePiecesConverter implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            String v = value.trim();
            if (v.equalsIgnoreCase("auto")) {
                return TessellationSettings.AUTO_FRAME_PIECES;
            }
            try {
                int n = Integer.parseInt(v);
                if (n >= 1) {
                    return n;
                }
            } catch (NumberFormatException e) {
                // fall through to the message
            }
            throw new TypeConversionException(quote(value) + " is not a piece count: use a whole number from 1 to "
                    + Integer.MAX_VALUE + ", or auto");
        }
    }

    /** An opaque colour {@code RRGGBB} (an optional leading # is allowed). */
    static final class ColourConverter implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            String v = value.trim();
            if (v.startsWith("#")) {
                v = v.substring(1);
            }
            if (v.matches("[0-9a-fA-F]{6}")) {
                return Integer.parseInt(v, 16);
            }
            throw new TypeConversionException(quote(value) + " is not a colour: use six hex digits RRGGBB, e.g. 202830");
        }
    }

    /** Names of an enum's constants, matched case-insensitively against a lower-case spelling. */
    abstract static class NamedConverter<E extends Enum<E>> implements ITypeConverter<E> {
        private final E[] values;
        private final String what;

        NamedConverter(E[] values, String what) {
            this.values = values;
            this.what = what;
        }

        String name(E value) {
            return value.name().toLowerCase(Locale.ROOT);
        }

        @Override
        public E convert(String value) {
            StringBuilder known = new StringBuilder();
            for (E e : values) {
                if (name(e).equalsIgnoreCase(value.trim())) {
                    return e;
                }
                known.append(known.length() == 0 ? "" : e == values[values.length - 1] ? " or " : ", ").append(name(e));
            }
            throw new TypeConversionException(quote(value) + " is not a " + what + ": use " + known);
        }
    }

    static final class ModeConverter extends NamedConverter<RenderMode> {
        ModeConverter() {
            super(RenderMode.values(), "mode");
        }
    }

    static final class SplitConverter extends NamedConverter<SplitPolicy> {
        SplitConverter() {
            super(SplitPolicy.values(), "split policy");
        }
    }

    static final class SplitPointConverter extends NamedConverter<SplitPoint> {
        SplitPointConverter() {
            super(SplitPoint.values(), "split point");
        }
    }

    static final class CullConverter extends NamedConverter<CullMode> {
        CullConverter() {
            super(CullMode.values(), "cull mode");
        }
    }

    static final class FilterConverter extends NamedConverter<TextureFilter> {
        FilterConverter() {
            super(TextureFilter.values(), "texture filter");
        }
    }
}
