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
layout(location = 8) in vec4 aColor;      // the vertex colour (white when the mesh has none)
layout(location = 9) in vec3 aRest;       // the rest position (bind space), whichever way the mesh is skinned

uniform samplerBuffer uMatrices;      // 3 texels per joint: the rows of a 3x4 affine matrix
uniform samplerBuffer uDualQuaternions; // 2 texels per joint: rotation (x y z w), dual part
uniform samplerBuffer uScales;        // 3 texels per joint: rows of the scale/shear part
uniform samplerBuffer uBones;         // 6 texels per joint: the bone rows (Frame.boneRows), for methods that read bones

uniform int uSkinning;        // 0: positions are already posed (CPU), else SkinningGlsl.methodCode
uniform int uInfluences;      // 4 or 8
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
out vec4 vColor;
out float vScalar;            // weight view: weight; difference view: |LBS - DQS|
out vec3 vRest;               // checker view: where the pattern is fixed
out vec3 vPosed;              // for transform feedback: the skinned position before uModel

// The palette as skinning.glsl reads it: matrices, dual quaternions and scale parts each in
// their own texture buffer.
const int MATRIX_ROWS = 0;
const int SCALE_ROWS = 1;

int influenceCount() {
    return uInfluences;
}

float weightAt(int i) {
    return i < 4 ? aWeights0[i] : aWeights1[i - 4];
}

uint jointAt(int i) {
    return i < 4 ? aJoints0[i] : aJoints1[i - 4];
}

vec4 paletteRow(int part, uint joint, int row) {
    int texel = int(joint) * 3 + row;
    return part == SCALE_ROWS ? texelFetch(uScales, texel) : texelFetch(uMatrices, texel);
}

vec4 paletteRotation(uint joint) {
    return texelFetch(uDualQuaternions, int(joint) * 2);
}

vec4 paletteDual(uint joint) {
    return texelFetch(uDualQuaternions, int(joint) * 2 + 1);
}

vec4 boneRow(uint joint, int row) {
    return texelFetch(uBones, int(joint) * 6 + row);
}

// The methods' formulas the Android app's shader shares (core's skinning.glsl).
#include "skinning.glsl"

void main() {
    vec3 posed = aPosition;
    vec3 normal = aNormal;
    vScalar = 0.0;
    skin(uSkinning, aPosition, aNormal, aCentre, posed, normal);
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
    vColor = aColor;
    vRest = aRest;
    gl_Position = uViewProjection * world;
}
