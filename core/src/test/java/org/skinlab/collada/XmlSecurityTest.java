package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.model.Model;

/**
 * Attack files: the importer reads nothing but the file it is given, never touches the network,
 * expands no entity, and refuses quickly with a {@link ColladaException} naming the file. The
 * secret a successful attack would leak is a temporary file the test writes; the server an attack
 * would call is a {@link ServerSocket} the test opens on the loopback interface.
 */
class XmlSecurityTest {
    private static final Duration FAST = Duration.ofSeconds(2);
    private static final String DOCTYPE_REFUSED = "a DOCTYPE declaration is not allowed";
    private static final String SECRET = "skinlab-secret-7f3a9c";

    @TempDir
    Path dir;

    private Path secret;
    private ServerSocket server;

    @BeforeEach
    void setUp() throws IOException {
        secret = dir.resolve("secret.txt");
        Files.writeString(secret, SECRET);
        server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
    }

    @AfterEach
    void tearDown() throws IOException {
        server.close();
    }

    private String secretUri() {
        return secret.toUri().toString();
    }

    private String serverUrl(String path) {
        return "http://127.0.0.1:" + server.getLocalPort() + "/" + path;
    }

    /** Asserts that no connection reached the test server (waiting 500 ms for one). */
    private void assertNoConnection() throws IOException {
        server.setSoTimeout(500);
        try (Socket s = server.accept()) {
            throw new AssertionError("the importer connected to " + serverUrl("") + " from " + s.getRemoteSocketAddress());
        } catch (SocketTimeoutException expected) {
            // nobody called
        }
    }

    /** Asserts the refusal: quick, naming the file, stating the problem, never leaking the secret. */
    private static ColladaException refused(String file, byte[] bytes, String problem) {
        ColladaException e = assertTimeoutPreemptively(FAST, () -> assertThrows(ColladaException.class,
                () -> ColladaImporter.read(new ByteArrayInputStream(bytes), file)));
        assertTrue(e.getMessage().startsWith(file + ": "), e.getMessage());
        assertTrue(e.problem().contains(problem), () -> "\"" + problem + "\" not in: " + e.getMessage());
        for (Throwable t = e; t != null; t = t.getCause()) {
            assertFalse(String.valueOf(t).contains(SECRET), () -> "secret leaked in " + e.getMessage());
        }
        return e;
    }

    private static ColladaException refused(String file, String xml, String problem) {
        return refused(file, xml.getBytes(StandardCharsets.UTF_8), problem);
    }

    /** A small valid document whose authoring tool text is {@code tool} (entities would land there). */
    private static String document(String prolog, String tool) {
        return prolog + "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">"
                + "<asset><contributor><authoring_tool>" + tool + "</authoring_tool></contributor>"
                + "<up_axis>Z_UP</up_axis></asset></COLLADA>";
    }

    // --------------------------------------------------------------------------------- entities

    @Test
    void predefinedEntitiesAndCharacterReferencesStillWork() {
        // The control: the five predefined entities and &#...; need no DTD and are not refused.
        Model m = Fixtures.read("plain.dae", document("", "A &amp; B &lt;&gt; &quot;&apos; &#65;&#x42;"));
        assertEquals("A & B <> \"' AB", m.asset().authoringTool());
    }

    @Test
    void externalGeneralEntityIsRefusedAndTheSecretNeverRead() {
        String xml = document("<?xml version=\"1.0\"?>\n<!DOCTYPE COLLADA [<!ENTITY xxe SYSTEM \"" + secretUri()
                + "\">]>\n", "&xxe;");
        ColladaException e = refused("xxe.dae", xml, DOCTYPE_REFUSED);
        assertTrue(e.element().contains("line 2"), e.getMessage());
    }

    @Test
    void externalEntityInAnAttributeIsRefused() {
        String xml = "<!DOCTYPE COLLADA [<!ENTITY xxe SYSTEM \"" + secretUri() + "\">]>"
                + "<COLLADA version=\"&xxe;\"/>";
        refused("xxe-attribute.dae", xml, DOCTYPE_REFUSED);
    }

    @Test
    void parameterEntityIsRefused() {
        String xml = document("<!DOCTYPE COLLADA [<!ENTITY % p SYSTEM \"" + secretUri() + "\"> %p;]>", "tool");
        refused("parameter-entity.dae", xml, DOCTYPE_REFUSED);
    }

    @Test
    void parameterEntityCallingTheNetworkIsRefusedWithoutAConnection() throws IOException {
        // The classic out-of-band exfiltration: a parameter entity that loads a DTD from a server.
        String xml = document("<!DOCTYPE COLLADA [<!ENTITY % remote SYSTEM \"" + serverUrl("evil.dtd") + "\"> %remote;]>",
                "tool");
        refused("oob.dae", xml, DOCTYPE_REFUSED);
        assertNoConnection();
    }

    @Test
    void externalDtdIsNeverFetched() throws IOException {
        String xml = document("<?xml version=\"1.0\"?>\n<!DOCTYPE COLLADA SYSTEM \"" + serverUrl("collada.dtd") + "\">\n",
                "tool");
        refused("external-dtd.dae", xml, DOCTYPE_REFUSED);
        assertNoConnection();
    }

    @Test
    void publicDtdIsNeverFetched() throws IOException {
        String xml = document("<!DOCTYPE COLLADA PUBLIC \"-//skinlab//test//EN\" \"" + serverUrl("public.dtd") + "\">",
                "tool");
        refused("public-dtd.dae", xml, DOCTYPE_REFUSED);
        assertNoConnection();
    }

    @Test
    void schemaLocationAndStylesheetAreNotFetched() throws IOException {
        // Not attacks the parser may refuse (no DTD), but nothing may follow these URLs either.
        String xml = "<?xml version=\"1.0\"?>\n<?xml-stylesheet type=\"text/xsl\" href=\"" + serverUrl("style.xsl") + "\"?>\n"
                + "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\""
                + " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:schemaLocation=\""
                + "http://www.collada.org/2005/11/COLLADASchema " + serverUrl("collada.xsd") + "\">"
                + "<asset><up_axis>Z_UP</up_axis></asset></COLLADA>";
        Model m = assertTimeoutPreemptively(FAST, () -> Fixtures.read("schema.dae", xml));
        assertEquals(0, m.meshes().size());
        assertNoConnection();
    }

    @Test
    void billionLaughsIsRefusedQuickly() {
        // Ten levels of ten references: 10^9 "lol"s if expanded.
        StringBuilder dtd = new StringBuilder("<!DOCTYPE COLLADA [<!ENTITY lol0 \"lol\">");
        for (int i = 1; i <= 9; i++) {
            dtd.append("<!ENTITY lol").append(i).append(" \"");
            for (int k = 0; k < 10; k++) {
                dtd.append("&lol").append(i - 1).append(';');
            }
            dtd.append("\">");
        }
        dtd.append("]>");
        refused("laughs.dae", document(dtd.toString(), "&lol9;"), DOCTYPE_REFUSED);
    }

    @Test
    void quadraticBlowupIsRefusedQuickly() {
        // One 50,000-character entity referenced 50,000 times: 2.5 GB of text if expanded.
        String big = "x".repeat(50_000);
        String refs = "&big;".repeat(50_000);
        refused("quadratic.dae", document("<!DOCTYPE COLLADA [<!ENTITY big \"" + big + "\">]>", refs), DOCTYPE_REFUSED);
    }

    @Test
    void undeclaredEntityIsMalformed() {
        // Without a DTD an entity reference can only be an error.
        ColladaException e = refused("undeclared.dae", document("", "&xxe;"), "\"xxe\" was referenced, but not declared");
        assertTrue(e.element().contains("inside <authoring_tool>"), e.getMessage());
    }

    // ------------------------------------------------------------------------ encodings as disguise

    /** The XXE document in another encoding, with or without a byte order mark. */
    private byte[] xxeIn(String encoding, byte[] bom, boolean declare) {
        String xml = document((declare ? "<?xml version=\"1.0\" encoding=\"" + encoding + "\"?>" : "")
                + "<!DOCTYPE COLLADA [<!ENTITY xxe SYSTEM \"" + secretUri() + "\">]>", "&xxe;");
        byte[] body = xml.getBytes(Charset.forName(encoding));
        byte[] out = new byte[bom.length + body.length];
        System.arraycopy(bom, 0, out, 0, bom.length);
        System.arraycopy(body, 0, out, bom.length, body.length);
        return out;
    }

    @Test
    void utf16LittleEndianWithBomIsRefused() {
        refused("xxe-utf16le.dae", xxeIn("UTF-16LE", new byte[] {(byte) 0xFF, (byte) 0xFE}, false), DOCTYPE_REFUSED);
    }

    @Test
    void utf16BigEndianWithBomIsRefused() {
        refused("xxe-utf16be.dae", xxeIn("UTF-16BE", new byte[] {(byte) 0xFE, (byte) 0xFF}, false), DOCTYPE_REFUSED);
    }

    @Test
    void utf16WithoutBomButDeclaredIsRefused() {
        // No byte order mark: the parser recognises "<?" in UTF-16 from the first four bytes.
        refused("xxe-utf16-nobom.dae", xxeIn("UTF-16LE", new byte[0], true), DOCTYPE_REFUSED);
        refused("xxe-utf16be-nobom.dae", xxeIn("UTF-16BE", new byte[0], true), DOCTYPE_REFUSED);
    }

    @Test
    void utf8WithBomIsRefused() {
        refused("xxe-utf8bom.dae", xxeIn("UTF-8", new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF}, true),
                DOCTYPE_REFUSED);
    }

    @Test
    void ebcdicIsRefused() {
        // EBCDIC hides the DOCTYPE from byte-level filters; the parser still decodes it.
        assumeTrue(Charset.isSupported("IBM037"), "this JVM has no IBM037 charset");
        refused("xxe-ebcdic.dae", xxeIn("IBM037", new byte[0], true), DOCTYPE_REFUSED);
    }

    @Test
    void utf16DeclaredButUtf8EncodedIsMalformed() {
        // The declaration lies about the encoding: nothing may be read past the contradiction.
        byte[] bytes = document("<?xml version=\"1.0\" encoding=\"UTF-16\"?><!DOCTYPE COLLADA [<!ENTITY xxe SYSTEM \""
                + secretUri() + "\">]>", "&xxe;").getBytes(StandardCharsets.UTF_8);
        // The parser switches to UTF-16 after the declaration and sees garbage after it.
        refused("xxe-liar.dae", bytes, "malformed XML: Content is not allowed in prolog");
    }

    @Test
    void utf32IsRefused() {
        // Four bytes per character, recognised from the first four bytes and the declaration.
        refused("xxe-utf32.dae", xxeIn("UTF-32LE", new byte[0], true), DOCTYPE_REFUSED);
    }

    @Test
    void utf7IsRefused() {
        // "+ADw-" is "<" in UTF-7: a DOCTYPE invisible to anything that does not decode UTF-7.
        String xml = "<?xml version=\"1.0\" encoding=\"UTF-7\"?>+ADw-!DOCTYPE COLLADA +AFs-+ADw-!ENTITY xxe SYSTEM"
                + " +ACI-" + secretUri() + "+ACI-+AD4-+AF0-+AD4-+ADw-COLLADA+AD4-+ACY-xxe;+ADw-/COLLADA+AD4-";
        refused("xxe-utf7.dae", xml, "encoding \"UTF-7\" is not supported");
    }

    // ----------------------------------------------------------------------------- other files

    @Test
    void xincludeIsNotProcessed() throws IOException {
        // An XInclude of the secret as text: processed, it would become the authoring tool.
        // Unprocessed it is an unknown element, which COLLADA readers ignore.
        String include = "<xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"" + secretUri()
                + "\" parse=\"text\"/>";
        Model m = assertTimeoutPreemptively(FAST, () -> Fixtures.read("xinclude.dae", document("", include)));
        assertNull(m.asset().authoringTool());
        assertFalse(m.warnings().toString().contains(SECRET));
    }

    @Test
    void xincludeOfAFifoDoesNotBlock() throws Exception {
        // Opening a named pipe for reading blocks until someone writes: if the importer tried to
        // read the include, this test would time out instead of importing.
        Path fifo = fifo("include.pipe");
        String include = "<xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"" + fifo.toUri()
                + "\" parse=\"text\"/>";
        Model m = assertTimeoutPreemptively(FAST, () -> Fixtures.read("xinclude-fifo.dae", document("", include)));
        assertNull(m.asset().authoringTool());
    }

    @Test
    void referenceIntoAnotherDocumentIsRefused() throws IOException {
        // other.dae exists beside the file and holds the node, so following the reference would
        // succeed: the refusal shows it was not followed.
        Files.writeString(dir.resolve("other.dae"), QuadFixture.text());
        Path main = dir.resolve("main.dae");
        Files.writeString(main, QuadFixture.with("<instance_node url=\"#marker\"/>", "<instance_node url=\"other.dae#marker\"/>"));
        ColladaException e = assertTimeoutPreemptively(FAST, () -> assertThrows(ColladaException.class,
                () -> ColladaImporter.read(main)));
        assertEquals("main.dae", e.file());
        assertTrue(e.element().contains("<instance_node> in <node id=\"Tip\">"), e.getMessage());
        assertTrue(e.problem().contains("url=\"other.dae#marker\" points into another document"), e.getMessage());
    }

    @Test
    void referenceIntoAFifoIsRefusedWithoutOpeningIt() throws Exception {
        // As above, but other.dae is a named pipe: opening it would block the import.
        fifo("other.dae");
        Path main = dir.resolve("main.dae");
        Files.writeString(main, QuadFixture.with("<instance_geometry url=\"#quad\"/>",
                "<instance_geometry url=\"other.dae#quad\"/>"));
        ColladaException e = assertTimeoutPreemptively(FAST, () -> assertThrows(ColladaException.class,
                () -> ColladaImporter.read(main)));
        assertTrue(e.getMessage().startsWith("main.dae: <instance_geometry> in <node id=\"static-quad\">"), e.getMessage());
        assertTrue(e.problem().contains("points into another document"), e.getMessage());
    }

    @Test
    void absoluteFileAndHttpReferencesAreRefused() throws IOException {
        refused("file-url.dae", QuadFixture.with("<instance_geometry url=\"#quad\"/>",
                "<instance_geometry url=\"" + secretUri() + "#quad\"/>"), "points into another document");
        refused("http-url.dae", QuadFixture.with("<instance_geometry url=\"#quad\"/>",
                "<instance_geometry url=\"" + serverUrl("model.dae") + "#quad\"/>"), "points into another document");
        assertNoConnection();
    }

    /** Makes a named pipe in the temporary folder, or skips the test where mkfifo is missing. */
    private Path fifo(String name) throws Exception {
        Path fifo = dir.resolve(name);
        boolean made;
        try {
            Process p = new ProcessBuilder("mkfifo", fifo.toString()).redirectErrorStream(true).start();
            made = p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            made = false;
        }
        assumeTrue(made, "mkfifo is not available: named-pipe check skipped");
        return fifo;
    }
}
