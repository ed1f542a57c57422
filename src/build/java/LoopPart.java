import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A piece of the pixel loops read from its file ({@link LoopGenerator} gives the syntax): a colour
 * source, a colour or a write, as its sections by name ({@code "setup"}, or {@code "setup KnotLoops"}
 * for one template only), each a list of lines; and how a line of a template or a source is kept for
 * one combination of the pieces ({@link #kept}).
 */
record LoopPart(String name, String description, Map<String, List<String>> sections) {
    /** The vertex layout's slot of a colour's first varying: slots 0 and 1 are the texel coordinates. */
    static final int FIRST_COLOUR_SLOT = 2;
    /** One marker at the end of a line of a template or a source. */
    private static final Pattern MARKER = Pattern.compile(" //#(!?)([a-zA-Z]+)(?:=([a-zA-Z,]+))?$");

    /** One loop's place in the dimensions. */
    record Combination(LoopPart source, LoopPart colour, LoopPart write, boolean uv, boolean ids, boolean divide) {
        /** The loop's {@code PixelState}, as a constant expression. */
        String state() {
            return "PixelState." + colour.constant() + " | PixelState." + write.constant();
        }

        /** With the UV output (which brings the ids) or the ids alone or neither. */
        Combination recording(boolean uvOn, boolean idsOn) {
            return new Combination(source, colour, write, uvOn, idsOn, divide);
        }

        Combination dividing(boolean on) {
            return new Combination(source, colour, write, uv, ids, on);
        }
    }

    /**
     * The line as written for combination {@code k}, without its markers: none when a marker excludes
     * it, one per varying of the colour ({@code $V$}, {@code $K$} replaced) when it is marked
     * {@code //#varying}, else one.
     */
    static List<String> kept(String line, Combination k) {
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
            case "ids":
                return k.ids;
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
    static String keep(String line, String dim, boolean value) {
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

    /**
     * LoopPart {@code name} from {@code NAME.source} in {@code dir}, or, where there is none and the name
     * ends in {@code Pot} or {@code Any}, from its family's file (the name without that ending) with
     * the lines marked {@code //#pot} kept only for Pot and those marked {@code //#!pot} only for Any.
     */
    static LoopPart read(String name, Path dir, String extension, String... required) throws IOException {
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
        return new LoopPart(name, description.toString(), sections);
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
