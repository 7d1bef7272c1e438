package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.model.AnimationClip;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.internal.metrics.InfluenceCapError;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * What {@code skinlab inspect} says of capping influences for a GPU (see {@link InfluenceCapError}):
 * per skinned mesh, for {@value #CAP_4} and {@value #CAP_8} influences, the largest LBS and DQS
 * position error over every clip of the file (the rest pose when it has none), with the clip and
 * time it happens at. A mesh is measured through the first instance that places it with a skin
 * ({@code Model.instances()} order); a mesh no instance places with a skin has no report.
 */
public final class InfluenceCapReport {
    static final int CAP_4 = 4;
    static final int CAP_8 = 8;
    private static final int[] CAPS = {CAP_4, CAP_8};

    /** The worst of one method over all clips; {@code clip} null when nothing moved (or no clip). */
    public record Worst(InfluenceCapError.Worst worst, String clip) {
    }

    /** One cap of one mesh. */
    public record Cap(int cap, int cappedPositions, float maxDroppedWeight, Worst lbs, Worst dqs) {
    }

    /**
     * One mesh: its influences per position, the rest size, the samples over all clips, the names
     * of the clips measured (empty: the rest pose alone) and one entry per cap.
     */
    public record MeshReport(int influences, double restSize, int samples, List<String> clips, List<Cap> caps) {
    }

    private InfluenceCapReport() {
    }

    /** Per mesh of the model (by identity), for the meshes some instance places with a skin. */
    public static Map<Mesh, MeshReport> of(Model model) {
        Map<Mesh, Integer> instanceOf = new IdentityHashMap<>();
        List<MeshInstance> instances = model.instances();
        for (int g = 0; g < instances.size(); g++) {
            if (instances.get(g).skin() != null) {
                instanceOf.putIfAbsent(instances.get(g).mesh(), g);
            }
        }
        Map<Mesh, MeshReport> reports = new IdentityHashMap<>();
        if (instanceOf.isEmpty()) {
            return reports;
        }
        List<AnimationClip> clips = model.clips().isEmpty() ? Collections.singletonList(null) : model.clips();
        List<String> clipNames = new ArrayList<>();
        for (AnimationClip clip : model.clips()) {
            clipNames.add(clip.name());
        }
        Map<Mesh, List<List<InfluenceCapError.Result>>> perClip = new IdentityHashMap<>();
        for (AnimationClip clip : clips) {
            // Normals are not compared: the cheaper rule will do.
            SkinnedModel skinned = new SkinnedModel(model, clip, NormalTransform.BLENDED_MATRIX,
                    EnumSet.of(SkinningMethod.LBS)); // poses and palettes: the caps are skinned apart
            List<List<InfluenceCapError.Result>> results = InfluenceCapError.measure(skinned, CAPS);
            for (Map.Entry<Mesh, Integer> e : instanceOf.entrySet()) {
                perClip.computeIfAbsent(e.getKey(), m -> new ArrayList<>()).add(results.get(e.getValue()));
            }
        }
        for (Map.Entry<Mesh, List<List<InfluenceCapError.Result>>> e : perClip.entrySet()) {
            reports.put(e.getKey(), merge(e.getValue(), clips, clipNames));
        }
        return reports;
    }

    /** One mesh's results of every clip (in clip order) as one report: the worst of each. */
    private static MeshReport merge(List<List<InfluenceCapError.Result>> byClip, List<AnimationClip> clips,
            List<String> clipNames) {
        List<InfluenceCapError.Result> first = byClip.get(0);
        int samples = 0;
        for (List<InfluenceCapError.Result> r : byClip) {
            samples += r.get(0).samples();
        }
        List<Cap> caps = new ArrayList<>();
        for (int c = 0; c < CAPS.length; c++) {
            Worst lbs = null;
            Worst dqs = null;
            for (int k = 0; k < byClip.size(); k++) {
                InfluenceCapError.Result r = byClip.get(k).get(c);
                String clip = clips.get(k) == null ? null : clips.get(k).name();
                lbs = worse(lbs, r.lbs(), clip);
                dqs = worse(dqs, r.dqs(), clip);
            }
            // Nothing moved in any clip: the first clip's (zero) result, at no clip.
            InfluenceCapError.Result r = first.get(c);
            caps.add(new Cap(CAPS[c], r.cappedPositions(), r.maxDroppedWeight(),
                    lbs != null ? lbs : new Worst(r.lbs(), null), dqs != null ? dqs : new Worst(r.dqs(), null)));
        }
        return new MeshReport(first.get(0).influences(), first.get(0).size(), samples, List.copyOf(clipNames),
                List.copyOf(caps));
    }

    /** The worse of the worst so far (null: none yet) and a clip's, which counts only if something moved. */
    private static Worst worse(Worst so, InfluenceCapError.Worst candidate, String clip) {
        boolean moved = candidate.position() >= 0;
        return moved && (so == null || candidate.distance() > so.worst().distance()) ? new Worst(candidate, clip) : so;
    }
}
