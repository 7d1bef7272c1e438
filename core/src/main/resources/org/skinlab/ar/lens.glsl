// The lens on the GPU: LensDistortion.distort's Brown-Conrady closed form, for the AR views'
// camera backgrounds. The model is drawn with the pinhole projection (ArCamera.projection), so the
// background must be the ideal pinhole image: for each of its pixels the fragment shader samples
// the camera image where the lens put that pixel's ray (the closed form, no inverse, no CPU remap).
// Both apps' background fragment shaders are made from this one text: the desktop's
// background.frag (GLSL 330) and the Android app's GlesShaders.backgroundFragment() (GLSL ES 3.00,
// highp: pixel coordinates need more than mediump's 11 bits), between their own header and main,
// at the line
//     #include "lens.glsl"
// that LensGlsl.expand replaces with this text (the same mechanism as skinning.glsl's).
//
// Conventions (CameraIntrinsics): pixel (i, j) has its centre at (i, j), so a texture coordinate
// s in [0, 1] across an image of w pixels is pixel s w - 0.5; pinhole = (fx, fy, cx, cy);
// radial = (k1, k2, k3), tangential = (p1, p2); all zero is the identity.

// Where the ideal normalised point n = (X / Z, Y / Z) appears, normalised (LensDistortion.distort).
vec2 lensDistort(vec2 n, vec3 radial, vec2 tangential) {
    float x2 = n.x * n.x;
    float y2 = n.y * n.y;
    float r2 = x2 + y2;
    float k = 1.0 + r2 * (radial.x + r2 * (radial.y + r2 * radial.z));
    float xy = n.x * n.y;
    return vec2(n.x * k + 2.0 * tangential.x * xy + tangential.y * (r2 + 2.0 * x2),
                n.y * k + tangential.x * (r2 + 2.0 * y2) + 2.0 * tangential.y * xy);
}

// The texture coordinate of the camera image (w x h pixels, t = 0 at its top row) that shows
// what the ideal pinhole image has at texture coordinate st (same layout).
vec2 lensSourceCoord(vec2 st, vec2 size, vec4 pinhole, vec3 radial, vec2 tangential) {
    vec2 pixel = st * size - 0.5;
    vec2 n = (pixel - pinhole.zw) / pinhole.xy;
    vec2 source = lensDistort(n, radial, tangential) * pinhole.xy + pinhole.zw;
    return (source + 0.5) / size;
}
