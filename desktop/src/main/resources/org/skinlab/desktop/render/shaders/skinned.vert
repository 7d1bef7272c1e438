#version 330 core
// Skins one vertex on the GPU from the frame's palette (Frame's class comment has the layouts),
// or passes through positions the CPU skinned. The palette lives in texture buffers, so any
// number of joints fits (a uniform array would stop near 200 joints on many drivers).

layout(location = 0) in vec3 aPosition;   // bind space (GPU skinning) or posed (CPU skinning)
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in uvec4 aJoints0;
layout(location = 4) in vec4 aWeights0;
layout(location = 5) in uvec4 aJoints1;   // influences 5-8 (zero weights with a 4-influence view)
layout(location = 6) in vec4 aWeights1;
layout(location = 7) in vec3 aCentre;     // CoR skinning: the point's centre of rotation (bind space)

uniform samplerBuffer uMatrices;      // 3 texels per joint: the rows of a 3x4 affine matrix
uniform samplerBuffer uDualQuaternions; // 2 texels per joint: rotation (x y z w), dual part
uniform samplerBuffer uScales;        // 3 texels per joint: rows of the scale/shear part

uniform int uSkinning;        // 0: positions are already posed (CPU), 1: LBS, 2: DQS, 3: CoR
uniform int uInfluences;      // 4 or 8
uniform bool uHasScale;       // DQS: run the scale phase first
uniform bool uMatricesMirror; // LBS normals: times the sign of the blend's determinant
uniform bool uScalesMirror;
uniform bool uCompare;        // difference view: also skin with the other method
uniform int uSelectedJoint;   // weight view

uniform mat4 uModel;          // upright and unit fix, placement on the floor
uniform mat4 uViewProjection;
uniform int uColumns;         // instances: a grid of copies, gl_InstanceID row by row
uniform float uSpacing;
uniform int uFirstInstance;   // grid cell of instance 0 (one draw per copy when each has its own pose)

out vec3 vWorld;
out vec3 vNormal;
out vec2 vUv;
out float vScalar;            // weight view: weight; difference view: |LBS - DQS|
out vec3 vPosed;              // for transform feedback: the skinned position before uModel

vec4 texel(samplerBuffer s, uint joint, int stride, int i) {
    return texelFetch(s, int(joint) * stride + i);
}

float weightAt(int i) {
    return i < 4 ? aWeights0[i] : aWeights1[i - 4];
}

uint jointAt(int i) {
    return i < 4 ? aJoints0[i] : aJoints1[i - 4];
}

// Weighted sum of the rows of a 3x4 matrix palette.
void blendRows(samplerBuffer s, out vec4 r0, out vec4 r1, out vec4 r2) {
    r0 = vec4(0.0); r1 = vec4(0.0); r2 = vec4(0.0);
    for (int i = 0; i < uInfluences; i++) {
        float w = weightAt(i);
        uint j = jointAt(i);
        r0 += w * texel(s, j, 3, 0);
        r1 += w * texel(s, j, 3, 1);
        r2 += w * texel(s, j, 3, 2);
    }
}

vec3 applyRows(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    vec4 h = vec4(p, 1.0);
    return vec3(dot(r0, h), dot(r1, h), dot(r2, h));
}

// The inverse transpose up to a positive factor: the cofactor matrix, as core's kernels do.
vec3 cofactorTimes(vec4 r0, vec4 r1, vec4 r2, vec3 n, bool mirrors) {
    vec3 c0 = cross(r1.xyz, r2.xyz);
    vec3 c1 = cross(r2.xyz, r0.xyz);
    vec3 c2 = cross(r0.xyz, r1.xyz);
    vec3 m = vec3(dot(c0, n), dot(c1, n), dot(c2, n));
    return mirrors && dot(r0.xyz, c0) < 0.0 ? -m : m;
}

void lbs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    vec4 r0, r1, r2;
    blendRows(uMatrices, r0, r1, r2);
    outP = applyRows(r0, r1, r2, p);
    outN = cofactorTimes(r0, r1, r2, n, uMatricesMirror);
}

vec3 rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

void dqs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    if (uHasScale) {
        vec4 s0, s1, s2;
        blendRows(uScales, s0, s1, s2);
        n = cofactorTimes(s0, s1, s2, n, uScalesMirror);
        p = applyRows(s0, s1, s2, p);
    }
    vec4 pivot = texel(uDualQuaternions, aJoints0.x, 2, 0);
    vec4 br = vec4(0.0);
    vec4 bd = vec4(0.0);
    for (int i = 0; i < uInfluences; i++) {
        uint j = jointAt(i);
        vec4 r = texel(uDualQuaternions, j, 2, 0);
        vec4 d = texel(uDualQuaternions, j, 2, 1);
        // Antipodality: each rotation on the pivot's side of the 4-sphere (Kavan et al. 2008).
        float w = dot(pivot, r) < 0.0 ? -weightAt(i) : weightAt(i);
        br += w * r;
        bd += w * d;
    }
    float len = length(br);
    br /= len;
    bd /= len;
    vec3 t = 2.0 * (br.w * bd.xyz - bd.w * br.xyz + cross(br.xyz, bd.xyz));
    outP = rotate(br, p) + t;
    outN = rotate(br, n);
}

// CoR (Le and Hodgins 2016): the rotations blended as in DQS, the translation LBS's (of the
// joints' rigid parts) at the point's centre of rotation; the scale phase first, as in DQS.
void cor(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    vec3 c = aCentre;
    if (uHasScale) {
        vec4 s0, s1, s2;
        blendRows(uScales, s0, s1, s2);
        n = cofactorTimes(s0, s1, s2, n, uScalesMirror);
        p = applyRows(s0, s1, s2, p);
        c = applyRows(s0, s1, s2, c);
    }
    vec4 pivot = texel(uDualQuaternions, aJoints0.x, 2, 0);
    vec4 q = vec4(0.0);
    vec3 t = vec3(0.0);
    for (int i = 0; i < uInfluences; i++) {
        uint j = jointAt(i);
        float w = weightAt(i);
        vec4 r = texel(uDualQuaternions, j, 2, 0);
        q += (dot(pivot, r) < 0.0 ? -w : w) * r;
        if (uHasScale) {
            // The rigid part D of a scaled joint, from its dual quaternion.
            vec4 d = texel(uDualQuaternions, j, 2, 1);
            t += w * (rotate(r, c) + 2.0 * (r.w * d.xyz - d.w * r.xyz + cross(r.xyz, d.xyz)));
        }
    }
    if (!uHasScale) {
        // D = M: LBS of the centre is the blended matrix applied once (as the CPU kernel does).
        vec4 m0, m1, m2;
        blendRows(uMatrices, m0, m1, m2);
        t = applyRows(m0, m1, m2, c);
    }
    q = normalize(q);
    outP = rotate(q, p - c) + t;
    outN = rotate(q, n);
}

void main() {
    vec3 posed = aPosition;
    vec3 normal = aNormal;
    vScalar = 0.0;
    if (uSkinning == 1) {
        lbs(aPosition, aNormal, posed, normal);
    } else if (uSkinning == 2) {
        dqs(aPosition, aNormal, posed, normal);
    } else if (uSkinning == 3) {
        cor(aPosition, aNormal, posed, normal);
    }
    if (uCompare) {
        vec3 pl, pd, unused;
        lbs(aPosition, aNormal, pl, unused);
        dqs(aPosition, aNormal, pd, unused);
        vScalar = distance(pl, pd);
    } else if (uSelectedJoint >= 0) {
        for (int i = 0; i < uInfluences; i++) {
            if (jointAt(i) == uint(uSelectedJoint)) {
                vScalar += weightAt(i);
            }
        }
    }
    vPosed = posed;
    int cell = gl_InstanceID + uFirstInstance;
    int column = cell % uColumns;
    int row = cell / uColumns;
    vec3 offset = vec3((float(column) - 0.5 * float(uColumns - 1)) * uSpacing, 0.0, -float(row) * uSpacing);
    vec4 world = uModel * vec4(posed, 1.0) + vec4(offset, 0.0);
    vWorld = world.xyz;
    vNormal = mat3(uModel) * normal;
    vUv = aUv;
    gl_Position = uViewProjection * world;
}
