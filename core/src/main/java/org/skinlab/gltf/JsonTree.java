package org.skinlab.gltf;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.StreamReadFeature;

/**
 * Parses a glTF JSON document with jackson-core's streaming parser into a small tree of plain
 * values ({@code LinkedHashMap}, {@code ArrayList}, {@code String}, {@code Long}, {@code Double},
 * {@code Boolean}, {@link #NULL}) that {@link JsonNode} walks with JSON paths.
 *
 * <p>Jackson's {@link StreamReadConstraints} bound what a hostile document can make us allocate
 * or recurse into: nesting depth {@value #MAX_DEPTH} (glTF nests fewer than 10 levels), strings
 * up to the largest data URI a buffer may have, numbers of at most 1000 digits. Duplicate keys
 * are refused (the specification leaves their meaning undefined).
 */
final class JsonTree {
    /** JSON {@code null}, distinct from a missing key. */
    static final Object NULL = new Object() {
        @Override
        public String toString() {
            return "null";
        }
    };

    static final int MAX_DEPTH = 64;

    private final GltfContext ctx;
    private final JsonParser parser;

    private JsonTree(GltfContext ctx, JsonParser parser) {
        this.ctx = ctx;
        this.parser = parser;
    }

    /** The document's root object, parsed from UTF-8 bytes {@code [offset, offset + length)}. */
    static JsonNode parse(GltfContext ctx, byte[] bytes, int offset, int length) throws GltfException {
        JsonFactory factory = JsonFactory.builder()
                .streamReadConstraints(StreamReadConstraints.builder()
                        .maxNestingDepth(MAX_DEPTH)
                        .maxStringLength(Math.max(1, length))
                        .maxNumberLength(1000)
                        .build())
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                .build();
        try (JsonParser p = factory.createParser(bytes, offset, length)) {
            JsonTree tree = new JsonTree(ctx, p);
            JsonToken first = p.nextToken();
            if (first != JsonToken.START_OBJECT) {
                throw ctx.error("", first == null ? "the JSON document is empty" : "the JSON document is not an object");
            }
            Object root = tree.value(first);
            if (p.nextToken() != null) {
                throw ctx.error("", "more content after the JSON document's root object");
            }
            return new JsonNode(ctx, "", root);
        } catch (JsonProcessingException e) {
            String where = e.getProcessor() instanceof JsonParser
                    ? ((JsonParser) e.getProcessor()).getParsingContext().pathAsPointer().toString() : "";
            throw new GltfException(ctx.file(), where, "invalid JSON: " + e.getOriginalMessage(), e);
        } catch (IOException e) {
            throw new GltfException(ctx.file(), "", "cannot read the JSON: " + e.getMessage(), e);
        }
    }

    private Object value(JsonToken token) throws IOException, GltfException {
        switch (token) {
            case START_OBJECT: {
                Map<String, Object> map = new LinkedHashMap<>();
                for (JsonToken t = parser.nextToken(); t != JsonToken.END_OBJECT; t = parser.nextToken()) {
                    String key = parser.currentName();
                    map.put(key, value(parser.nextToken()));
                }
                return map;
            }
            case START_ARRAY: {
                List<Object> list = new ArrayList<>();
                for (JsonToken t = parser.nextToken(); t != JsonToken.END_ARRAY; t = parser.nextToken()) {
                    list.add(value(t));
                }
                return list;
            }
            case VALUE_STRING:
                return parser.getText();
            case VALUE_NUMBER_INT:
                return parser.getNumberType() == JsonParser.NumberType.BIG_INTEGER
                        ? (Object) parser.getDoubleValue() : (Object) parser.getLongValue();
            case VALUE_NUMBER_FLOAT:
                return parser.getDoubleValue();
            case VALUE_TRUE:
                return Boolean.TRUE;
            case VALUE_FALSE:
                return Boolean.FALSE;
            case VALUE_NULL:
                return NULL;
            default:
                throw ctx.error(parser.getParsingContext().pathAsPointer().toString(), "unexpected JSON token " + token);
        }
    }
}
