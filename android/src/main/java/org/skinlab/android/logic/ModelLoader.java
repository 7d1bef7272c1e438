package org.skinlab.android.logic;

import java.io.IOException;
import java.io.InputStream;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

import org.skinlab.importer.ModelImporter;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The app's models (COLLADA or glTF: {@link ModelImporter} tells them apart; a {@code .gltf}
 * must be self-contained, as an asset has no folder to look for its buffers in), loaded one at a time on their own thread ({@value #THREAD}): imported, made a
 * {@link SkeletalAnimatedMesh} (not started), their CoR centres computed and their textures decoded
 * ({@link ModelTextures}) there, not on the GL thread when a model is first drawn. Each loaded
 * model goes to the listener on the loader thread;
 * the app swaps it in on its UI thread. A model the user skipped past before its turn is not loaded.
 * A model that fails, in any way, becomes {@link #problem()}: never the end of the thread.
 */
public final class ModelLoader implements AutoCloseable {
    /** The loader thread's name. */
    public static final String THREAD = "model-loader";

    /** Where a model's bytes come from (the APK's assets on a phone). */
    public interface Source {
        InputStream open(String name) throws IOException;
    }

    /** A loaded model: its simulation (the receiver closes it) and its decoded textures. */
    public record Loaded(SkeletalAnimatedMesh mesh, ModelTextures textures) {
    }

    private final Source source;
    private final AnimationConfig config;
    private final ModelTextures.Decoder decoder;
    private final Consumer<Loaded> loaded;
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, THREAD));
    private final AtomicInteger pending = new AtomicInteger();
    private volatile String wanted;
    private volatile String problem = "";

    /**
     * Loads from {@code source} for simulations under {@code config}, decoding textures with
     * {@code decoder}; {@code loaded} hears each model.
     */
    public ModelLoader(Source source, AnimationConfig config, ModelTextures.Decoder decoder, Consumer<Loaded> loaded) {
        this.source = source;
        this.config = config;
        this.decoder = decoder;
        this.loaded = loaded;
    }

    /** Loads {@code name} after the loads asked for before it (any thread). */
    public void load(String name) {
        wanted = name;
        pending.incrementAndGet();
        thread.execute(() -> {
            try {
                if (name.equals(wanted)) {
                    loadNow(name);
                }
            } finally {
                pending.decrementAndGet();
            }
        });
    }

    private void loadNow(String name) {
        SkeletalAnimatedMesh mesh = null;
        ModelTextures textures;
        try (InputStream in = source.open(name)) {
            // Bind time (CoR's centres too: up to half a second, then from the disk cache) is here, on this thread.
            mesh = SkeletalAnimatedMesh.of(ModelImporter.read(in, name, null), config);
            textures = ModelTextures.decode(mesh.model(), decoder);
        } catch (Throwable e) { // errors too: a model too big for the heap must not end the app
            String message = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
            problem = message.contains(name) ? message : name + ": " + message;
            if (mesh != null) {
                mesh.close();
            }
            return;
        }
        problem = textures.problems().isEmpty() ? "" : name + ": " + textures.problems().get(0);
        loaded.accept(new Loaded(mesh, textures));
    }

    /** Whether a load is asked for or under way. */
    public boolean loading() {
        return pending.get() > 0;
    }

    /**
     * Why the last model asked for did not load, or the first of its pictures that was left out,
     * or "" when it loaded whole (or none was asked for yet).
     */
    public String problem() {
        return problem;
    }

    /** Stops loading: a load under way is interrupted, the ones waiting are dropped. */
    @Override
    public void close() {
        thread.shutdownNow();
    }
}
