// The skinning formulas on the GPU: LBS, DQS with its scale phase, CoR, as core's CPU kernels
// compute them (ScalarLbsSkinner, ScalarDqsSkinner, ScalarCorSkinner; Frame's class comment has
// the palette's layouts). Both apps' vertex shaders are made from this one text, so that they
// cannot drift apart: the desktop's skinned.vert (GLSL 330, the palette in texture buffers) and
// the Android app's GlesShaders.skinnedVertex() (GLSL ES 3.00, the palette in one float texture,
// PaletteTexture) each hold their own header (#version, precision, inputs, how the palette is
// fetched, how many influences) and main, and between them the line
//     #include "skinning.glsl"
// that SkinningGlsl.expand replaces with this text before the driver sees it (GLSL has no include).
//
// Why a Java resource of core, read at run time: both apps depend on core, so its jar brings the
// file to the desktop, to the Android tests and to R8 without a build step of its own, and one
// mechanism serves both apps (the desktop reads all its shaders as resources). To core it is only
// text: core gains no GL type. In the APK it sits at the root, where Android's class loader finds
// Java resources (android/build.gradle's apk task adds it; android/check-apk.sh checks it).
//
// The header declares, before the include line, in the same text for both GLSL versions:
//   const int MATRIX_ROWS, SCALE_ROWS     which palette part paletteRow reads
//   int influenceCount()                  influences per vertex the loops read
//   float weightAt(int i), uint jointAt(int i)
//                                         slot i's weight and palette joint (slot 0 the heaviest:
//                                         the DQS pivot)
//   vec4 paletteRow(int part, uint joint, int row)
//                                         row 0-2 of the joint's skinning matrix M (MATRIX_ROWS)
//                                         or scale part S (SCALE_ROWS), row-major 3x4
//   vec4 paletteRotation(uint joint), vec4 paletteDual(uint joint)
//                                         the joint's dual quaternion: rotation (x y z w), dual part
//   vec4 boneRow(uint joint, int row)     row 0-5 of the joint's bone rows (JointPalette.boneRows,
//                                         Frame.boneRows: 0 posed head | twist, 1 posed tail |
//                                         stretch, 2 tail's stretch offset | 0, 3 posed bone axis | 0,
//                                         4 rest head | length, 5 rest tail | parent index); the
//                                         renderers upload them for the methods that read bones
//                                         (SkinningMethod.usesBones), so only those may call it

uniform bool uHasScale;       // some joint has a scale part this frame: DQS and CoR run the scale phase first
uniform bool uMatricesMirror; // LBS normals: times the sign of the blend's determinant (Frame.mirrorsMatrices)
uniform bool uScalesMirror;   // the scale phase's normals: the same for the blended S (Frame.mirrorsScales)

// Weighted sum of the rows of a 3x4 matrix palette part.
void blendRows(int part, out vec4 r0, out vec4 r1, out vec4 r2) {
    r0 = vec4(0.0); r1 = vec4(0.0); r2 = vec4(0.0);
    for (int i = 0; i < influenceCount(); i++) {
        float w = weightAt(i);
        uint j = jointAt(i);
        r0 += w * paletteRow(part, j, 0);
        r1 += w * paletteRow(part, j, 1);
        r2 += w * paletteRow(part, j, 2);
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
    blendRows(MATRIX_ROWS, r0, r1, r2);
    outP = applyRows(r0, r1, r2, p);
    outN = cofactorTimes(r0, r1, r2, n, uMatricesMirror);
}

vec3 rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// DQS's and CoR's scale phase (JointPalette's two-phase split, as ScalarDqsSkinner): the blended S applied
// first, to the point, its normal (by the cofactor) and its CoR centre.
void scalePhase(inout vec3 p, inout vec3 n, inout vec3 c) {
    vec4 s0, s1, s2;
    blendRows(SCALE_ROWS, s0, s1, s2);
    n = cofactorTimes(s0, s1, s2, n, uScalesMirror);
    p = applyRows(s0, s1, s2, p);
    c = applyRows(s0, s1, s2, c);
}

void dqs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    if (uHasScale) {
        vec3 noCentre = vec3(0.0);
        scalePhase(p, n, noCentre);
    }
    vec4 pivot = paletteRotation(jointAt(0));
    vec4 br = vec4(0.0);
    vec4 bd = vec4(0.0);
    for (int i = 0; i < influenceCount(); i++) {
        uint j = jointAt(i);
        vec4 r = paletteRotation(j);
        vec4 d = paletteDual(j);
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

// CoR (Le and Hodgins 2016) of point p with centre c: the rotations blended as in DQS, the
// translation LBS's (of the joints' rigid parts) at the centre; the scale phase first, as in DQS.
void cor(vec3 p, vec3 n, vec3 c, out vec3 outP, out vec3 outN) {
    if (uHasScale) {
        scalePhase(p, n, c);
    }
    vec4 pivot = paletteRotation(jointAt(0));
    vec4 q = vec4(0.0);
    vec3 t = vec3(0.0);
    for (int i = 0; i < influenceCount(); i++) {
        uint j = jointAt(i);
        float w = weightAt(i);
        vec4 r = paletteRotation(j);
        q += (dot(pivot, r) < 0.0 ? -w : w) * r;
        if (uHasScale) {
            // The rigid part D of a scaled joint, from its dual quaternion.
            vec4 d = paletteDual(j);
            t += w * (rotate(r, c) + 2.0 * (r.w * d.xyz - d.w * r.xyz + cross(r.xyz, d.xyz)));
        }
    }
    if (!uHasScale) {
        // D = M: LBS of the centre is the blended matrix applied once (as the CPU kernel does).
        vec4 m0, m1, m2;
        blendRows(MATRIX_ROWS, m0, m1, m2);
        t = applyRows(m0, m1, m2, c);
    }
    q = normalize(q);
    outP = rotate(q, p - c) + t;
    outN = rotate(q, n);
}

// Bulge-free DQS (ScalarBulgeFreeDqsSkinner, BulgeFreeBinding; docs/skinning.md): DQS, then a point
// that ended up farther from its bone than at rest is pulled back towards it. Its bone is chosen here
// as BulgeFreeBinding chooses it on the CPU, from the vertex's own influences and the bones' rest
// segments (rows 4 and 5 of boneRow, which the header declares: vec4 boneRow(uint joint, int row)),
// so no attribute is needed. ALLOWANCE and TIE are BulgeFreeBinding's constants (the same values).
const float BFDQS_ALLOWANCE = 0.05;
const float BFDQS_TIE = 1e-4;

vec3 nearestOnSegment(vec3 p, vec3 a, vec3 b) {
    vec3 e = b - a;
    float len2 = dot(e, e);
    float t = len2 > 0.0 ? clamp(dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
    return a + t * e;
}

void bfdqs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    dqs(p, n, outP, outN);
    // The nearest rest bone among the influences with weight (slot 0 always); a later, lighter one
    // only when nearer by more than the tie margin.
    uint bone = jointAt(0);
    vec3 restNearest = nearestOnSegment(p, boneRow(bone, 4).xyz, boneRow(bone, 5).xyz);
    float r = distance(p, restNearest);
    for (int i = 1; i < influenceCount(); i++) {
        if (weightAt(i) > 0.0) {
            uint j = jointAt(i);
            vec3 c = nearestOnSegment(p, boneRow(j, 4).xyz, boneRow(j, 5).xyz);
            float d = distance(p, c);
            if (d < (1.0 - BFDQS_TIE) * r) {
                r = d;
                bone = j;
                restNearest = c;
            }
        }
    }
    if (uHasScale) {
        // The rest offset from the bone through the joint's matrix: a joint scaled across its
        // bone widens what it carries, which is no bulge.
        vec3 u = p - restNearest;
        r = length(vec3(dot(paletteRow(MATRIX_ROWS, bone, 0).xyz, u), dot(paletteRow(MATRIX_ROWS, bone, 1).xyz, u),
                dot(paletteRow(MATRIX_ROWS, bone, 2).xyz, u)));
    }
    vec3 c = nearestOnSegment(outP, boneRow(bone, 0).xyz, boneRow(bone, 1).xyz);
    vec3 u = outP - c;
    float d = length(u);
    if (d > r) {
        // The excess e saturates smoothly at a = ALLOWANCE s r (BulgeFreeBinding.pulledDistance), s the
        // sine of half the angle between the two heaviest influences' rotations (BulgeFreeBinding.spread).
        float s = 0.0;
        if (influenceCount() > 1 && weightAt(1) > 0.0) {
            float c01 = dot(paletteRotation(jointAt(0)), paletteRotation(jointAt(1)));
            s = sqrt(max(0.0, 1.0 - c01 * c01));
        }
        float a = BFDQS_ALLOWANCE * s * r;
        float e = d - r;
        outP = c + u * ((r + e * a / sqrt(max(a * a + e * e, 1e-30))) / d);
    }
}

// Stretchable and twistable bones (Jacobson and Sorkine 2011), as core's StbsInfluence and
// ScalarStbsSkinner: joint j's rigid transformation of rest point p, a rotation r and a
// translation x, from its bone rows (JointPalette.boneRows; boneRow(j, row) is declared by the
// header): the endpoint weight e from the rest bone (rows 4, 5; 1 for a point-like bone), the
// twist still missing at e, -(1 - e) theta, about the posed axis through the posed head (rows 3,
// 0), and e times the tail's stretch offset (row 2).
void stbsInfluence(uint j, vec3 p, out vec4 r, out vec3 x) {
    vec4 posedHead = boneRow(j, 0);
    vec4 restHead = boneRow(j, 4);
    float e = 1.0;
    if (restHead.w > 0.0) {
        e = clamp(dot(p - restHead.xyz, boneRow(j, 5).xyz - restHead.xyz) / (restHead.w * restHead.w), 0.0, 1.0);
    }
    float halfAngle = -0.5 * (1.0 - e) * posedHead.w;
    vec3 u = boneRow(j, 3).xyz * sin(halfAngle);
    float uw = cos(halfAngle);
    vec4 q = paletteRotation(j);
    r = vec4(uw * q.xyz + q.w * u + cross(u, q.xyz), uw * q.w - dot(u, q.xyz));
    x = posedHead.xyz + e * boneRow(j, 2).xyz - rotate(r, restHead.xyz);
}

// STBS on LBS: the influences' matrices [R(r) | x] blended linearly; normals by the cofactor.
void stbsLbs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    vec4 r0 = vec4(0.0), r1 = vec4(0.0), r2 = vec4(0.0);
    for (int i = 0; i < influenceCount(); i++) {
        vec4 r;
        vec3 x;
        stbsInfluence(jointAt(i), p, r, x);
        float w = weightAt(i);
        r0 += w * vec4(1.0 - 2.0 * (r.y * r.y + r.z * r.z), 2.0 * (r.x * r.y - r.z * r.w), 2.0 * (r.x * r.z + r.y * r.w), x.x);
        r1 += w * vec4(2.0 * (r.x * r.y + r.z * r.w), 1.0 - 2.0 * (r.x * r.x + r.z * r.z), 2.0 * (r.y * r.z - r.x * r.w), x.y);
        r2 += w * vec4(2.0 * (r.x * r.z - r.y * r.w), 2.0 * (r.y * r.z + r.x * r.w), 1.0 - 2.0 * (r.x * r.x + r.y * r.y), x.z);
    }
    outP = applyRows(r0, r1, r2, p);
    outN = cofactorTimes(r0, r1, r2, n, false);
}

// STBS on DQS: the influences as dual quaternions (r, (x, 0) r / 2), on the dominant one's side.
void stbsDqs(vec3 p, vec3 n, out vec3 outP, out vec3 outN) {
    vec4 pivot = vec4(0.0);
    vec4 br = vec4(0.0);
    vec4 bd = vec4(0.0);
    for (int i = 0; i < influenceCount(); i++) {
        vec4 r;
        vec3 x;
        stbsInfluence(jointAt(i), p, r, x);
        if (i == 0) {
            pivot = r;
        }
        float w = dot(pivot, r) < 0.0 ? -weightAt(i) : weightAt(i);
        br += w * r;
        bd += 0.5 * w * vec4(r.w * x + cross(x, r.xyz), -dot(x, r.xyz));
    }
    float len = length(br);
    br /= len;
    bd /= len;
    vec3 t = 2.0 * (br.w * bd.xyz - bd.w * br.xyz + cross(br.xyz, bd.xyz));
    outP = rotate(br, p) + t;
    outN = rotate(br, n);
}

// Point p (normal n, CoR centre c) skinned by the method with this code, SkinningGlsl.methodCode's:
// 1 LBS, 2 DQS, 3 CoR, 4 bulge-free DQS, 5 STBS on LBS, 6 STBS on DQS; any other code leaves them as they are (CPU-skinned points:
// code 0, and a method without shader code, which the simulation skins on the CPU, SkinningGlsl.hasCode).
void skin(int method, vec3 p, vec3 n, vec3 c, out vec3 outP, out vec3 outN) {
    outP = p;
    outN = n;
    if (method == 1) {
        lbs(p, n, outP, outN);
    } else if (method == 2) {
        dqs(p, n, outP, outN);
    } else if (method == 3) {
        cor(p, n, c, outP, outN);
    } else if (method == 4) {
        bfdqs(p, n, outP, outN);
    } else if (method == 5) {
        stbsLbs(p, n, outP, outN);
    } else if (method == 6) {
        stbsDqs(p, n, outP, outN);
    }
}
