// The vertex shader text the add-on puts in place of three's skinning chunks: a header that
// declares what core's skinning.glsl expects of its host (its comment lists it), that text
// itself, and three small chunks that call dqs() or cor() where three blends its bone matrices.
// Everything else of three's shader (morphs before skinning, lighting, fog, shadows received)
// stays three's.
import SKINNING_GLSL from './generated/skinning-glsl.js';
import {DUAL_TEXEL, MATRIX_ROWS, ROTATION_TEXEL, SCALE_ROWS} from './palette.js';

/** The vertex attribute GLTFLoader makes of skinlab's _COR_CENTER (it lower-cases unknown names). */
export const COR_ATTRIBUTE = '_cor_center';

/**
 * The header, GLSL ES 3.00. The palette is one float texture, a row per joint of 8 texels (see
 * palette.js). Slot 0 must be the heaviest influence (the DQS pivot): glTF files need not sort
 * JOINTS_0, so skinlabChoosePivot() finds the heaviest slot per vertex and jointAt/weightAt swap it
 * with slot 0. Weights are divided by their sum, as core's skinning path does.
 */
function header(influences, method) {
    return `
#define SKINLAB_INFLUENCES ${influences}
uniform highp sampler2D skinlabPalette;
#if SKINLAB_INFLUENCES > 4
in vec4 joints_1;
in vec4 weights_1;
#endif
${method === 'cor' ? `in vec3 ${COR_ATTRIBUTE};` : ''}
const int MATRIX_ROWS = ${MATRIX_ROWS};
const int SCALE_ROWS = ${SCALE_ROWS};
int skinlabPivot;
float skinlabWeightScale;

float skinlabRawWeight(int i) {
#if SKINLAB_INFLUENCES > 4
    if (i >= 4) return weights_1[i - 4];
#endif
    return skinWeight[i];
}

float skinlabRawJoint(int i) {
#if SKINLAB_INFLUENCES > 4
    if (i >= 4) return joints_1[i - 4];
#endif
    return skinIndex[i];
}

int influenceCount() {
    return SKINLAB_INFLUENCES;
}

int skinlabSlot(int i) {
    return i == 0 ? skinlabPivot : (i == skinlabPivot ? 0 : i);
}

float weightAt(int i) {
    return skinlabRawWeight(skinlabSlot(i)) * skinlabWeightScale;
}

uint jointAt(int i) {
    return uint(skinlabRawJoint(skinlabSlot(i)) + 0.5);
}

vec4 paletteRow(int part, uint joint, int row) {
    return texelFetch(skinlabPalette, ivec2(part + row, int(joint)), 0);
}

vec4 paletteRotation(uint joint) {
    return texelFetch(skinlabPalette, ivec2(${ROTATION_TEXEL}, int(joint)), 0);
}

vec4 paletteDual(uint joint) {
    return texelFetch(skinlabPalette, ivec2(${DUAL_TEXEL}, int(joint)), 0);
}

// Only bfdqs() and the STBS functions of the shared text read bone rows; this add-on offers
// neither and never calls them, so the palette carries none (declared for the text to compile).
vec4 boneRow(uint joint, int row) {
    return vec4(0.0);
}

void skinlabChoosePivot() {
    skinlabPivot = 0;
    float heaviest = skinlabRawWeight(0);
    float sum = 0.0;
    for (int i = 0; i < SKINLAB_INFLUENCES; i++) {
        float w = skinlabRawWeight(i);
        sum += w;
        if (w > heaviest) {
            heaviest = w;
            skinlabPivot = i;
        }
    }
    skinlabWeightScale = sum > 0.0 ? 1.0 / sum : 0.0;
}
`;
}

/** The call of the method's function in the shared text for point P, normal N, into outP, outN. */
function call(method, p, n) {
    return method === 'dqs'
        ? `dqs(${p}, ${n}, skinlabP, skinlabN);`
        : `cor(${p}, ${n}, ${COR_ATTRIBUTE}, skinlabP, skinlabN);`;
}

/**
 * Rewrites a material's vertex shader (as onBeforeCompile gets it, chunks not yet expanded) to
 * skin by {@code method}: three's skinbase, skinnormal and skinning chunks replaced.
 *
 * @param {string} vertexShader three's vertex shader text
 * @param {'dqs'|'cor'} method
 * @param {4|8} influences influence slots per vertex (8 when the geometry has joints_1/weights_1)
 * @returns {string} the rewritten shader
 */
export function skinningVertexShader(vertexShader, method, influences) {
    const chunks = {
        '#include <skinning_pars_vertex>': `#include <skinning_pars_vertex>
#ifdef USE_SKINNING
${header(influences, method)}
${SKINNING_GLSL}
#endif`,
        '#include <skinbase_vertex>': `#ifdef USE_SKINNING
    skinlabChoosePivot();
#endif`,
        // The normal first (three transforms normals before positions): the shared functions
        // give both; for the normal the point is irrelevant (DQS and CoR turn normals by the
        // blended rotation after the scale phase's cofactor, neither of which depends on it).
        '#include <skinnormal_vertex>': `#ifdef USE_SKINNING
    {
        vec3 skinlabP;
        vec3 skinlabN;
        ${call(method, 'vec3(0.0)', 'objectNormal')}
        objectNormal = skinlabN;
#ifdef USE_TANGENT
        ${call(method, 'vec3(0.0)', 'objectTangent')}
        objectTangent = skinlabN;
#endif
    }
#endif`,
        '#include <skinning_vertex>': `#ifdef USE_SKINNING
    {
        vec3 skinlabP;
        vec3 skinlabN;
        ${call(method, 'transformed', 'vec3(0.0, 0.0, 1.0)')}
        transformed = skinlabP;
    }
#endif`,
    };
    let out = vertexShader;
    for (const [chunk, replacement] of Object.entries(chunks)) {
        if (!out.includes(chunk)) {
            throw new Error(`skinlab-three: the material's vertex shader has no ${chunk}; only materials built`
                + ' from three\'s skinning chunks can switch method');
        }
        out = out.replace(chunk, replacement);
    }
    return out;
}
