package example;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL33C.*;
import static org.lwjgl.system.MemoryUtil.NULL;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.BufferUtils;
import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.stb.STBImageWrite;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * What a desktop app that depends on {@code org.skinlab:skinlab-core} does to show a character, in
 * one class: it plays the model on skinlab's simulation thread, skinned on the CPU with dual
 * quaternions (DQS), and draws every frame with LWJGL and OpenGL 3.3 core. Each frame's deformed
 * positions and normals go into vertex buffers as they are, the mesh's triangles index them, and a
 * tiny shader lights them (Lambert); the camera frames the first frame's bounds.
 *
 * <p>The one thing to know about the data: points {@code [0, vertexCount)} of a
 * {@link SkinnedGeometry} are its mesh's render vertices in order, so {@link Mesh#triangles()}
 * index {@link Frame#positions(int)} and {@link Frame#normals(int)} directly (the points after
 * them are positions no triangle uses).
 *
 * <p>Usage: {@code java --add-modules jdk.incubator.vector -jar play-desktop.jar [FILE] [--frames N]
 * [--screenshot OUT.png]}. It plays in a window until the window is closed, or for N frames; with
 * {@code --screenshot} it draws N frames (60 unless given) in a hidden window and writes the last
 * one as PNG. It ends by printing what it drew, or with status 1 and one line when there is no
 * display or no OpenGL 3.3 (headless, run it under {@code xvfb-run -a}: Mesa's llvmpipe has 4.5).
 */
public final class PlayDesktop {
    private static final String VERTEX_SHADER = """
            #version 330 core
            layout(location = 0) in vec3 position;
            layout(location = 1) in vec3 normal;
            uniform mat4 model;           // the file's frame to Y up, in metres
            uniform mat4 viewProjection;
            out vec3 worldNormal;
            void main() {
                worldNormal = mat3(model) * normal;  // a rotation and a uniform scale
                gl_Position = viewProjection * model * vec4(position, 1.0);
            }
            """;
    private static final String FRAGMENT_SHADER = """
            #version 330 core
            in vec3 worldNormal;
            out vec4 color;
            const vec3 toLight = normalize(vec3(0.4, 0.8, 0.6));
            void main() {
                vec3 n = worldNormal / max(length(worldNormal), 1e-6);
                float lambert = max(dot(n, toLight), 0.0);
                color = vec4(vec3(0.85, 0.78, 0.70) * (0.2 + 0.8 * lambert), 1.0);
            }
            """;

    private static final String USAGE = "usage: play-desktop [FILE] [--frames N] [--screenshot OUT.png]";

    /** One geometry with a mesh, on the GPU: its vertex array, and the two buffers each frame refills. */
    private record Drawable(int geometry, int vertexCount, int triangleCount, int vao, int positions, int normals) {
    }

    /** Where the model is, Y up, for the camera. */
    private record Sphere(Vector3f centre, float radius) {
    }

    private PlayDesktop() {
    }

    public static void main(String[] args) {
        String file = "assets/characters/humanoid-walk.dae";
        int frames = -1; // until the window is closed
        Path screenshot = null;
        try {
            for (int i = 0; i < args.length; i++) {
                switch (args[i]) {
                    case "--frames" -> frames = Integer.parseUnsignedInt(args[++i]);
                    case "--screenshot" -> screenshot = Path.of(args[++i]);
                    default -> file = args[i];
                }
            }
        } catch (IndexOutOfBoundsException | NumberFormatException e) {
            fail(2, USAGE);
        }
        if (frames == 0 || file.startsWith("--")) {
            fail(2, USAGE);
        }
        if (screenshot != null && frames < 0) {
            frames = 60;
        }
        Model model = null;
        try {
            model = ModelImporter.read(Path.of(file));
        } catch (IOException | ImportException e) {
            fail(1, "cannot read " + file + ": " + (e instanceof NoSuchFileException ? "no such file" : e.getMessage()));
        }

        Matrix4f toYUp = model.asset().toYUpMeters(new Matrix4f()); // the file's frame to Y up, in metres
        AnimationConfig config = new AnimationConfig();
        config.setMethod(SkinningMethod.DQS); // skinned on the CPU (the default), with dual quaternions
        // Building the mesh is bind time (every method's data, CoR's centres too): done before the
        // window opens, so the GL thread never waits for it.
        SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, config);
        long window = openWindow("play-desktop: " + file, screenshot == null);
        try {
            List<Drawable> drawables = upload(mesh.geometries());
            if (drawables.isEmpty()) {
                fail(1, file + " has no mesh to draw");
            }
            int program = program();
            glUseProgram(program);
            glUniformMatrix4fv(glGetUniformLocation(program, "model"), false, toYUp.get(new float[16]));
            glEnable(GL_DEPTH_TEST);
            glClearColor(0.16f, 0.18f, 0.22f, 1f);

            mesh.start();
            Sphere bounds = null; // from the first frame
            float clipTime = 0;
            int drawn = 0;
            int[] width = new int[1];
            int[] height = new int[1];
            while (!glfwWindowShouldClose(window) && (frames < 0 || drawn < frames)) {
                try (Frame frame = mesh.acquire()) {
                    for (Drawable d : drawables) {
                        glBindBuffer(GL_ARRAY_BUFFER, d.positions());
                        glBufferData(GL_ARRAY_BUFFER, frame.positions(d.geometry()), GL_STREAM_DRAW);
                        glBindBuffer(GL_ARRAY_BUFFER, d.normals());
                        glBufferData(GL_ARRAY_BUFFER, frame.normals(d.geometry()), GL_STREAM_DRAW);
                    }
                    if (bounds == null) {
                        bounds = bounds(frame, drawables, toYUp);
                    }
                    clipTime = frame.clipTime();
                }
                glfwGetFramebufferSize(window, width, height);
                glViewport(0, 0, width[0], height[0]);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), false,
                        camera(bounds, width[0] / (float) Math.max(height[0], 1)).get(new float[16]));
                for (Drawable d : drawables) {
                    glBindVertexArray(d.vao());
                    glDrawElements(GL_TRIANGLES, 3 * d.triangleCount(), GL_UNSIGNED_INT, 0L);
                }
                if (++drawn == frames && screenshot != null) {
                    writePng(screenshot, width[0], height[0]);
                }
                glfwSwapBuffers(window);
                glfwPollEvents();
                mesh.throwIfFailed();
            }
            System.out.printf(Locale.ROOT, "drew %d frames of %s: %d points, %d triangles, clip time %.3f s%n", drawn,
                    file, drawables.stream().mapToInt(d -> mesh.geometries().get(d.geometry()).pointCount()).sum(),
                    drawables.stream().mapToInt(Drawable::triangleCount).sum(), clipTime);
        } finally {
            mesh.close(); // stops the simulation thread
            glfwDestroyWindow(window);
            glfwTerminate();
        }
    }

    /** A vertex array per geometry that has a mesh: its triangles once, its vertices refilled each frame. */
    private static List<Drawable> upload(List<SkinnedGeometry> geometries) {
        List<Drawable> drawables = new ArrayList<>();
        for (int g = 0; g < geometries.size(); g++) {
            Mesh mesh = geometries.get(g).mesh();
            if (mesh == null) {
                continue;
            }
            int vao = glGenVertexArrays();
            glBindVertexArray(vao);
            int[] buffers = {glGenBuffers(), glGenBuffers()}; // positions, normals: 3 floats per point
            for (int attribute = 0; attribute < 2; attribute++) {
                glBindBuffer(GL_ARRAY_BUFFER, buffers[attribute]);
                glVertexAttribPointer(attribute, 3, GL_FLOAT, false, 0, 0L);
                glEnableVertexAttribArray(attribute);
            }
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, glGenBuffers());
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.triangles(), GL_STATIC_DRAW);
            drawables.add(new Drawable(g, geometries.get(g).vertexCount(), mesh.triangleCount(), vao, buffers[0],
                    buffers[1]));
        }
        glBindVertexArray(0);
        return drawables;
    }

    /** The sphere around the box of the frame's render vertices, Y up. */
    private static Sphere bounds(Frame frame, List<Drawable> drawables, Matrix4f toYUp) {
        Vector3f min = new Vector3f(Float.POSITIVE_INFINITY);
        Vector3f max = new Vector3f(Float.NEGATIVE_INFINITY);
        Vector3f p = new Vector3f();
        for (Drawable d : drawables) {
            float[] positions = frame.positions(d.geometry());
            for (int i = 0; i < 3 * d.vertexCount(); i += 3) {
                toYUp.transformPosition(p.set(positions[i], positions[i + 1], positions[i + 2]));
                min.min(p);
                max.max(p);
            }
        }
        return new Sphere(min.add(max, new Vector3f()).mul(0.5f), max.distance(min) / 2);
    }

    /** Looks at the sphere from the front (+Z), a little from the side and above; it fills the height. */
    private static Matrix4f camera(Sphere bounds, float aspect) {
        float fovY = (float) Math.toRadians(35);
        float distance = 1.1f * bounds.radius() / (float) Math.sin(fovY / 2);
        Vector3f eye = new Vector3f(0.35f, 0.25f, 1f).normalize(distance).add(bounds.centre());
        return new Matrix4f().perspective(fovY, aspect, distance / 100, distance * 10)
                .lookAt(eye, bounds.centre(), new Vector3f(0, 1, 0));
    }

    private static int program() {
        int program = glCreateProgram();
        for (int type : new int[] {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER}) {
            int shader = glCreateShader(type);
            glShaderSource(shader, type == GL_VERTEX_SHADER ? VERTEX_SHADER : FRAGMENT_SHADER);
            glCompileShader(shader);
            if (glGetShaderi(shader, GL_COMPILE_STATUS) == GL_FALSE) {
                fail(1, "shader: " + glGetShaderInfoLog(shader));
            }
            glAttachShader(program, shader);
        }
        glLinkProgram(program);
        if (glGetProgrami(program, GL_LINK_STATUS) == GL_FALSE) {
            fail(1, "shader program: " + glGetProgramInfoLog(program));
        }
        return program;
    }

    /** A window with an OpenGL 3.3 core context, current on this thread; exits with one line if none can be had. */
    private static long openWindow(String title, boolean visible) {
        String[] error = {"no reason given"};
        glfwSetErrorCallback((code, description) -> error[0] = GLFWErrorCallback.getDescription(description));
        // X11 unless in a Wayland session: GLFW 3.4 would try Wayland first and complain.
        if (glfwPlatformSupported(GLFW_PLATFORM_X11) && System.getenv("WAYLAND_DISPLAY") == null) {
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        }
        if (!glfwInit()) {
            fail(1, "no display: " + error[0] + " (without a screen, run it under xvfb-run -a)");
        }
        glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE); // what macOS needs
        long window = glfwCreateWindow(960, 720, title, NULL, NULL);
        if (window == NULL) {
            fail(1, "no OpenGL 3.3 core context: " + error[0]);
        }
        glfwMakeContextCurrent(window);
        GL.createCapabilities();
        glfwSwapInterval(1);
        return window;
    }

    /** The back buffer, read before the swap, as PNG (stb_image_write: no AWT). */
    private static void writePng(Path file, int width, int height) {
        ByteBuffer rgb = BufferUtils.createByteBuffer(3 * width * height);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb);
        STBImageWrite.stbi_flip_vertically_on_write(true); // OpenGL's rows run bottom up
        if (!STBImageWrite.stbi_write_png(file.toString(), width, height, 3, rgb, 3 * width)) {
            fail(1, "cannot write " + file);
        }
    }

    private static void fail(int status, String message) {
        System.err.println("play-desktop: " + message);
        System.exit(status);
    }
}
