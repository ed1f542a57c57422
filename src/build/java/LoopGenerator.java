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

/**
 * Expands the pixel loops' templates into Java at build time (as OpenJDK's X-Buffer.java.template):
 * one monomorphic loop per colour source and per setting of each other dimension (with or without
 * the UV output; dividing by 1/w or not), and per template a dispatcher that picks the loop once per
 * triangle. Maven runs it in the generate-sources phase as a single-file program
 * ({@code java src/build/java/LoopGenerator.java src/main/templates target/generated-sources/loops}),
 * so the templates are the one source of truth and the loops are never checked in; a file whose text
 * did not change is not rewritten, so that an unchanged build compiles nothing again.
 *
 * <p>Template ({@code dev/trisect/raster/NAME.java.template}): the sections {@code //#header},
 * {@code //#method} (expanded once per combination) and {@code //#footer}, and the lines
 * {@code //#params} (the loop's parameters) and {@code //#dimensions} (of {@code source}, {@code uv},
 * {@code divide}). In the method, a line ending in {@code //#uv} is kept only with the UV output,
 * {@code //#!uv} only without it, likewise {@code //#divide} and {@code //#!divide}; {@code $FIXED$}
 * becomes the source's colour from 32.32 fixed-point texel coordinates {@code s}, {@code t},
 * {@code $DOUBLE$} from doubles, {@code $STEP$} (in a for header) the source's further steps per
 * column, {@code $SOURCE_ID$} and {@code $UV$} the combination's source and UV setting, {@code $NAME$}
 * the loop's name. A line that is only {@code $WORD$} is a hook: it becomes the source's section of
 * that name in lower case ({@code $SETUP$}: {@code //#setup}, per triangle; {@code $ROW$},
 * {@code $PIXEL$}, {@code $KNOT$}, {@code $SEGMENT$}, {@code $PIECE$}), indented as the line, or
 * nothing where the source has no such section.
 *
 * <p>Colour source ({@code dev/trisect/raster/sources/NAME.source}): comment lines (its description),
 * then its sections, each from a line {@code //#name} to the next: {@code fixed} and {@code double}
 * (expressions, required), the hooks' statements, {@code step} and {@code imports} (import lines the
 * generated classes get). A section {@code //#name TEMPLATE} is that section for one template only,
 * in place of the common one. Source lines take the //#uv and //#divide markers as template lines
 * do, and a line or a part of a line {@code $WORD$} includes the source's own section of that name.
 * A source named {@code FAMILYPot} or {@code FAMILYAny} without a file of its own is read from
 * {@code FAMILY.source}, keeping lines ending in {@code //#pot} (blocks from a line {@code //#pot} to
 * {@code //#end}) for Pot only, {@code //#!pot} for Any only: a chain whose sides are powers of two,
 * or any. Adding a source is its file and its line in {@link #SOURCES}.
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
    /** The templates, each giving one class of loops. */
    static final List<String> TEMPLATES = List.of("PerPixelNearest", "FixedNearest", "KnotNearest", "TreeNearest");
    /** Where the raster package's templates are, below the templates' root; likewise its output. */
    static final Path PACKAGE = Path.of("dev/trisect/raster");

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
            sources.add(Source.read(name, dir.resolve("sources")));
        }
        Map<Path, String> out = new LinkedHashMap<>();
        out.put(PACKAGE.resolve("ColourSources.java"), colourSources(sources));
        for (String t : TEMPLATES) {
            String text = Files.readString(dir.resolve(t + ".java.template"), StandardCharsets.UTF_8);
            out.put(PACKAGE.resolve(t + ".java"), expand(t, text, sources));
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

    private static String expand(String name, String text, List<Source> sources) {
        String header = section(text, "//#header", "//#params");
        String params = line(text, "//#params ");
        List<String> dims = List.of(line(text, "//#dimensions ").split(" "));
        String method = section(text, "//#method", "//#footer");
        String footer = text.substring(text.indexOf("//#footer") + "//#footer".length() + 1);
        boolean divides = dims.contains("divide");
        StringBuilder b = new StringBuilder(banner(name + ".java.template"));
        b.append(withImports(header, sources));
        b.append(dispatcher(params, divides, sources));
        for (Source s : sources) {
            for (boolean uv : new boolean[] {true, false}) {
                for (boolean divide : divides ? new boolean[] {true, false} : new boolean[] {false}) {
                    b.append('\n');
                    b.append("    /** ").append(s.name).append(divides ? divide ? ", dividing by 1/w" : ", affine" : "")
                            .append(uv ? ", with" : ", without").append(" the UV output; pixels written. */\n");
                    b.append(method(method, name, s, uv, divide, methodName(s, uv, divides, divide)));
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

    private static String dispatcher(String params, boolean divides, List<Source> sources) {
        StringBuilder args = new StringBuilder();
        for (String p : params.split(",")) {
            String[] words = p.trim().split(" ");
            args.append(args.length() == 0 ? "" : ", ").append(words[words.length - 1]);
        }
        StringBuilder b = new StringBuilder("\n");
        b.append("    /**\n     * The loop of colour source {@code source} ({@link ColourSources}), with the UV output when\n");
        b.append("     * {@code uv}").append(divides ? ", dividing by the interpolated 1/w when {@code divide}" : "")
                .append(": chosen once per triangle.\n     *\n     * @return pixels written\n     */\n");
        b.append("    static long fill(int source, boolean uv, ").append(divides ? "boolean divide," : "")
                .append(divides ? "\n            " : "").append(params).append(") {\n");
        b.append("        switch (source) {\n");
        for (Source s : sources) {
            b.append("            case ColourSources.").append(s.constant()).append(":\n");
            if (divides) {
                b.append("                if (divide) {\n");
                b.append("                    return uv ? ").append(methodName(s, true, true, true)).append('(').append(args)
                        .append(")\n                            : ").append(methodName(s, false, true, true)).append('(')
                        .append(args).append(");\n                }\n");
            }
            b.append("                return uv ? ").append(methodName(s, true, divides, false)).append('(').append(args)
                    .append(")\n                        : ").append(methodName(s, false, divides, false)).append('(')
                    .append(args).append(");\n");
        }
        b.append("            default:\n");
        b.append("                throw new IllegalArgumentException(\"no colour source \" + source);\n");
        b.append("        }\n    }\n");
        return b.toString();
    }

    private static String methodName(Source s, boolean uv, boolean divides, boolean divide) {
        String n = Character.toLowerCase(s.name.charAt(0)) + s.name.substring(1);
        return n + (divides ? divide ? "Divide" : "Affine" : "") + (uv ? "Uv" : "");
    }

    private static String method(String template, String templateName, Source s, boolean uv, boolean divide,
                                 String name) {
        StringBuilder b = new StringBuilder();
        for (String l : template.split("\n", -1)) {
            if (l.isEmpty() && b.length() > 0 && template.endsWith(l)) {
                continue;
            }
            String kept = keep(l, "uv", uv);
            kept = kept == null ? null : keep(kept, "divide", divide);
            if (kept == null) {
                continue;
            }
            String hook = kept.trim();
            if (hook.matches("\\$[A-Z]+\\$")) {
                // A hook line: the source's section of that name, indented as the line, or nothing.
                String indent = kept.substring(0, kept.indexOf('$'));
                for (String line : s.lines(hook.substring(1, hook.length() - 1).toLowerCase(Locale.ROOT), templateName,
                        uv, divide)) {
                    b.append(indent).append(substitute(line, s, uv, name)).append('\n');
                }
                continue;
            }
            for (String e : List.of("fixed", "double")) {
                String placeholder = "$" + e.toUpperCase(Locale.ROOT) + "$";
                if (kept.contains(placeholder)) {
                    kept = kept.replace(placeholder, s.expression(e, templateName, uv, divide));
                }
            }
            List<String> step = s.lines("step", templateName, uv, divide);
            kept = kept.replace("$STEP$", step.isEmpty() ? "" : ", " + String.join(" ", step));
            b.append(substitute(kept, s, uv, name)).append('\n');
        }
        return b.toString();
    }

    private static String substitute(String line, Source s, boolean uv, String name) {
        return line.replace("$NAME$", name).replace("$SOURCE_ID$", "ColourSources." + s.constant())
                .replace("$UV$", Boolean.toString(uv));
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
        static Source read(String name, Path dir) throws IOException {
            Path file = dir.resolve(name + ".source");
            Boolean pot = null;
            if (!Files.isRegularFile(file) && name.matches(".*(Pot|Any)")) {
                pot = name.endsWith("Pot");
                file = dir.resolve(name.substring(0, name.length() - 3) + ".source");
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
            for (String s : List.of("fixed", "double")) {
                if (!sections.containsKey(s)) {
                    throw new IllegalArgumentException(file + ": no //#" + s + " section");
                }
            }
            return new Source(name, description.toString(), sections);
        }

        /**
         * The lines of section {@code section} for template {@code template} (its own section if it has
         * one, else the common one, else none), kept for the UV and divide settings as template lines are.
         */
        List<String> lines(String section, String template, boolean uv, boolean divide) {
            List<String> lines = sections.getOrDefault(section + " " + template, sections.get(section));
            List<String> kept = new ArrayList<>();
            for (String l : lines == null ? List.<String>of() : lines) {
                String k = keep(l, "uv", uv);
                k = k == null ? null : keep(k, "divide", divide);
                if (k != null && k.trim().matches("\\$[A-Z]+\\$")) {
                    // Another section of the source, included here with this line's indentation.
                    String indent = k.substring(0, k.indexOf('$'));
                    for (String included : lines(k.trim().substring(1, k.trim().length() - 1).toLowerCase(Locale.ROOT),
                            template, uv, divide)) {
                        kept.add(indent + included);
                    }
                } else if (k != null) {
                    kept.add(inline(k, template, uv, divide));
                }
            }
            return kept;
        }

        /** The line with each {@code $NAME$} of a section of the source replaced by that section as one expression. */
        private String inline(String line, String template, boolean uv, boolean divide) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\$([A-Z]+)\\$").matcher(line);
            StringBuilder b = new StringBuilder();
            while (m.find()) {
                String section = m.group(1).toLowerCase(Locale.ROOT);
                String text = sections.containsKey(section) ? expression(section, template, uv, divide) : m.group();
                m.appendReplacement(b, java.util.regex.Matcher.quoteReplacement(text));
            }
            return m.appendTail(b).toString();
        }

        /** Section {@code section} as one expression: its lines joined. */
        String expression(String section, String template, boolean uv, boolean divide) {
            List<String> lines = lines(section, template, uv, divide);
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
