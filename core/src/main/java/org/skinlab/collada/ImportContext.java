package org.skinlab.collada;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.ImportWarning;

/**
 * State shared by the loaders while one file is imported: the file name for messages, the
 * document's id index, the parsed {@code <source>} cache and the warnings collected so far.
 * Every error and warning goes through here so that all of them name the file and the element.
 */
final class ImportContext {
    /** At most this many warnings are kept; a hostile file could otherwise produce millions. */
    static final int MAX_WARNINGS = 200;

    final String file;
    /** Where the document lives (for its relative URLs), or null when unknown. */
    final DocumentLocation location;
    private final XmlElement root;
    private final Map<String, XmlElement> ids = new HashMap<>();
    private final Map<XmlElement, Source> sources = new IdentityHashMap<>();
    private final List<ImportWarning> warnings = new ArrayList<>();
    private final Set<String> warnedOnce = new HashSet<>();
    private Set<String> nodeNames; // made on first use
    private int droppedWarnings;

    ImportContext(String file, XmlElement root) {
        this(file, null, root);
    }

    ImportContext(String file, Path location, XmlElement root) {
        this.file = file;
        this.location = new DocumentLocation(location);
        this.root = root;
        // Iterative walk: the tree may be as deep as SafeXmlReader allows.
        Deque<XmlElement> todo = new ArrayDeque<>();
        todo.push(root);
        List<XmlElement> duplicates = new ArrayList<>();
        while (!todo.isEmpty()) {
            XmlElement e = todo.pop();
            String id = e.id();
            if (id != null && ids.putIfAbsent(id, e) != null) {
                duplicates.add(e);
            }
            List<XmlElement> children = e.children();
            for (int i = children.size() - 1; i >= 0; i--) {
                todo.push(children.get(i));
            }
        }
        for (XmlElement d : duplicates) {
            warn(d, "duplicate id \"" + d.id() + "\"; references resolve to the first element with it");
        }
    }

    ColladaException error(XmlElement e, String problem) {
        return new ColladaException(file, e == null ? "document" : e.describe(), problem);
    }

    void warn(XmlElement e, String message) {
        if (warnings.size() < MAX_WARNINGS) {
            warnings.add(new ImportWarning(e == null ? "document" : e.describe(), message));
        } else {
            droppedWarnings++;
        }
    }

    /**
     * Warns only the first time {@code kind} comes up in this file: for exporter habits that
     * repeat on every source of a file (unnamed params, decimal commas), where one warning naming
     * the first place says all there is to say and a hundred would bury every other warning.
     */
    void warnOnce(String kind, XmlElement e, String message) {
        if (warnedOnce.add(kind)) {
            warn(e, message);
        }
    }

    /** The warning for numbers written with a decimal comma (once per file). */
    void warnDecimalComma(XmlElement e) {
        warnOnce("decimal-comma", e, "numbers are written with a decimal comma (a localised exporter); read with"
                + " the comma as the decimal point");
    }

    List<ImportWarning> warnings() {
        List<ImportWarning> result = new ArrayList<>(warnings);
        if (droppedWarnings > 0) {
            result.add(new ImportWarning("document", droppedWarnings + " more warnings not shown"));
        }
        return result;
    }

    /** The id, sid and name of every {@code <node>} of the document (library nodes included). */
    Set<String> nodeNames() {
        if (nodeNames == null) {
            nodeNames = new HashSet<>();
            Deque<XmlElement> todo = new ArrayDeque<>();
            todo.push(root);
            while (!todo.isEmpty()) {
                XmlElement e = todo.pop();
                if (e.name().equals("node")) {
                    for (String key : new String[] {e.id(), e.attr("sid"), e.attr("name")}) {
                        if (key != null) {
                            nodeNames.add(key);
                        }
                    }
                }
                for (XmlElement c : e.children()) {
                    todo.push(c);
                }
            }
        }
        return nodeNames;
    }

    /** The document's root element. */
    XmlElement root() {
        return root;
    }

    /** The element with the given id, or null. */
    XmlElement byId(String id) {
        return ids.get(id);
    }

    /** A required attribute. */
    String attr(XmlElement e, String name) throws ColladaException {
        String v = e.attr(name);
        if (v == null) {
            throw error(e, "missing attribute " + name);
        }
        return v;
    }

    /** A required child element. */
    XmlElement child(XmlElement e, String name) throws ColladaException {
        XmlElement c = e.child(name);
        if (c == null) {
            throw error(e, "missing <" + name + ">");
        }
        return c;
    }

    /** A non-negative integer attribute, or {@code fallback} when absent. */
    int count(XmlElement e, String name, int fallback) throws ColladaException {
        String v = e.attr(name);
        if (v == null) {
            return fallback;
        }
        try {
            long n = Long.parseLong(v.trim());
            if (n < 0 || n > Integer.MAX_VALUE) {
                throw error(e, name + "=\"" + v + "\" is out of range");
            }
            return (int) n;
        } catch (NumberFormatException ex) {
            throw error(e, name + "=\"" + v + "\" is not a non-negative integer");
        }
    }

    /**
     * The required {@code offset} of an {@code <input>} in a primitive or {@code <vertex_weights>}.
     * The index stride is the largest offset + 1, so the largest int is refused here: its stride
     * would overflow to a negative number and turn every later count check into nonsense.
     */
    int inputOffset(XmlElement input) throws ColladaException {
        int offset = count(input, "offset", -1);
        if (offset < 0) {
            throw error(input, "missing attribute offset");
        }
        if (offset == Integer.MAX_VALUE) {
            throw error(input, "offset=\"" + input.attr("offset") + "\" is out of range");
        }
        return offset;
    }

    /** A finite float attribute, or {@code fallback} when absent. */
    double number(XmlElement e, String name, double fallback) throws ColladaException {
        String v = e.attr(name);
        if (v == null) {
            return fallback;
        }
        String text = v.trim();
        if (text.indexOf(',') >= 0 && text.indexOf('.') < 0 && text.indexOf(',') == text.lastIndexOf(',')) {
            text = text.replace(',', '.'); // meter="0,01" from a localised exporter
            warnDecimalComma(e);
        }
        try {
            double d = Double.parseDouble(text);
            if (!Double.isFinite(d)) {
                throw error(e, name + "=\"" + v + "\" is not a finite number");
            }
            return d;
        } catch (NumberFormatException ex) {
            throw error(e, name + "=\"" + v + "\" is not a number");
        }
    }

    /**
     * Resolves a URI fragment reference ({@code "#id"}) held in attribute {@code attribute} (or in
     * the text when {@code attribute} is null) to an element with one of the expected names.
     * References to other documents are refused: the importer never opens other files.
     */
    XmlElement resolve(XmlElement from, String attribute, String... expected) throws ColladaException {
        String ref = attribute == null ? from.text().trim() : attr(from, attribute);
        String where = where(ref, attribute);
        XmlElement target = ids.get(referencedId(from, attribute));
        if (target == null) {
            throw error(from, where + " refers to nothing in the file");
        }
        for (String name : expected) {
            if (target.name().equals(name)) {
                return target;
            }
        }
        throw error(from, where + " refers to a <" + target.name() + ">, expected <"
                + String.join("> or <", expected) + ">");
    }

    /**
     * The id a reference names, whether or not an element has it: {@code "#id"}; {@code
     * "self.dae#id"} when the document names itself by its file name (warned once per file);
     * a bare id (warned when it exists). A reference into another document is refused.
     */
    String referencedId(XmlElement from, String attribute) throws ColladaException {
        String ref = attribute == null ? from.text().trim() : attr(from, attribute);
        int hash = ref.indexOf('#');
        if (hash == 0) {
            return ref.substring(1);
        }
        if (hash > 0) {
            if (!location.isThisDocument(ref.substring(0, hash))) {
                throw error(from, where(ref, attribute) + " points into another document; only references within the"
                        + " file are supported");
            }
            // "self.dae#id": the document names itself by its file name (some exporters do).
            warnOnce("self-url", from, where(ref, attribute) + " names this document by its file name; read as \""
                    + ref.substring(hash) + "\"");
            return ref.substring(hash + 1);
        }
        // Not a URI fragment, but some exporters write bare ids.
        if (ids.containsKey(ref)) {
            warn(from, where(ref, attribute) + " lacks the leading '#'; read as \"#" + ref + "\"");
        }
        return ref;
    }

    /**
     * The id part of a reference, without checks or warnings: what follows '#', or the whole
     * text (a bare id). For lookups that may fail quietly; {@link #referencedId} is the checked one.
     */
    static String idPart(String ref) {
        return ref.substring(ref.indexOf('#') + 1);
    }

    private static String where(String ref, String attribute) {
        return attribute == null ? "reference \"" + ref + "\"" : attribute + "=\"" + ref + "\"";
    }

    /** The parsed {@code <source>} (cached: sources are often shared). */
    Source source(XmlElement sourceElement) throws ColladaException {
        Source s = sources.get(sourceElement);
        if (s == null) {
            s = Source.parse(this, sourceElement);
            sources.put(sourceElement, s);
        }
        return s;
    }

    /** Resolves an {@code <input source="#...">} to its parsed source. */
    Source inputSource(XmlElement input) throws ColladaException {
        return source(resolve(input, "source", "source"));
    }
}
