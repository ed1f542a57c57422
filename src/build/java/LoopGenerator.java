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
 * one monomorphic loop per combination of colour source, colour, write, UV output and (per pixel)
 * division, and per template a dispatcher that picks the loop once per triangle. Maven compiles it
 * with {@link LoopPart} and runs it in the generate-sources phase ({@code java -cp
 * target/loop-generator LoopGenerator src/main/templates target/generated-sources/loops}); the loops
 * are never checked in, and a file whose text did not change is not rewritten. docs/architecture.md
 * ("The pixel stage") describes the seams; this comment, the syntax.
 *
 * <p>Template ({@code dev/trisect/raster/NAME.java.template}): sections {@code //#header},
 * {@code //#method} (expanded per combination), {@code //#footer}; lines {@code //#params} and
 * {@code //#dimensions} (of {@code source colour write uv ids divide}; without {@code colour} or
 * {@code write}, only the first of {@link #COLOURS} or {@link #WRITES}). A line of a template or of
 * a source may end in markers, each {@code " //#"} and a word: {@code uv}, {@code ids} (the int ids,
 * written with the UV output or alone), {@code divide},
 * {@code varyings} (the colour reads varyings), each negated by {@code !}, keep the line when they
 * hold; {@code write=V,..}, {@code colour=V,..}, {@code source=V,..} (names with a lower-case first
 * letter) for those values; {@code varying} writes the line once per varying of the colour, with
 * {@code $V$} its name and {@code $K$} its slot (2, 3, 4). Placeholders: {@code $FIXED$} and
 * {@code $DOUBLE$} the fragment's colour (ARGB, alpha kept: the colour's {@code //#combine} of the
 * source's texel from 32.32 fixed-point or double {@code s}, {@code t}, where the template has left a
 * double for each varying); {@code $STEP$} (in a for header) the source's further steps;
 * {@code $SOURCE_ID$}, {@code $PIXEL_STATE$}, {@code $UV$}, {@code $IDS$}, {@code $NAME$} the
 * combination's source, state, UV and ids settings and the loop's name. A line that is only {@code $WRITE$} or {@code $END_WRITE$}
 * becomes the write's {@code //#begin} or {@code //#end} (around the UV output's lines; they read the
 * locals {@code i}, {@code qf}, {@code argb} and the arrays {@code depth}, {@code color}); a line that is
 * only another {@code $WORD$} is a hook: the write's, the source's and the colour's sections of that
 * name in lower case, in that order ({@code $SETUP$}, {@code $ROW$}, {@code $PIXEL$}, {@code $KNOT$},
 * {@code $SEGMENT$}, {@code $PIECE$}, {@code $RUN$}), or nothing.
 *
 * <p>LoopPart ({@code sources/NAME.source}): comment lines (its description), then sections, each from
 * a line {@code //#name} to the next: {@code fixed} and {@code double} (the texel, required), the
 * hooks' statements, {@code step}, {@code imports}. {@code //#name TEMPLATE} is a section for one
 * template only. A line or part of a line {@code $WORD$} includes the source's own section. A source
 * {@code FAMILYPot} or {@code FAMILYAny} without a file is read from {@code FAMILY.source}, lines ending
 * in {@code //#pot} (blocks {@code //#pot} .. {@code //#end}) kept for Pot only, {@code //#!pot} for Any.
 * Colour ({@code colours/NAME.colour}): {@code //#varyings} (names, slots 2.. in order),
 * {@code //#combine} (of {@code $TEXEL$} and them), and hook sections as a source's, written after the
 * source's. Write ({@code writes/NAME.write}): {@code //#uv}
 * ({@code yes} when it writes the UV output), {@code //#begin}, {@code //#end}, and hook sections
 * ({@code //#pixel}: right after the depth test, before the colour). Adding one is its file
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
            "Modulate",
            "Constant");
    /** The writes ({@code writes/NAME.write}), likewise {@code PixelState} constants. */
    static final List<String> WRITES = List.of(
            "Opaque",
            "AlphaTest",
            "Blend");
    /** The templates, each giving one class of loops. */
    static final List<String> TEMPLATES = List.of("PerPixelLoops", "FixedLoops", "KnotLoops", "TreeLoops");
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
        List<LoopPart> sources = new ArrayList<>();
        for (String name : SOURCES) {
            sources.add(LoopPart.read(name, dir.resolve("sources"), ".source", "fixed", "double"));
        }
        List<LoopPart> colours = new ArrayList<>();
        for (String name : COLOURS) {
            colours.add(LoopPart.read(name, dir.resolve("colours"), ".colour", "combine"));
        }
        List<LoopPart> writes = new ArrayList<>();
        for (String name : WRITES) {
            writes.add(LoopPart.read(name, dir.resolve("writes"), ".write", "uv", "begin"));
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

    private static String colourSources(List<LoopPart> sources) {
        StringBuilder b = new StringBuilder(banner("sources/*.source"));
        b.append("package dev.trisect.raster;\n\n");
        b.append("/**\n * The colour sources of the pixel loops: what colour a fragment gets, chosen once per triangle.\n");
        b.append(" * Each generated loop class ({@link PerPixelLoops}, {@link FixedLoops}, {@link KnotLoops},\n");
        b.append(" * {@link TreeLoops}) has one loop per source and dispatches on these numbers.\n */\n");
        b.append("final class ColourSources {\n");
        for (int i = 0; i < sources.size(); i++) {
            LoopPart s = sources.get(i);
            b.append("    /** ").append(s.description()).append(" */\n");
            b.append("    static final int ").append(s.constant()).append(" = ").append(i).append(";\n");
        }
        b.append("    /** How many sources there are. */\n");
        b.append("    static final int COUNT = ").append(sources.size()).append(";\n\n");
        b.append("    private ColourSources() {\n    }\n}\n");
        return b.toString();
    }

    private static String expand(String name, String text, List<LoopPart> sources, List<LoopPart> allColours,
                                 List<LoopPart> allWrites) {
        String header = section(text, "//#header", "//#params");
        String params = line(text, "//#params ");
        List<String> dims = List.of(line(text, "//#dimensions ").split(" "));
        String method = section(text, "//#method", "//#footer");
        String footer = text.substring(text.indexOf("//#footer") + "//#footer".length() + 1);
        boolean divides = dims.contains("divide");
        boolean hasIds = dims.contains("ids");
        boolean stated = dims.contains("colour") || dims.contains("write");
        List<LoopPart> colours = dims.contains("colour") ? allColours : allColours.subList(0, 1);
        List<LoopPart> writes = dims.contains("write") ? allWrites : allWrites.subList(0, 1);
        List<LoopPart.Combination> all = new ArrayList<>();
        for (LoopPart s : sources) {
            for (LoopPart c : colours) {
                for (LoopPart w : writes) {
                    all.add(new LoopPart.Combination(s, c, w, w.writesUv(), w.writesUv() && hasIds, false));
                }
            }
        }
        StringBuilder b = new StringBuilder(banner(name + ".java.template"));
        b.append(withImports(header, sources));
        b.append(dispatcher(params, divides, hasIds, stated, all));
        for (LoopPart.Combination k : all) {
            // Recording: the UV output (and the ids with it), the ids alone, or nothing.
            int recordings = k.uv() ? k.ids() ? 3 : 2 : 1;
            for (int r = 0; r < recordings; r++) {
                boolean uv = r == 0 && recordings > 1;
                boolean ids = k.ids() && r < 2;
                for (boolean divide : divides ? new boolean[] {true, false} : new boolean[] {false}) {
                    LoopPart.Combination m = k.recording(uv, ids).dividing(divide);
                    b.append('\n');
                    b.append("    /** ").append(k.source().name()).append(", ").append(k.colour().name()).append(", ")
                            .append(k.write().name()).append(divides ? divide ? ", dividing by 1/w" : ", affine" : "")
                            .append(uv ? ", with the UV output" : ids ? ", with the ids alone" : ", recording nothing")
                            .append("; pixels written. */\n");
                    b.append(method(method, name, m, methodName(m, divides)));
                }
            }
        }
        b.append(footer);
        return b.toString();
    }

    /** The header with the sources' imports after its package line. */
    private static String withImports(String header, List<LoopPart> sources) {
        TreeSet<String> imports = new TreeSet<>();
        for (LoopPart s : sources) {
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

    /**
     * The dispatch: {@code fill} chooses by source, a method per source by pixel state, a method per
     * source and state by division and recording, each small enough for C2 to inline where it is hot,
     * so that the per-triangle code calls the loop itself. One method of them all (a switch over every
     * loop, 5 kB of bytecode) was never inlined: a call more per triangle and band, with arguments on
     * the stack (docs/performance/pixel-stage.md, "All four paths, three filters, four scenes").
     */
    private static String dispatcher(String params, boolean divides, boolean hasIds, boolean stated,
                                     List<LoopPart.Combination> all) {
        StringBuilder args = new StringBuilder();
        for (String p : params.split(",")) {
            String[] words = p.trim().split(" ");
            args.append(args.length() == 0 ? "" : ", ").append(words[words.length - 1]);
        }
        String choice = ("boolean uv, " + (hasIds ? "boolean ids, " : "") + (divides ? "boolean divide," : "")).trim();
        String choiceArgs = "uv, " + (hasIds ? "ids, " : "") + (divides ? "divide, " : "");
        StringBuilder b = new StringBuilder("\n");
        b.append("    /**\n     * The loop of colour source {@code source} ({@link ColourSources})")
                .append(stated ? " and pixel state {@code state}\n     * ({@link PixelState})" : "")
                .append(", with the UV output when {@code uv}").append(hasIds ? " (and the ids), else the ids when {@code ids}" : "")
                .append(stated ? " (when the write has them)" : "")
                .append(divides ? ",\n     * dividing by the interpolated 1/w when {@code divide}" : "")
                .append(": chosen once per triangle,\n     * by source, then by state, then by the rest, each step small")
                .append(" enough to be inlined.\n     *\n     * @return pixels written\n     */\n");
        b.append("    static long fill(int source, ").append(stated ? "int state, " : "").append(choice)
                .append("\n            ").append(params).append(") {\n        switch (source) {\n");
        List<LoopPart> sources = new ArrayList<>();
        for (LoopPart.Combination k : all) {
            if (!sources.contains(k.source())) {
                sources.add(k.source());
                b.append("            case ColourSources.").append(k.source().constant()).append(":\n")
                        .append("                return fill").append(k.source().name()).append("(")
                        .append(stated ? "state, " : "").append(choiceArgs).append(args).append(");\n");
            }
        }
        b.append("            default:\n                throw new IllegalArgumentException(\"no colour source \" + source);\n")
                .append("        }\n    }\n");
        for (LoopPart s : sources) {
            b.append("\n    /** {@link #fill} of source ").append(s.name()).append(stated ? ", by pixel state" : "")
                    .append(". */\n    private static long fill").append(s.name()).append("(")
                    .append(stated ? "int state, " : "").append(choice).append("\n            ").append(params)
                    .append(") {\n");
            b.append(stated ? "        switch (state) {\n" : "");
            for (LoopPart.Combination k : all) {
                if (k.source() == s) {
                    String call = "fill" + k.source().name() + k.colour().name() + k.write().name() + "(" + choiceArgs
                            + args + ")";
                    b.append(stated ? "            case " + k.state() + ":\n                return " + call + ";\n"
                            : "        return " + call + ";\n");
                }
            }
            b.append(stated ? "            default:\n                throw new IllegalArgumentException("
                    + "\"no loop for pixel state \" + state);\n        }\n" : "").append("    }\n");
        }
        for (LoopPart.Combination k : all) {
            String indent = "        ";
            b.append("\n    /** {@link #fill} of ").append(k.source().name()).append(", ").append(k.colour().name())
                    .append(", ").append(k.write().name()).append(". */\n    private static long fill")
                    .append(k.source().name()).append(k.colour().name()).append(k.write().name()).append("(")
                    .append(choice).append("\n            ").append(params).append(") {\n");
            if (divides) {
                b.append(indent).append("if (divide) {\n").append(indent).append("    return ")
                        .append(call(k.dividing(true), divides, args, indent + "            ")).append(";\n")
                        .append(indent).append("}\n");
            }
            b.append(indent).append("return ").append(call(k, divides, args, indent + "        ")).append(";\n    }\n");
        }
        return b.toString();
    }

    /** The call of combination {@code k}'s loop, choosing by {@code uv} and {@code ids} where the write records. */
    private static String call(LoopPart.Combination k, boolean divides, CharSequence args, String indent) {
        String none = methodName(k.recording(false, false), divides) + "(" + args + ")";
        if (!k.uv()) {
            return none;
        }
        String uv = "uv ? " + methodName(k, divides) + "(" + args + ")\n" + indent + ": ";
        return k.ids() ? uv + "ids ? " + methodName(k.recording(false, true), divides) + "(" + args + ")\n" + indent
                + ": " + none : uv + none;
    }

    private static String methodName(LoopPart.Combination k, boolean divides) {
        String n = Character.toLowerCase(k.source().name().charAt(0)) + k.source().name().substring(1);
        return n + (k.colour().name().equals(COLOURS.get(0)) ? "" : k.colour().name())
                + (k.write().name().equals(WRITES.get(0)) ? "" : k.write().name())
                + (divides ? k.divide() ? "Divide" : "Affine" : "") + (k.uv() ? "Uv" : k.ids() ? "Ids" : "");
    }

    private static String method(String template, String templateName, LoopPart.Combination k, String name) {
        StringBuilder b = new StringBuilder();
        String[] all = template.split("\n", -1);
        for (int n = 0; n < all.length; n++) {
            if (all[n].isEmpty() && n == all.length - 1) {
                continue;
            }
            for (String kept : LoopPart.kept(all[n], k)) {
                String hook = kept.trim();
                if (hook.equals("$WRITE$") || hook.equals("$END_WRITE$")) {
                    // The write's code before or after the UV output's lines, indented as the line.
                    String indent = kept.substring(0, kept.indexOf('$'));
                    for (String line : k.write().raw(hook.equals("$WRITE$") ? "begin" : "end")) {
                        b.append(indent).append(line).append('\n');
                    }
                } else if (hook.matches("\\$[A-Z]+\\$")) {
                    // A hook line: the write's section of that name, then the source's, then the
                    // colour's, indented as the line, or nothing.
                    String indent = kept.substring(0, kept.indexOf('$'));
                    String section = hook.substring(1, hook.length() - 1).toLowerCase(Locale.ROOT);
                    List<String> lines = new ArrayList<>(k.write().lines(section, templateName, k));
                    lines.addAll(k.source().lines(section, templateName, k));
                    lines.addAll(k.colour().lines(section, templateName, k));
                    for (String line : lines) {
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
    private static String expressions(String line, String templateName, LoopPart.Combination k) {
        String combine = String.join(" ", k.colour().raw("combine"));
        for (String e : List.of("fixed", "double")) {
            String placeholder = "$" + e.toUpperCase(Locale.ROOT) + "$";
            if (line.contains(placeholder)) {
                line = line.replace(placeholder, combine.replace("$TEXEL$", k.source().expression(e, templateName, k)));
            }
        }
        List<String> step = k.source().lines("step", templateName, k);
        return line.replace("$STEP$", step.isEmpty() ? "" : ", " + String.join(" ", step));
    }

    private static String substitute(String line, LoopPart.Combination k, String name) {
        return line.replace("$NAME$", name).replace("$SOURCE_ID$", "ColourSources." + k.source().constant())
                .replace("$PIXEL_STATE$", k.state()).replace("$UV$", Boolean.toString(k.uv()))
                .replace("$IDS$", Boolean.toString(k.ids()));
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
}
