package org.skinlab.collada;

import java.io.CharConversionException;
import java.io.IOException;
import java.io.InputStream;
import java.io.UnsupportedEncodingException;
import java.util.Arrays;

import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;

import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.XMLReader;
import org.xml.sax.ext.DefaultHandler2;

/**
 * Reads XML into an {@link XmlElement} tree with a SAX parser configured so that a hostile file
 * cannot reach the network or other files, and cannot expand entities.
 *
 * <p>Policy: a document type declaration is refused outright. COLLADA files never need one, and
 * without a DTD there are no entities to expand (billion laughs), no external entities (XXE), no
 * parameter entities and no external DTD to load. The refusal is enforced three ways so that it
 * holds on every SAX implementation: the Xerces feature {@code disallow-doctype-decl} (JDK), a
 * lexical handler that throws on {@code startDTD} (Android's Expat-based parser reports the DTD
 * there before its internal subset), and an entity resolver that refuses every external entity.
 * Secure processing is switched on as a further guard where it is supported.
 *
 * <p>Other limits: element nesting deeper than {@link #MAX_DEPTH} is refused (it would only
 * serve to exhaust the stack of whatever walks the tree).
 *
 * <p>Android-safe: uses only {@code javax.xml.parsers} and {@code org.xml.sax}.
 */
final class SafeXmlReader {
    /** Deepest element nesting accepted; real COLLADA files stay far below (skeleton depth + ~6). */
    static final int MAX_DEPTH = 512;

    private static final String DISALLOW_DOCTYPE = "http://apache.org/xml/features/disallow-doctype-decl";
    private static final String EXTERNAL_GENERAL = "http://xml.org/sax/features/external-general-entities";
    private static final String EXTERNAL_PARAMETER = "http://xml.org/sax/features/external-parameter-entities";
    private static final String LOAD_EXTERNAL_DTD = "http://apache.org/xml/features/nonvalidating/load-external-dtd";
    private static final String LEXICAL_HANDLER = "http://xml.org/sax/properties/lexical-handler";

    private static final SAXParserFactory FACTORY = createFactory();

    /**
     * One parser per thread, reused: creating a JDK SAX parser costs about as much as importing a
     * small file. A parser is not thread-safe, hence one per thread.
     */
    private static final ThreadLocal<SAXParser> PARSERS = ThreadLocal.withInitial(() -> {
        try {
            synchronized (FACTORY) {
                return FACTORY.newSAXParser();
            }
        } catch (ParserConfigurationException | SAXException e) {
            throw new IllegalStateException("no usable SAX parser", e);
        }
    });

    private SafeXmlReader() {
    }

    private static SAXParserFactory createFactory() {
        SAXParserFactory f = SAXParserFactory.newInstance();
        f.setNamespaceAware(false);
        f.setValidating(false);
        f.setXIncludeAware(false);
        trySetFeature(f, XMLConstants.FEATURE_SECURE_PROCESSING, true);
        trySetFeature(f, DISALLOW_DOCTYPE, true);
        trySetFeature(f, EXTERNAL_GENERAL, false);
        trySetFeature(f, EXTERNAL_PARAMETER, false);
        trySetFeature(f, LOAD_EXTERNAL_DTD, false);
        return f;
    }

    private static void trySetFeature(SAXParserFactory f, String feature, boolean value) {
        try {
            f.setFeature(feature, value);
        } catch (ParserConfigurationException | SAXException e) {
            // Not every parser knows every feature (Android's does not know the Xerces ones);
            // the handler below enforces the same policy independently.
        }
    }

    /**
     * Parses the stream into a tree. The caller owns and closes the stream.
     *
     * @param fileName used in error messages only; never resolved
     */
    static XmlElement read(InputStream in, String fileName) throws ColladaException, IOException {
        TreeBuilder builder = new TreeBuilder(fileName);
        SAXParser parser = null;
        try {
            parser = PARSERS.get();
            XMLReader reader = parser.getXMLReader();
            reader.setContentHandler(builder);
            reader.setErrorHandler(builder);
            reader.setEntityResolver(builder);
            reader.setDTDHandler(builder);
            try {
                reader.setProperty(LEXICAL_HANDLER, builder);
            } catch (SAXException e) {
                // Without a lexical handler the disallow-doctype feature and the entity resolver
                // still refuse; every parser we ship on supports the property.
            }
            reader.parse(new InputSource(in));
        } catch (DocumentComplete done) {
            // the root element closed: the tree is complete
        } catch (Refusal r) {
            throw r.exception;
        } catch (SAXParseException e) {
            throw new ColladaException(fileName, "XML at line " + e.getLineNumber() + ", column "
                    + e.getColumnNumber() + builder.openElement(), explain(e), e);
        } catch (SAXException e) {
            throw new ColladaException(fileName, "XML" + builder.openElement(), explain(e), e);
        } catch (UnsupportedEncodingException e) {
            // The XML declaration names an encoding this platform cannot decode (UTF-7, or
            // nonsense): a property of the file, not an I/O failure.
            throw new ColladaException(fileName, "XML declaration", "encoding \"" + e.getMessage()
                    + "\" is not supported (use UTF-8 or UTF-16)", e);
        } catch (CharConversionException e) {
            // Bytes that are not valid in the document's encoding, when the parser throws them
            // rather than reporting a fatal error.
            throw new ColladaException(fileName, "XML" + builder.openElement(), "malformed XML: " + e.getMessage(), e);
        } finally {
            if (parser != null) {
                // Drop the handlers (and with them the tree) so a parser kept for the thread
                // holds no document; reset() restores the configured features.
                try {
                    parser.reset();
                } catch (UnsupportedOperationException e) {
                    PARSERS.remove(); // a parser that cannot be reset is not reused
                }
            }
        }
        if (builder.root == null) {
            throw new ColladaException(fileName, "XML", "the document has no root element");
        }
        return builder.root;
    }

    private static String explain(SAXException e) {
        String m = e.getMessage() == null ? e.toString() : e.getMessage();
        if (m.contains("disallow-doctype-decl") || m.contains("DOCTYPE")) {
            return "a DOCTYPE declaration is not allowed (refused to protect against entity expansion and"
                    + " external entities)";
        }
        return "malformed XML: " + m;
    }

    /** Ends parsing once the root element is closed; shared, without a stack trace (it is no error). */
    private static final class DocumentComplete extends SAXException {
        private static final long serialVersionUID = 1L;
        static final DocumentComplete INSTANCE = new DocumentComplete();

        private DocumentComplete() {
            super("document complete");
        }

        @Override
        public synchronized Throwable fillInStackTrace() {
            return this;
        }
    }

    /** A refusal raised inside the SAX callbacks, carrying the exception to rethrow. */
    private static final class Refusal extends SAXException {
        private static final long serialVersionUID = 1L;
        final transient ColladaException exception;

        Refusal(ColladaException exception) {
            super(exception.getMessage());
            this.exception = exception;
        }
    }

    /** Builds the tree; also refuses DTDs and external entities. */
    private static final class TreeBuilder extends DefaultHandler2 {
        private final String fileName;
        private Locator locator;
        XmlElement root;

        private XmlElement[] stack = new XmlElement[32];
        private StringBuilder[] text = new StringBuilder[32];
        private boolean[] hasText = new boolean[32];
        private int depth;

        TreeBuilder(String fileName) {
            this.fileName = fileName;
        }

        @Override
        public void setDocumentLocator(Locator locator) {
            this.locator = locator;
        }

        private int line() {
            return locator == null ? -1 : locator.getLineNumber();
        }

        /** ", inside <p> in <geometry id="g"> at line 40" for the innermost open element, or "". */
        String openElement() {
            return depth == 0 || stack[depth - 1] == null ? "" : ", inside " + stack[depth - 1].describe();
        }

        private Refusal refuse(String element, String problem) {
            return new Refusal(new ColladaException(fileName, element, problem));
        }

        @Override
        public void startElement(String uri, String localName, String qName, Attributes atts) throws SAXException {
            if (depth >= MAX_DEPTH) {
                throw refuse("<" + qName + "> at line " + line(),
                        "elements nested deeper than " + MAX_DEPTH + " levels");
            }
            int n = atts.getLength();
            String[] attributes = null;
            if (n > 0) {
                attributes = new String[2 * n];
                for (int i = 0; i < n; i++) {
                    attributes[2 * i] = stripPrefix(atts.getQName(i));
                    attributes[2 * i + 1] = atts.getValue(i);
                }
            }
            XmlElement parent = depth == 0 ? null : stack[depth - 1];
            XmlElement e = new XmlElement(stripPrefix(qName), parent, line(), attributes);
            if (parent == null) {
                root = e;
            } else {
                parent.addChild(e);
            }
            if (depth == stack.length) {
                int size = depth * 2;
                stack = Arrays.copyOf(stack, size);
                text = Arrays.copyOf(text, size);
                hasText = Arrays.copyOf(hasText, size);
            }
            stack[depth] = e;
            int numeric = numericKind(e.name());
            if (numeric != NOT_NUMERIC) {
                e.setNumbers(new NumberScanner(numeric == FLOATS, countHint(e.attr("count"))));
            } else if (text[depth] == null) {
                text[depth] = new StringBuilder(64);
            } else {
                text[depth].setLength(0);
            }
            hasText[depth] = false;
            depth++;
        }

        @Override
        public void characters(char[] ch, int start, int length) {
            if (depth == 0) {
                return;
            }
            int d = depth - 1;
            NumberScanner numbers = stack[d].numbers();
            if (numbers != null) {
                numbers.feed(ch, start, length); // straight from the parser's buffer, no String
                return;
            }
            if (!hasText[d]) {
                // Skip leading whitespace so indentation between child elements costs nothing.
                int end = start + length;
                while (start < end && isXmlWhitespace(ch[start])) {
                    start++;
                }
                if (start == end) {
                    return;
                }
                length = end - start;
                hasText[d] = true;
            }
            text[d].append(ch, start, length);
        }

        @Override
        public void endElement(String uri, String localName, String qName) throws SAXException {
            depth--;
            NumberScanner numbers = stack[depth].numbers();
            if (numbers != null) {
                numbers.finish();
            } else if (hasText[depth]) {
                StringBuilder sb = text[depth];
                stack[depth].setText(sb.toString());
                if (sb.capacity() > (1 << 16)) {
                    text[depth] = null; // do not keep megabyte buffers alive for small siblings
                }
            }
            stack[depth] = null;
            if (depth == 0) {
                // The document is complete. Stop here: after the root only comments and processing
                // instructions may follow, and the JDK parser detects the end of the input by
                // throwing and catching an exception, which costs as much as importing a small file.
                throw DocumentComplete.INSTANCE;
            }
        }

        // ---- refusals: DTDs and every kind of entity

        @Override
        public void startDTD(String name, String publicId, String systemId) throws SAXException {
            throw refuse("<!DOCTYPE " + name + "> at line " + line(), "a DOCTYPE declaration is not allowed"
                    + " (refused to protect against entity expansion and external entities)");
        }

        @Override
        public void startEntity(String name) throws SAXException {
            // The five predefined entities (&amp; &lt; ...) are reported here too; anything else
            // could only come from a DTD, which startDTD already refused.
            switch (name) {
                case "amp": case "lt": case "gt": case "quot": case "apos":
                    return;
                default:
                    throw refuse("entity &" + name + "; at line " + line(), "entities are not allowed");
            }
        }

        @Override
        public InputSource resolveEntity(String publicId, String systemId) throws SAXException {
            throw refuse("external entity " + systemId + " at line " + line(),
                    "external entities are not allowed (the importer never reads other files or the network)");
        }

        @Override
        public InputSource resolveEntity(String name, String publicId, String baseURI, String systemId)
                throws SAXException {
            return resolveEntity(publicId, systemId);
        }

        @Override
        public InputSource getExternalSubset(String name, String baseURI) throws SAXException {
            throw refuse("external DTD subset at line " + line(), "external DTDs are not allowed");
        }

        @Override
        public void unparsedEntityDecl(String name, String publicId, String systemId, String notationName)
                throws SAXException {
            throw refuse("entity " + name + " at line " + line(), "entity declarations are not allowed");
        }

        @Override
        public void fatalError(SAXParseException e) throws SAXException {
            throw e;
        }

        @Override
        public void error(SAXParseException e) throws SAXException {
            throw e;
        }
    }

    private static final int NOT_NUMERIC = 0;
    private static final int FLOATS = 1;
    private static final int INTS = 2;

    /**
     * Whether COLLADA elements of this name only ever hold a list of numbers (and which kind):
     * those are parsed while the XML is read instead of being kept as text.
     */
    private static int numericKind(String name) {
        switch (name) {
            case "float_array":
            case "matrix":
            case "translate":
            case "rotate":
            case "scale":
            case "lookat":
            case "skew":
            case "bind_shape_matrix":
                return FLOATS;
            case "int_array":
            case "p":
            case "v":
            case "vcount":
            case "h":
                return INTS;
            default:
                return NOT_NUMERIC;
        }
    }

    /** A count attribute as a capacity hint; -1 when absent or not a number. */
    private static int countHint(String count) {
        if (count == null) {
            return -1;
        }
        try {
            return Integer.parseInt(count.trim());
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    static boolean isXmlWhitespace(char c) {
        return c == ' ' || c == '\n' || c == '\t' || c == '\r';
    }

    private static String stripPrefix(String qName) {
        int colon = qName.indexOf(':');
        return colon < 0 ? qName : qName.substring(colon + 1);
    }
}
