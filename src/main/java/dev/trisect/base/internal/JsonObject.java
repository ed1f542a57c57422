package dev.trisect.base.internal;

import com.fasterxml.jackson.jr.ob.JSON;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One JSON object whose fields keep the order they were put in, written as one line by jackson-jr, so
 * names and strings (file paths, exception messages) are always escaped correctly. Every JSON line the
 * project prints is built with this class: one {@code put} per field, so adding a field is one line.
 *
 * <p>Numbers JSON cannot express (NaN, infinities) are written as {@code null}.
 */
public final class JsonObject {
    private static final JSON WRITER = JSON.std.with(JSON.Feature.WRITE_NULL_PROPERTIES);

    private final Map<String, Object> fields = new LinkedHashMap<>();

    /** Adds (or replaces) an integer field. */
    public JsonObject put(String name, long value) {
        fields.put(name, value);
        return this;
    }

    /** Adds a number field as the shortest decimal that reads back as {@code value}; non-finite as null. */
    public JsonObject put(String name, double value) {
        fields.put(name, Double.isFinite(value) ? value : null);
        return this;
    }

    /**
     * Adds a number field rounded half-up to a fixed number of decimals (always written with them, like
     * {@code %.3f}); non-finite as null.
     */
    public JsonObject put(String name, double value, int decimals) {
        fields.put(name, Double.isFinite(value)
                ? BigDecimal.valueOf(value).setScale(decimals, RoundingMode.HALF_UP) : null);
        return this;
    }

    /** Adds a string field (null writes JSON null). */
    public JsonObject put(String name, String value) {
        fields.put(name, value);
        return this;
    }

    /** Adds a boolean field. */
    public JsonObject put(String name, boolean value) {
        fields.put(name, value);
        return this;
    }

    /** Adds a nested object. */
    public JsonObject put(String name, JsonObject value) {
        fields.put(name, value.fields);
        return this;
    }

    /**
     * Adds an array; its elements may be numbers, strings, booleans, null or {@link JsonObject}s.
     * Non-finite doubles become null.
     */
    public JsonObject put(String name, List<?> values) {
        List<Object> copy = new ArrayList<>(values.size());
        for (Object v : values) {
            copy.add(v instanceof JsonObject o ? o.fields
                    : v instanceof Double d && !Double.isFinite(d) ? null : v);
        }
        fields.put(name, copy);
        return this;
    }

    /** Adds every field of {@code other}, in its order, after this object's own. */
    public JsonObject putAll(JsonObject other) {
        fields.putAll(other.fields);
        return this;
    }

    /** The object as one line of JSON, without a line break. */
    @Override
    public String toString() {
        try {
            return WRITER.asString(fields);
        } catch (IOException e) {
            // Only plain values are ever put in, which the writer cannot fail on.
            throw new UncheckedIOException(e);
        }
    }
}
