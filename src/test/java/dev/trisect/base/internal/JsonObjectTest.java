package dev.trisect.base.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import com.fasterxml.jackson.jr.ob.JSON;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonObjectTest {
    @Test
    void pathsWithQuotesBackslashesAndControlCharactersRoundTrip() throws Exception {
        String path = "C:\\renders\\\"best\" run\\a\tb\nc\u0001.png";
        String line = new JsonObject().put("file", path).put("note\"key\\", "x").toString();
        assertFalse(line.contains("\n"), "one line: " + line);
        Map<String, Object> back = JSON.std.mapFrom(line);
        assertEquals(path, back.get("file"));
        assertEquals("x", back.get("note\"key\\"));
    }

    @Test
    void fieldsKeepTheirOrderAndNestedObjectsAndListsAreWritten() {
        String line = new JsonObject().put("b", 1).put("a", "x")
                .put("ms", new JsonObject().put("total", 1.23456, 3).put("zero", 0.0, 3))
                .put("list", List.of(1.5, Double.NaN, "s")).put("ok", true).toString();
        assertEquals("{\"b\":1,\"a\":\"x\",\"ms\":{\"total\":1.235,\"zero\":0.000},\"list\":[1.5,null,\"s\"],"
                + "\"ok\":true}", line);
    }

    @Test
    void nonFiniteNumbersAreNull() {
        String line = new JsonObject().put("nan", Double.NaN).put("inf", Double.POSITIVE_INFINITY, 3)
                .put("s", (String) null).put("d", 2.5E-4).toString();
        assertEquals("{\"nan\":null,\"inf\":null,\"s\":null,\"d\":2.5E-4}", line);
    }

    @Test
    void putAllAppendsInOrder() {
        JsonObject tail = new JsonObject().put("c", 3).put("d", 4);
        assertEquals("{\"a\":1,\"c\":3,\"d\":4}", new JsonObject().put("a", 1).putAll(tail).toString());
    }
}
