package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.RandomRigs;

/** When the provider offers its kernels and when core's scalar ones run instead. */
class VectorSkinnerProviderTest {
    /** The methods with Vector API kernels: all of them. */
    private static final SkinningMethod[] WITH_VECTOR_KERNELS = SkinningMethod.values();

    @Test
    void skinnersPicksTheVectorKernelsForAnyInfluenceCount() {
        // This test JVM runs with --add-modules jdk.incubator.vector (simd/build.gradle) on an
        // AVX2 machine, and ServiceLoader finds the provider through META-INF/services.
        assertTrue(VectorSkinnerProvider.moduleAvailable());
        for (int width = 1; width <= 12; width++) {
            SkinnedGeometry g = RandomRigs.geometry(width, 20, width, 16);
            for (SkinningMethod m : WITH_VECTOR_KERNELS) {
                Skinner s = Skinners.create(m, g.boundFor(m), NormalTransform.INVERSE_TRANSPOSE);
                assertEquals("vector-256", s.implementation(), m + " with " + width + " influences");
                assertEquals(m, s.method());
                assertEquals(NormalTransform.INVERSE_TRANSPOSE, s.normalTransform());
                assertEquals(m == SkinningMethod.LBS ? 1 : 8, s.rangeAlignment());
            }
        }
        assertEquals("vector-256", Skinners.expansion(new int[] {0, 0}, new float[6]).implementation());
    }

    @Test
    void withoutTheIncubatorModuleSkinnersFallsBackToScalar() throws Exception {
        // A child JVM without --add-modules: the provider must decline (not fail to load) and
        // the scalar kernels run.
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process p = new ProcessBuilder(java.toString(), "-cp", classPath(), ProbeMain.class.getName())
                .redirectErrorStream(true).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "child JVM did not finish in 60 s");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertEquals(0, p.exitValue(), out);
        assertEquals(everyMethod("scalar"), out);
    }

    @Test
    void withTheModuleTheChildJvmGetsTheVectorKernels() throws Exception {
        // The same probe with the flag: shows the class path above is complete, so the fallback
        // seen without it comes from the missing module.
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process p = new ProcessBuilder(java.toString(), "--add-modules", VectorSkinnerProvider.MODULE, "-cp",
                classPath(), ProbeMain.class.getName()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "child JVM did not finish in 60 s");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertEquals(0, p.exitValue(), out);
        assertEquals(everyMethod("vector-256"), out);
    }

    /** Test classes (simd's and core's), simd's classes and resources (the service file), core and JOML. */
    private static String classPath() throws Exception {
        List<String> entries = new ArrayList<>();
        for (Class<?> c : new Class<?>[] {ProbeMain.class, org.skinlab.testing.RandomRigs.class,
                VectorSkinnerProvider.class, Skinners.class, org.joml.Matrix4f.class}) {
            entries.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        }
        URL service = VectorSkinnerProviderTest.class.getClassLoader()
                .getResource("META-INF/services/org.skinlab.skinning.SkinnerProvider");
        assertNotNull(service, "the service file is on the test class path");
        if (service.getProtocol().equals("file")) {
            entries.add(Path.of(service.toURI()).getParent().getParent().getParent().toString());
        }
        return String.join(File.pathSeparator, entries);
    }

    /** What ProbeMain prints when every method gets the implementation {@code implementation}. */
    private static String everyMethod(String implementation) {
        StringBuilder s = new StringBuilder();
        for (SkinningMethod m : SkinningMethod.values()) {
            s.append(s.length() == 0 ? "" : " ").append(m.key()).append('=').append(implementation);
        }
        return s.toString();
    }
}
