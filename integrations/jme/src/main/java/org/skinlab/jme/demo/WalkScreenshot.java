package org.skinlab.jme.demo;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import com.jme3.anim.AnimComposer;
import com.jme3.anim.tween.action.BlendableAction;
import com.jme3.app.SimpleApplication;
import com.jme3.asset.plugins.FileLocator;
import com.jme3.bounding.BoundingBox;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import com.jme3.system.AppSettings;
import com.jme3.system.JmeContext;
import com.jme3.texture.FrameBuffer;
import com.jme3.texture.Image;
import com.jme3.util.BufferUtils;
import org.skinlab.jme.SkinlabGltfExtension;
import org.skinlab.jme.SkinlabSkinningControl;
import org.skinlab.skinning.SkinningMethod;

/**
 * Renders a glb's character walking with the control's GPU path in an offscreen jME application
 * and saves one frame as PNG: {@code WalkScreenshot [MODEL.glb [OUT.png [METHOD [SECONDS]]]]}
 * (defaults: assets/characters/humanoid-walk.glb, docs/screenshot.png, cor, 0.5 s into the clip).
 * Needs an X display (xvfb-run -a under CI); fails when the frame shows almost nothing (under 1% of its
 * pixels away from the background colour).
 */
public final class WalkScreenshot extends SimpleApplication {
    private static final int WIDTH = 640;
    private static final int HEIGHT = 480;
    private final Path model;
    private final Path out;
    private final SkinningMethod method;
    private final float seconds;
    private final CountDownLatch done = new CountDownLatch(1);
    private FrameBuffer target;
    private int frame;
    private volatile Throwable error;

    private WalkScreenshot(Path model, Path out, SkinningMethod method, float seconds) {
        super(new com.jme3.app.state.AppState[0]);
        this.model = model;
        this.out = out;
        this.method = method;
        this.seconds = seconds;
    }

    public static void main(String[] args) throws Exception {
        Path model = Paths.get(args.length > 0 ? args[0] : "../../assets/characters/humanoid-walk.glb").toAbsolutePath();
        Path out = Paths.get(args.length > 1 ? args[1] : "docs/screenshot.png").toAbsolutePath();
        SkinningMethod method = SkinningMethod.fromKey(args.length > 2 ? args[2] : "cor");
        float seconds = args.length > 3 ? Float.parseFloat(args[3]) : 0.5f;
        WalkScreenshot app = new WalkScreenshot(model, out, method, seconds);
        AppSettings settings = new AppSettings(true);
        settings.setRenderer(AppSettings.LWJGL_OPENGL33);
        settings.setResolution(WIDTH, HEIGHT);
        settings.setAudioRenderer(null);
        app.setSettings(settings);
        app.setShowSettings(false);
        app.start(JmeContext.Type.OffscreenSurface);
        boolean finished = app.done.await(120, TimeUnit.SECONDS);
        app.stop(true);
        if (!finished || app.error != null) {
            throw new IllegalStateException("no screenshot of " + model, app.error);
        }
        System.out.println("wrote " + out + ": " + model.getFileName() + " skinned by " + method.key() + " on the GPU");
    }

    @Override
    public void simpleInitApp() {
        assetManager.registerLocator("/", FileLocator.class);
        SkinlabGltfExtension.register();
        Spatial character = assetManager.loadModel(model.toString());
        SkinlabSkinningControl.replace(character, method, SkinlabSkinningControl.Mode.GPU, assetManager);
        character.depthFirstTraversal(s -> {
            AnimComposer composer = s.getControl(AnimComposer.class);
            if (composer != null) {
                String clip = composer.getAnimClipsNames().iterator().next();
                // The clip's own pose at that time, without jME's 0.4 s fade-in from the rest pose.
                ((BlendableAction) composer.action(clip)).setTransitionLength(0);
                composer.setCurrentAction(clip);
                composer.setTime(seconds);
                composer.setGlobalSpeed(0);
            }
        });
        rootNode.attachChild(character);
        rootNode.updateGeometricState();
        BoundingBox box = (BoundingBox) character.getWorldBound();
        Vector3f centre = box.getCenter();
        float radius = box.getExtent(null).length();
        cam.setFrustumPerspective(35f, (float) WIDTH / HEIGHT, radius * 0.05f, radius * 20f);
        cam.setLocation(centre.add(new Vector3f(0.8f, 0.25f, 1.6f).normalizeLocal().multLocal(3.4f * radius)));
        cam.lookAt(centre, Vector3f.UNIT_Y);
        viewPort.setBackgroundColor(new ColorRGBA(0.78f, 0.82f, 0.88f, 1f));
        target = new FrameBuffer(WIDTH, HEIGHT, 1);
        target.addColorTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.RGBA8));
        target.setDepthTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.Depth));
        viewPort.setOutputFrameBuffer(target);
    }

    @Override
    public void simpleUpdate(float tpf) {
        // Frame 3: the two before it have run the control and drawn into the frame buffer.
        if (++frame == 3 && done.getCount() > 0) {
            try {
                save();
            } catch (Throwable t) {
                error = t;
            }
            done.countDown();
        }
    }

    @Override
    public void handleError(String errorMessage, Throwable t) {
        error = new IllegalStateException(errorMessage, t);
        done.countDown();
    }

    private static int colourDistance(int a, int b) {
        return Math.abs((a >> 16 & 0xff) - (b >> 16 & 0xff)) + Math.abs((a >> 8 & 0xff) - (b >> 8 & 0xff))
                + Math.abs((a & 0xff) - (b & 0xff));
    }

    private void save() throws IOException {
        ByteBuffer pixels = BufferUtils.createByteBuffer(4 * WIDTH * HEIGHT);
        renderer.readFrameBufferWithFormat(target, pixels, Image.Format.RGBA8);
        BufferedImage image = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                int i = 4 * ((HEIGHT - 1 - y) * WIDTH + x);
                int rgb = (pixels.get(i) & 0xff) << 16 | (pixels.get(i + 1) & 0xff) << 8 | (pixels.get(i + 2) & 0xff);
                image.setRGB(x, y, rgb);
            }
        }
        // The frame must show the character: enough pixels away from the background colour.
        int background = image.getRGB(0, 0);
        int covered = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                if (colourDistance(image.getRGB(x, y), background) > 24) {
                    covered++;
                }
            }
        }
        System.out.println("character covers " + covered + " of " + WIDTH * HEIGHT + " pixels");
        if (covered < WIDTH * HEIGHT / 100) {
            throw new IllegalStateException("the frame shows almost nothing: " + covered + " pixels differ from the background");
        }
        File file = out.toFile();
        file.getParentFile().mkdirs();
        ImageIO.write(image, "png", file);
    }
}
