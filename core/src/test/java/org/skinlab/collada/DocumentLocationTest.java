package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/**
 * Image URLs as real exporters write them (every form below was found in public files: 3ds Max
 * with ColladaMax, OpenCOLLADA and FBX, modo, Maya, Blender, MeshLab), and how they resolve against
 * the document's folder.
 */
class DocumentLocationTest {
    private static final DocumentLocation DOC = new DocumentLocation(Path.of("/models/monster/monster.dae"));

    private static Path resolve(String url) {
        return DOC.resolve(url);
    }

    @Test
    void relativePathsResolveAgainstTheDocumentsFolder() {
        assertEquals(Path.of("/models/monster/skin.png"), resolve("skin.png"));
        assertEquals(Path.of("/models/textures/skin.png"), resolve("../textures/skin.png"));
        assertEquals(Path.of("/models/X/top.tga"), resolve("./../X/top.tga"));
        assertEquals(Path.of("/models/monster/my skin.png"), resolve("my%20skin.png"));
        assertEquals(Path.of("/models/monster/tex/skin.png"), resolve("tex\\skin.png"));
        assertEquals(Path.of("/models/monster/\u00e9t\u00e9.png"), resolve("%C3%A9t%C3%A9.png"), "UTF-8 escapes");
    }

    @Test
    void fileUrlsWithThreeSlashesAreAbsolute() {
        assertEquals(Path.of("/home/me/skin.png"), resolve("file:///home/me/skin.png"));
        assertEquals(Path.of("C:/Program Files/a.exr").normalize(), resolve("file:///C:/Program%20Files/a.exr"));
        assertEquals(Path.of("/x/skin.png"), resolve("file://localhost/x/skin.png"));
    }

    @Test
    void fileUrlsWithTwoSlashesAreRelativePathsNotHosts() {
        // 3ds Max and the FBX exporter: "file://monster.jpg" beside the document.
        assertEquals(Path.of("/models/monster/monster.jpg"), resolve("file://monster.jpg"));
        assertEquals(Path.of("/models/LWO/earth.jpg"), resolve("file://..\\LWO\\earth.jpg"));
    }

    @Test
    void aLeadingSeparatorBeforeDotDotIsRelative() {
        // FBX: "\..\LWO\LWO2\EarthCylindric.jpg" cannot mean above the root.
        assertEquals(Path.of("/models/LWO/LWO2/EarthCylindric.jpg"), resolve("\\..\\LWO\\LWO2\\EarthCylindric.jpg"));
    }

    @Test
    void aRelativePathToAnotherDriveIsThatDrivesPath() {
        // OpenCOLLADA Max: "../../../C:/Dropbox/..." from a document on another drive.
        assertEquals(Path.of("C:/Dropbox/Cheetah_D.psd").normalize(),
                resolve("../../../../../../C:/Dropbox/Cheetah_D.psd"));
    }

    @Test
    void otherSchemesAreNoFiles() {
        assertNull(resolve("http://example.com/a.png"));
        assertNull(resolve("data:image/png;base64,iVBORw0KGgo="));
    }

    @Test
    void theDocumentRecognisesItselfByFileName() {
        assertTrue(DOC.isThisDocument("monster.dae"));
        assertTrue(DOC.isThisDocument("./monster.dae"));
        assertTrue(DOC.isThisDocument("../monster/monster.dae"));
        assertTrue(DOC.isThisDocument("file:///models/monster/monster.dae"));
        assertFalse(DOC.isThisDocument("other.dae"));
        assertFalse(DOC.isThisDocument("../other/monster.dae"));
        assertFalse(new DocumentLocation(null).isThisDocument("monster.dae"), "unknown location: nothing is itself");
    }
}
