import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Expands the pixel loops' templates into Java at build time (as OpenJDK's X-Buffer.java.template):
 * one monomorphic loop per combination of colour source, colour, write, UV output and (per pixel)
 * division, and per template a dispatcher that picks the loop once per triangle. Maven runs it in the
 * generate-sources phase as a single-file program ({@code java src/build/java/LoopGenerator.java
 * src/main/templates target/generated-sources/loops}); the loops are never checked in, and a file
 * whose text did not change is not rewritten. docs/architecture.md ("The pixel stage") describes
 * the seams; this comment, the syntax.
 *
 * <p>Template ({@code dev/trisect/raster/NAME.java.template}): sections {@code //#header},
 * {@code //#method} (expanded per combination), {@code //#footer}; lines {@code //#params} and
 * {@code //#dimensions} (of {@code source colour write uv divide}; without {@code colour} or
 * {@code write}, only the first of {@link #COLOURS} or {@link #WRITES}). A line of a template or of
 * a source may end in markers, each {@code " //#"} and a word: {@code uv}, {@code divide},
 * {@code varyings} (the colour reads varyings), each negated by {@code !}, keep the line when they
 * hold; {@code write=V,..}, {@code colour=V,..}, {@code source=V,..} (names with a lower-case first
 * letter) for those values; {@code varying} writes the line once per varying of the colour, with
 * {@code $V$} its name and {@code $K$} its slot (2, 3, 4). Placeholders: {@code $FIXED$} and
 * {@code $DOUBLE$} the fragment's colour (ARGB, alpha kept: the colour's {@code //#combine} of the
 * source's texel from 32.32 fixed-point or double {@code s}, {@code t}, where the template has left a
 * double for each varying); {@code $STEP$} (in a for header) the source's further steps;
 * {@code $SOURCE_ID$}, {@code $PIXEL_STATE$}, {@code $UV$}, {@code $NAME$} the combination's source,
 * state, UV setting and the loop's name. A line that is only {@code $WRITE$} or {@code $END_WRITE$}
 * becomes the write's {@code //#begin} or {@code //#end} (around the UV output's lines; they read the
 * locals {@code i}, {@code qf}, {@code argb} and the arrays {@code depth}, {@code color}); a line that is
 * only another {@code $WORD$} is a hook: the source's section of that name in lower case
 * ({@code $SETUP$}, {@code $ROW$}, {@code $PIXEL$}, {@code $KNOT$}, {@code $SEGMENT$}, {@code $PIECE$}),
 * or nothing.
 *
 * <p>Source ({@code sources/NAME.source}): comment lines (its description), then sections, each from
 * a line {@code //#name} to the next: {@code fixed} and {@code double} (the texel, required), the
 * hooks' statements, {@code step}, {@code imports}. {@code //#name TEMPLATE} is a section for one
 * template only. A line or part of a line {@code $WORD$} includes the source's own section. A source
 * {@code FAMILYPot} or {@code FAMILYAny} without a file is read from {@code FAMILY.source}, lines ending
 * in {@code //#pot} (blocks {@code //#pot} .. {@code //#end}) kept for Pot only, {@code //#!pot} for Any.
 * Colour ({@code colours/NAME.colour}): {@code //#varyings} (names, slots 2.. in order),
 * {@code //#combine} (of {@code $TEXEL$} and them). Write ({@code writes/NAME.write}): {@code //#uv}
 * ({@code yes} when it writes the UV output), {@code //#begin}, {@code //#end}. Adding one is its file
 * and its line in {@link #SOURCES}, {@link #COLOURS} or {@link #WRITES} (and for the last two its
 * {@code PixelState} constant).
 */
public final class LoopGenerator {
    /** The colour sources, in the order of their ids in {@code ColourSources}: one line registers one. */
    static final List<String> SOURCES = List.of(
            "NearestPot",
            "NearestAny",
            "BilinearPot",
            "BilinearAny",
            "TrilinearPot",
            "TrilinearAny");
    /** The colours ({@code colours/NAME.colour}), each also a {@code PixelState} constant (NAME in upper case). */
    static final List<String> COLOURS = List.of(
            "Texel",
            "Modulate");
    /** The writes ({@code writes/NAME.write}), likewise {@code PixelState} constants. */
    static final List<String> WRITES = List.of(
            "Opaque",
            "AlphaTest",
            "Blend");
    /** The templates, each giving one class of loops. */
    static final List<String> TEMPLATES = List.of("PerPixelNearest", "FixedNearest", "KnotNearest", "TreeNearest");
    /** Where the raster package's templates are, below the templates' root; likewise its output. */
    static final Path PACKAGE = Path.of("dev/trisect/raster");
    /** The vertex layout's slot of a colour's first varying: slots 0 and 1 are the texel coordinates. */
    static final int FIRST_COLOUR_SLOT = 2;
    /** One marker at the end of a line of a template or a source. */
    private static final Pattern MARKER = Pattern.compile(" //#(!?)([a-zA-Z]+)(?:=([a-zA-Z,]+))?$");

    private LoopGenerator() {
    }

    /**
     * Writes the generated sources: {@code args[0]} the templates' root, {@code args[1]} the output
     * root (a source folder).
     */
    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: java LoopGenerator.java TEMPLATES_DIR OUTPUT_DIR");
            System.exit(2);
        }
        Path out = Path.of(args[1]);
        for (Map.Entry<Path, String> e : generate(Path.of(args[0])).entrySet()) {
            Path file = out.resolve(e.getKey());
            if (Files.isRegularFile(file) && Files.readString(file, StandardCharsets.UTF_8).equals(e.getValue())) {
                continue;
            }
            Files.createDirectories(file.getParent());
            Files.writeString(file, e.getValue(), StandardCharsets.UTF_8);
        }
    }

    /** Every generated file, by its path relative to the output root, from the templates under {@code root}. */
    static Map<Path, String> generate(Path root) throws IOException {
        Path dir = root.resolve(PACKAGE);
        List<Source> sources = new ArrayList<>();
        for (String name : SOURCES) {
            sources.add(Source.read(name, dir.resolve("sources"), ".source", "fixed", "double"));
        }
        List<Source> colours = new ArrayList<>();
        for (String name : COLOURS) {
            colours.add(Source.read(name, dir.resolve("colours"), ".colour", "combine"));
        }
        List<Source> writes = new ArrayList<>();
        for (String name : WRITES) {
            writes.add(Source.read(name, dir.resolve("writes"), ".write", "uv", "begin"));
        }
        Map<Path, String> out = new LinkedHashMap<>();
        out.put(PACKAGE.resolve("ColourSources.java"), colourSources(sources));
        for (String t : TEMPLATES) {
            String text = Files.readString(dir.resolve(t + ".java.template"), StandardCharsets.UTF_8);
            out.put(PACKAGE.resolve(t + ".java"), expand(t, text, sources, colours, writes));
        }
        return out;
    }

    private static String banner(String from) {
        return "// Generated at build time by src/build/java/LoopGenerator.java from src/main/templates/"
                + PACKAGE.toString().replace('\\', '/') + "/" + from + ": edit that, not this.\n";
    }

    private static String colourSources(List<Source> sources) {
        StringBuilder b = new StringBuilder(banner("sources/*.source"));
        b.append("package dev.trisect.raster;\n\n");
        b.append("/**\n * The colour sources of the pixel loops: what colour a fragment gets, chosen once per triangle.\n");
        b.append(" * Each generated loop class ({@link PerPixelNearest}, {@link FixedNearest}, {@link KnotNearest},\n");
        b.append(" * {@link TreeNearest}) has one loop per source and dispatches on these numbers.\n */\n");
        b.append("final class ColourSources {\n");
        for (int i = 0; i < sources.size(); i++) {
            Source s = sources.get(i);
            b.append("    /** ").append(s.description).append(" */\n");
            b.append("    static final int ").append(s.constant()).append(" = ").append(i).append(";\n");
        }
        b.append("    /** How many sources there are. */\n");
        b.append("    static final int COUNT = ").append(sources.size()).append(";\n\n");
        b.append("    private ColourSources() {\n    }\n}\n");
        return b.toString();
    }

    /** One loop's place in the dimensions. */
    private record Combination(Source source, Source colour, Source write, boolean uv, boolean divide) {
        /** The loop's {@code PixelState}, as a constant expression. */
        String state() {
            return "PixelState." + colour.constant() + " | PixelState." + write.constant();
        }

        Combination withUv(boolean on) {
            return new Combination(source, colour, write, on, divide);
        }

        Combination dividing(boolean on) {
            return new Combination(source, colour, write, uv, on);
        }
    }

    private static String expand(String name, String text, List<Source> sources, List<Source> allColours,
                                 List<Source> allWrites) {
        String header = section(text, "//#header", "//#params");
        String params = line(text, "//#params ");
        List<String> dims = List.of(line(text, "//#dimensions ").split(" "));
        String method = section(text, "//#method", "//#footer");
        String footer = text.substring(text.indexOf("//#footer") + "//#footer".length() + 1);
        boolean divides = dims.contains("divide");
        boolean stated = dims.contains("colour") || dims.contains("write");
        List<Source> colours = dims.contains("colour") ? allColours : allColours.subList(0, 1);
        List<Source> writes = dims.contains("write") ? allWrites : allWrites.subList(0, 1);
        List<Combination> all = new ArrayList<>();
        for (Source s : sources) {
            for (Source c : colours) {
                for (Source w : writes) {
                    all.add(new Combination(s, c, w, w.writesUv(), false));
                }
            }
        }
        StringBuilder b = new StringBuilder(banner(name + ".java.template"));
        b.append(withImports(header, sources));
        b.append(dispatcher(params, divides, stated, all));
        for (Combination k : all) {
            for (boolean uv : k.uv ? new boolean[] {true, false} : new boolean[] {false}) {
                for (boolean divide : divides ? new boolean[] {true, false} : new boolean[] {false}) {
                    Combination m = k.withUv(uv).dividing(divide);
                    b.append('\n');
                    b.append("    /** ").append(k.source.name).append(", ").append(k.colour.name).append(", ")
                            .append(k.write.name).append(divides ? divide ? ", dividing by 1/w" : ", affine" : "")
                            .append(uv ? ", with" : ", without").append(" the UV output; pixels written. */\n");
                    b.append(method(method, name, m, methodName(m, divides)));
                }
            }
        }
        b.append(footer);
        return b.toString();
    }

    /** The header with the sources' imports after its package line. */
    private static String withImports(String header, List<Source> sources) {
        TreeSet<String> imports = new TreeSet<>();
        for (Source s : sources) {
            imports.addAll(s.imports());
        }
        int end = header.indexOf('\n', header.indexOf("package ")) + 1;
        StringBuilder b = new StringBuilder(header.substring(0, end));
        for (String i : imports) {
            if (!header.contains(i)) {
                b.append(b.length() == end ? "\n" : "").append(i).append('\n');
            }
        }
        return b.append(header.substring(end)).toString();
    }

    private static String dispatcher(String params, boolean divides, boolean stated, List<Combination> all) {
        StringBuilder args = new StringBuilder();
        for (String p : params.split(",")) {
            String[] words = p.trim().split(" ");
            args.append(args.length() == 0 ? "" : ", ").append(words[words.length - 1]);
        }
        StringBuilder b = new StringBuilder("\n");
        b.append("    /**\n     * The loop of colour source {@code source} ({@link ColourSources})")
                .append(stated ? " and pixel state {@code state}\n     * ({@link PixelState})" : "")
                .append(", with the UV output when {@code uv}").append(stated ? " (and the write has one)" : "")
                .append(divides ? ",\n     * dividing by the interpolated 1/w when {@code divide}" : "")
                .append(": chosen once per triangle.\n     *\n     * @return pixels written\n     */\n");
        b.append("    static long fill(int source, ").append(stated ? "int state, " : "").append("boolean uv, ")
                .append(divides ? "boolean divide," : "").append("\n            ").append(params).append(") {\n");
        b.append("        switch (source) {\n");
        String indent = stated ? "                        " : "                ";
        Source last = null;
        for (Combination k : all) {
            if (k.source != last) {
                if (last != null && stated) {
                    b.append("                    default:\n                        throw new IllegalArgumentException(")
                            .append("\"no loop for pixel state \" + state);\n                }\n");
                }
                last = k.source;
                b.append("            case ColourSources.").append(k.source.constant()).append(":\n");
                b.append(stated ? "                switch (state) {\n" : "");
            }
            if (stated) {
                b.append("                    case ").append(k.state()).append(":\n");
            }
            if (divides) {
                b.append(indent).append("if (divide) {\n").append(indent).append("    return ")
                        .append(call(k.dividing(true), divides, args, indent + "            ")).append(";\n")
                        .append(indent).append("}\n");
            }
            b.append(indent).append("return ").append(call(k, divides, args, indent + "        ")).append(";\n");
        }
        if (stated) {
            b.append("                    default:\n                        throw new IllegalArgumentException(")
                    .append("\"no loop for pixel state \" + state);\n                }\n");
        }
        b.append("            default:\n");
        b.append("                throw new IllegalArgumentException(\"no colour source \" + source);\n");
        b.append("        }\n    }\n");
        return b.toString();
    }

    /** The call of combination {@code k}'s loop, choosing by {@code uv} where the write has a UV output. */
    private static String call(Combination k, boolean divides, CharSequence args, String indent) {
        if (!k.uv) {
            return methodName(k, divides) + "(" + args + ")";
        }
        return "uv ? " + methodName(k, divides) + "(" + args + ")\n" + indent + ": "
                + methodName(k.withUv(false), divides) + "(" + args + ")";
    }

    private static String methodName(Combination k, boolean divides) {
        String n = Character.toLowerCase(k.source.name.charAt(0)) + k.source.name.substring(1);
        return n + (k.colour.name.equals(COLOURS.get(0)) ? "" : k.colour.name)
                + (k.write.name.equals(WRITES.get(0)) ? "" : k.write.name)
                + (divides ? k.divide ? "Divide" : "Affine" : "") + (k.uv ? "Uv" : "");
    }

    private static String method(String template, String templateName, Combination k, String name) {
        StringBuilder b = new StringBuilder();
        String[] all = template.split("\n", -1);
        for (int n = 0; n < all.length; n++) {
            if (all[n].isEmpty() && n == all.length - 1) {
                continue;
            }
            for (String kept : kept(all[n], k)) {
                String hook = kept.trim();
                if (hook.equals("$WRITE$") || hook.equals("$END_WRITE$")) {
                    // The write's code before or after the UV output's lines, indented as the line.
                    String indent = kept.substring(0, kept.indexOf('$'));
                    for (String line : k.write.raw(hook.equals("$WRITE$") ? "begin" : "end")) {
                        b.append(indent).append(line).append('\n');
                    }
                } else if (hook.matches("\\$[A-Z]+\\$")) {
                    // A hook line: the source's section of that name, indented as the line, or nothing.
                    String indent = kept.substring(0, kept.indexOf('$'));
                    for (String line : k.source.lines(hook.substring(1, hook.length() - 1).toLowerCase(Locale.ROOT),
                            templateName, k)) {
                        b.append(indent).append(substitute(line, k, name)).append('\n');
                    }
                } else {
                    b.append(substitute(expressions(kept, templateName, k), k, name)).append('\n');
                }
            }
        }
        return b.toString();
    }

    /** The line with the fragment's colour ({@code $FIXED$}, {@code $DOUBLE$}) and the source's {@code $STEP$}. */
    private static String expressions(String line, String templateName, Combination k) {
        String combine = String.join(" ", k.colour.raw("combine"));
        for (String e : List.of("fixed", "double")) {
            String placeholder = "$" + e.toUpperCase(Locale.ROOT) + "$";
            if (line.contains(placeholder)) {
                line = line.replace(placeholder, combine.replace("$TEXEL$", k.source.expression(e, templateName, k)));
            }
        }
        List<String> step = k.source.lines("step", templateName, k);
        return line.replace("$STEP$", step.isEmpty() ? "" : ", " + String.join(" ", step));
    }

    private static String substitute(String line, Combination k, String name) {
        return line.replace("$NAME$", name).replace("$SOURCE_ID$", "ColourSources." + k.source.constant())
                .replace("$PIXEL_STATE$", k.state()).replace("$UV$", Boolean.toString(k.uv));
    }

    /**
     * The line as written for combination {@code k}, without its markers: none when a marker excludes
     * it, one per varying of the colour ({@code $V$}, {@code $K$} replaced) when it is marked
     * {@code //#varying}, else one.
     */
    private static List<String> kept(String line, Combination k) {
        List<String> varyings = k.colour.words("varyings");
        boolean repeat = false;
        Matcher m = MARKER.matcher(line);
        while (m.find()) {
            boolean not = !m.group(1).isEmpty();
            String dim = m.group(2);
            if (dim.equals("varying") && !not && m.group(3) == null) {
                repeat = true;
            } else if (holds(k, varyings, dim, m.group(3)) == not) {
                return List.of();
            }
            line = line.substring(0, m.start());
            m = MARKER.matcher(line);
        }
        if (!repeat) {
            return List.of(line);
        }
        List<String> lines = new ArrayList<>();
        for (int v = 0; v < varyings.size(); v++) {
            lines.add(line.replace("$V$", varyings.get(v)).replace("$K$", Integer.toString(FIRST_COLOUR_SLOT + v)));
        }
        return lines;
    }

    /** Whether marker {@code dim} (with its {@code values}, or null) holds for combination {@code k}. */
    private static boolean holds(Combination k, List<String> varyings, String dim, String values) {
        String value;
        switch (dim + (values == null ? "" : "=")) {
            case "uv":
                return k.uv;
            case "divide":
                return k.divide;
            case "varyings":
                return !varyings.isEmpty();
            case "write=":
                value = k.write.name;
                break;
            case "colour=":
                value = k.colour.name;
                break;
            case "source=":
                value = k.source.name;
                break;
            default:
                throw new IllegalArgumentException("unknown marker //#" + dim + (values == null ? "" : "=" + values));
        }
        return List.of(values.split(",")).contains(Character.toLowerCase(value.charAt(0)) + value.substring(1));
    }

    /** The line without its marker if it is kept for {@code value} of dimension {@code dim}; null if dropped. */
    private static String keep(String line, String dim, boolean value) {
        String on = " //#" + dim;
        String off = " //#!" + dim;
        if (line.endsWith(on)) {
            return value ? line.substring(0, line.length() - on.length()) : null;
        }
        if (line.endsWith(off)) {
            return value ? null : line.substring(0, line.length() - off.length());
        }
        return line;
    }

    private static String section(String text, String start, String end) {
        int a = text.indexOf(start);
        int z = text.indexOf(end);
        if (a < 0 || z < a) {
            throw new IllegalArgumentException("template without " + start + " before " + end);
        }
        return text.substring(a + start.length() + 1, z);
    }

    private static String line(String text, String prefix) {
        int a = text.indexOf(prefix);
        if (a < 0) {
            throw new IllegalArgumentException("template without " + prefix.trim());
        }
        return text.substring(a + prefix.length(), text.indexOf('\n', a)).trim();
    }

    /**
     * A colour source read from its file: its sections by name ({@code "setup"}, or {@code "setup KnotNearest"}
     * for one template only), each a list of lines.
     */
    private record Source(String name, String description, Map<String, List<String>> sections) {
        /**
         * Source {@code name} from {@code NAME.source} in {@code dir}, or, where there is none and the name
         * ends in {@code Pot} or {@code Any}, from its family's file (the name without that ending) with
         * the lines marked {@code //#pot} kept only for Pot and those marked {@code //#!pot} only for Any.
         */
        static Source read(String name, Path dir, String extension, String... required) throws IOException {
            Path file = dir.resolve(name + extension);
            Boolean pot = null;
            if (!Files.isRegularFile(file) && name.matches(".*(Pot|Any)")) {
                pot = name.endsWith("Pot");
                file = dir.resolve(name.substring(0, name.length() - 3) + extension);
            }
            StringBuilder description = new StringBuilder();
            Map<String, List<String>> sections = new LinkedHashMap<>();
            List<String> current = null;
            Boolean block = null;
            for (String l : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                if (pot != null && l.matches("//#!?pot|//#end")) {
                    // A block of lines for one variant: from //#pot or //#!pot to //#end.
                    block = l.equals("//#end") ? null : l.equals("//#pot");
                    continue;
                }
                l = pot == null ? l : block != null ? block == pot ? l : null : keep(l, "pot", pot);
                if (l == null) {
                    continue;
                }
                if (l.startsWith("//#")) {
                    current = new ArrayList<>();
                    sections.put(l.substring(3).trim(), current);
                } else if (current == null && l.startsWith("//")) {
                    description.append(description.length() == 0 ? "" : " ").append(l.substring(2).trim());
                } else if (current != null && !l.isBlank()) {
                    current.add(l);
                }
            }
            sections.values().removeIf(List::isEmpty);
            for (String s : required) {
                if (!sections.containsKey(s)) {
                    throw new IllegalArgumentException(file + ": no //#" + s + " section");
                }
            }
            return new Source(name, description.toString(), sections);
        }

        /**
         * The lines of section {@code section} for template {@code template} (its own section if it has
         * one, else the common one, else none), kept for combination {@code c} as template lines are.
         */
        List<String> lines(String section, String template, Combination c) {
            List<String> lines = sections.getOrDefault(section + " " + template, sections.get(section));
            List<String> kept = new ArrayList<>();
            for (String l : lines == null ? List.<String>of() : lines) {
                for (String k : kept(l, c)) {
                    if (k.trim().matches("\\$[A-Z]+\\$")) {
                        // Another section of the source, included here with this line's indentation.
                        String indent = k.substring(0, k.indexOf('$'));
                        for (String included : lines(k.trim().substring(1, k.trim().length() - 1)
                                .toLowerCase(Locale.ROOT), template, c)) {
                            kept.add(indent + included);
                        }
                    } else {
                        kept.add(inline(k, template, c));
                    }
                }
            }
            return kept;
        }

        /** Section {@code section}'s lines as written, or none. */
        List<String> raw(String section) {
            return sections.getOrDefault(section, List.of());
        }

        /** Section {@code section}'s words. */
        List<String> words(String section) {
            String all = String.join(" ", raw(section)).trim();
            return all.isEmpty() ? List.of() : List.of(all.split("\\s+"));
        }

        /** Whether a write writes the UV output (its {@code //#uv} section says yes). */
        boolean writesUv() {
            return words("uv").equals(List.of("yes"));
        }

        /** The line with each {@code $NAME$} of a section of the source replaced by that section as one expression. */
        private String inline(String line, String template, Combination c) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\$([A-Z]+)\\$").matcher(line);
            StringBuilder b = new StringBuilder();
            while (m.find()) {
                String section = m.group(1).toLowerCase(Locale.ROOT);
                String text = sections.containsKey(section) ? expression(section, template, c) : m.group();
                m.appendReplacement(b, java.util.regex.Matcher.quoteReplacement(text));
            }
            return m.appendTail(b).toString();
        }

        /** Section {@code section} as one expression: its lines joined. */
        String expression(String section, String template, Combination c) {
            List<String> lines = lines(section, template, c);
            StringBuilder b = new StringBuilder();
            for (String l : lines) {
                b.append(b.length() == 0 ? "" : " ").append(l.trim());
            }
            return b.toString();
        }

        /** The imports its sections need ({@code //#imports}). */
        List<String> imports() {
            return sections.getOrDefault("imports", List.of());
        }

        /** NearestPot gives NEAREST_POT. */
        String constant() {
            return name.replaceAll("([a-z0-9])([A-Z])", "$1_$2").toUpperCase(Locale.ROOT);
        }
    }
}
