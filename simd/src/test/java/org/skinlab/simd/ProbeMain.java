package org.skinlab.simd;

import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.RandomRigs;

/** Run in a child JVM by {@link VectorSkinnerProviderTest}: prints which kernels Skinners picks. */
public final class ProbeMain {
    private ProbeMain() {
    }

    public static void main(String[] args) {
        var g = RandomRigs.geometry(1, 40, 4, 6);
        var palette = RandomRigs.palette(g, 2, false);
        StringBuilder sb = new StringBuilder();
        for (SkinningMethod m : SkinningMethod.values()) {
            Skinner s = Skinners.create(m, g.boundFor(m));
            float[] p = new float[3 * 40];
            float[] n = new float[3 * 40];
            s.skinAll(palette, p, n); // must run, whichever kernel it is
            sb.append(m.key()).append('=').append(s.implementation()).append(' ');
        }
        System.out.println(sb.toString().trim());
    }
}
