package org.skinlab.collada;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * One element of the lightweight tree {@link SafeXmlReader} builds: local name, attributes,
 * children, text and the line it started on (for error messages). COLLADA has no mixed content,
 * so an element has either children or text that matters.
 */
final class XmlElement {
    private static final String[] NO_ATTRIBUTES = new String[0];

    private final String name;
    private final XmlElement parent;
    private final int line;
    private final String[] attributes; // name, value, name, value, ...
    private List<XmlElement> children = Collections.emptyList();
    private String text = "";
    private NumberScanner numbers;

    XmlElement(String name, XmlElement parent, int line, String[] attributes) {
        this.name = name;
        this.parent = parent;
        this.line = line;
        this.attributes = attributes == null ? NO_ATTRIBUTES : attributes;
    }

    void addChild(XmlElement child) {
        if (children.isEmpty()) {
            children = new ArrayList<>(4);
        }
        children.add(child);
    }

    void setText(String text) {
        this.text = text;
    }

    /** Numbers scanned while the XML was read (numeric elements only), or null. */
    NumberScanner numbers() {
        return numbers;
    }

    void setNumbers(NumberScanner numbers) {
        this.numbers = numbers;
    }

    String name() {
        return name;
    }

    XmlElement parent() {
        return parent;
    }

    int line() {
        return line;
    }

    /** The attribute's value, or null when absent. */
    String attr(String attributeName) {
        for (int i = 0; i < attributes.length; i += 2) {
            if (attributes[i].equals(attributeName)) {
                return attributes[i + 1];
            }
        }
        return null;
    }

    String id() {
        return attr("id");
    }

    List<XmlElement> children() {
        return children;
    }

    /** All direct children with the given local name, in document order. */
    List<XmlElement> children(String childName) {
        List<XmlElement> result = null;
        for (XmlElement c : children) {
            if (c.name.equals(childName)) {
                if (result == null) {
                    result = new ArrayList<>(4);
                }
                result.add(c);
            }
        }
        return result == null ? Collections.emptyList() : result;
    }

    /** The first direct child with the given local name, or null. */
    XmlElement child(String childName) {
        for (XmlElement c : children) {
            if (c.name.equals(childName)) {
                return c;
            }
        }
        return null;
    }

    /**
     * The element's character content (whitespace-only content is the empty string). Numeric
     * elements keep no text: see {@link #numbers()}.
     */
    String text() {
        return text;
    }

    /** Describes the element for messages: {@code <p> in <geometry id="g"> at line 40}. */
    String describe() {
        StringBuilder sb = new StringBuilder();
        appendTag(sb, this);
        if (attr("id") == null) {
            for (XmlElement a = parent; a != null; a = a.parent) {
                if (a.attr("id") != null) {
                    sb.append(" in ");
                    appendTag(sb, a);
                    break;
                }
            }
        }
        if (line > 0) {
            sb.append(" at line ").append(line);
        }
        return sb.toString();
    }

    private static void appendTag(StringBuilder sb, XmlElement e) {
        sb.append('<').append(e.name);
        String id = e.attr("id");
        if (id != null) {
            sb.append(" id=\"").append(id).append('"');
        } else {
            String sid = e.attr("sid");
            if (sid != null) {
                sb.append(" sid=\"").append(sid).append('"');
            }
        }
        sb.append('>');
    }

    @Override
    public String toString() {
        return describe();
    }
}
