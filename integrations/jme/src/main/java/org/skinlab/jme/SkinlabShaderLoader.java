package org.skinlab.jme;

import java.io.IOException;

import com.jme3.asset.AssetInfo;
import com.jme3.asset.AssetManager;
import com.jme3.shader.plugins.GLSLLoader;
import org.skinlab.skinning.SkinningGlsl;

/**
 * jME's GLSL loader, then skinlab's {@code #include "skinning.glsl"} expanded
 * ({@link SkinningGlsl#expand}): so the GPU path's vertex shader runs the very formulas the desktop
 * and Android apps run, from core's one copy, with jME's {@code #import}s resolved as usual. It
 * loads the files named {@code *.}{@value #EXTENSION}.
 */
public final class SkinlabShaderLoader extends GLSLLoader {
    /** The file extension of shaders that include skinning.glsl. */
    public static final String EXTENSION = "skinvert";

    /**
     * Registers this loader for {@value #EXTENSION} files with {@code assets}.
     *
     * @param assets the application's asset manager
     */
    public static void register(AssetManager assets) {
        assets.registerLoader(SkinlabShaderLoader.class, EXTENSION);
    }

    @Override
    public Object load(AssetInfo info) throws IOException {
        Object source = super.load(info);
        return source instanceof String ? SkinningGlsl.expand((String) source) : source;
    }
}
