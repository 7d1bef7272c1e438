#!/usr/bin/env python3
"""Check the full-vertex skinning references assets/reference/skinning/*.json against the .dae files
(plain Python 3, standard library only, no Blender, no numpy).

Usage (from the repository root):  python3 assets/src/check_skin_reference.py [ASSETS_DIR]

The references (written by make_skin_reference.py) hold Blender 3.4's Armature-modifier deformation
of every vertex at every key time, once with linear blend skinning (LBS) and once with
"preserve volume", Blender's dual quaternion skinning (DQS). This script recomputes both from the
.dae alone and reports the largest distance of any vertex to Blender's, relative to the extent
(the diagonal of the rest bounding box):

  LBS (check_assets.lbs):  v' = sum_i w_i K_i v,  K_i = JointWorld_i(t) INV_BIND_MATRIX_i BIND_SHAPE_MATRIX

  DQS (dqs_blender below): Kavan, Collins, Zara, O'Sullivan, "Geometric Skinning with Approximate
  Dual Quaternion Blending", ACM TOG 27(4), 2008, Algorithm 1, with the two additions Blender's
  armature deform makes (source/blender/blenlib/intern/math_rotation.c, mat4_to_dquat /
  add_weighted_dq_dq / normalize_dq / mul_v3m3_dq, called from blenkernel/intern/armature_deform.c
  and armature.c, BKE_pose_bone_done; Blender 3.4):
  1. Scale. Each joint's skinning matrix K = R S is split about the joint's REST frame
     B = inverse(INV_BIND_MATRIX) (Blender's bone arm_mat; the vertex is taken in bind-shape space,
     v = BIND_SHAPE_MATRIX v_file): the posed joint matrix P = K B = JointWorld(t) is orthogonalised
     keeping its Y axis (the bone axis; Z = normalize(X x Y), X = Y x Z), giving the rigid
     P_R = [rotation | translation of P]; then R = P_R B^-1 (rigid, blended as a dual quaternion)
     and S = B (P_R^-1 P) B^-1 (scale and shear about the bone's rest head, in rest coordinates).
     Only joints whose P has column lengths off 1 by more than 1e-4 (or det K < 0) take this path;
     the others have no scale part and count as identity in the scale blend.
     The scale parts are blended LINEARLY as 4x4 matrices with the (positive) weights,
     S_blend = (sum_scaled w_i S_i + (sum w - sum_scaled w_i) I) / sum w,
     and applied to the vertex BEFORE the blended dual quaternion: v' = DQ_blend(S_blend v).
  2. Antipodality: each joint's dual quaternion is added with its weight negated if its real part
     has a negative dot product with the RUNNING SUM so far (not with the first joint's); the first
     one is added as it is (the sum starts at zero).
  Normalisation: the sum is divided by the weight sum (not by its norm); the point is then mapped
  with the homogeneous form v' = (M(q) v + 2 vec(q_e q*)) / |q|^2, where M(q) is the rotation matrix
  of the unnormalised q times |q|^2 - exactly Kavan's normalisation by |q| (the component of q_e
  along q is dropped by taking the vector part). Blender also divides LBS by the weight sum;
  check_assets.lbs uses the weights as written (they sum to 1 +- 2e-7 in our files, so this changes
  nothing beyond 1e-7 of the extent).
  Blender decides a joint's scale path by "column lengths of P off 1 by more than 1e-4, or det < 0"
  (later versions also when K is not orthonormal); taking the scale path for every joint changes
  our results by at most 7e-7 m (the float noise of the file's 7-digit matrices), so the threshold
  does not matter here.
  Later Blender versions (the current armature_deform.cc, add_weighted_dq_dq_pivot, fixes
  #32022/#43188/#100373) move each scale part's pivot to the vertex itself and fold the induced
  translation into the dual quaternion; Blender 3.4 does not (that variant deviates 2.3 cm, 1.1e-2
  of the extent, from Blender 3.4 on tentacle-wave), so the references are tied to Blender 3.4.
  Other splits of K = R S deviate from Blender 3.4 on tentacle-wave too (measured): polar
  decomposition of K about the world origin 3.8e-2 of the extent, Blender's rest-frame split with a
  polar instead of Y-keeping orthogonalisation 7.3e-3, DQS of K ignoring the scale 0.68; on the
  files without bone scale all of these agree with Blender to 7e-7.

Exit status 1 if a reference is malformed or deviates by more than TOLERANCE * extent.
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True   # no __pycache__ in the source folder
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_assets as ca  # noqa: E402

# Float precision of the references: Blender deforms in float32 and the JSON holds 7 significant
# digits, both ~1e-7 of the ~2 m extents; 1e-5 leaves room for float32 pose evaluation.
TOLERANCE = 1e-5
# Key times where two joints sharing a vertex are rotated within this many degrees of 180 apart
# are left out of the references: there the sign of a dual quaternion (and so DQS) is arbitrary.
ANTIPODAL_MARGIN_DEG = 2.0
REF_KEYS = ["about", "file", "extent", "times", "lbs", "dqs", "skipped"]
TIME_EPS = 1e-6


class SkinReferenceError(Exception):
    pass


# ---------------------------------------------------------------- 4x4 / 3-vector helpers
def inverse(m):
    """Inverse of a 4x4 matrix (list of rows) by Gauss-Jordan elimination with partial pivoting."""
    a = [list(map(float, row)) + [1.0 if i == j else 0.0 for j in range(4)] for i, row in enumerate(m)]
    for c in range(4):
        p = max(range(c, 4), key=lambda r: abs(a[r][c]))
        if abs(a[p][c]) < 1e-12:
            raise SkinReferenceError("singular matrix %r" % (m,))
        a[c], a[p] = a[p], a[c]
        f = a[c][c]
        a[c] = [x / f for x in a[c]]
        for r in range(4):
            if r != c and a[r][c] != 0.0:
                g = a[r][c]
                a[r] = [x - g * y for x, y in zip(a[r], a[c])]
    return [row[4:] for row in a]


def column(m, c):
    return [m[0][c], m[1][c], m[2][c]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def quat_from_rotation(m):
    """Unit quaternion (w, x, y, z) of the rotation in the upper 3x3 of m (columns normalised
    first, as Blender's mat3_to_quat does); the sign is irrelevant for the blend (see
    add_weighted)."""
    cols = [normalize(column(m, c)) for c in range(3)]
    r = [[cols[c][i] for c in range(3)] for i in range(3)]   # rows again
    tr = r[0][0] + r[1][1] + r[2][2]
    if tr > 0:
        s = 2.0 * math.sqrt(1.0 + tr)
        q = [0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s]
    elif r[0][0] > r[1][1] and r[0][0] > r[2][2]:
        s = 2.0 * math.sqrt(1.0 + r[0][0] - r[1][1] - r[2][2])
        q = [(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s]
    elif r[1][1] > r[2][2]:
        s = 2.0 * math.sqrt(1.0 + r[1][1] - r[0][0] - r[2][2])
        q = [(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + r[2][2] - r[0][0] - r[1][1])
        q = [(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s]
    n = math.sqrt(sum(x * x for x in q))
    q = [x / n for x in q]
    return q if q[0] >= 0 else [-x for x in q]


# ---------------------------------------------------------------- the skinning setup of a file
def load(path):
    """Everything skinning needs from one .dae: rest points in bind-shape space, influences, per
    joint node id and INV_BIND_MATRIX, the scene nodes and channels, the key times."""
    root = ET.parse(path).getroot()
    geoms = list(root.iter(ca.NS + "geometry"))
    if len(geoms) != 1:
        raise SkinReferenceError("%s: %d geometries, expected 1" % (path, len(geoms)))
    g = ca.read_geometry(root, geoms[0])
    skin = ca.read_skin(root)
    nodes, order = ca.read_scene(root)
    joint_nodes, _ = ca.resolve_joints(nodes, skin["joints"])
    if None in joint_nodes:
        raise SkinReferenceError("%s: unresolved skin joints" % path)
    channels = ca.read_animations(root)
    times = sorted({t for c in channels.values() for t in c["times"]})
    bind_points = [ca.transform_point(skin["bsm"], p) for p in g["points"]]
    lo = [min(p[a] for p in bind_points) for a in range(3)]
    hi = [max(p[a] for p in bind_points) for a in range(3)]
    extent = math.sqrt(sum((h - l) ** 2 for l, h in zip(lo, hi)))
    return dict(root=root, points=g["points"], bind_points=bind_points, triangles=g["triangles"],
                skin=skin, nodes=nodes, order=order, joint_nodes=joint_nodes, channels=channels,
                times=times, extent=extent)


def world_at(setup, t):
    """Node world matrices at key time t. Every channel must have a key at t (our files key all
    channels at the same times); no interpolation is done here."""
    world = {}
    for nid in setup["order"]:
        n = setup["nodes"][nid]
        local = n["matrix"]
        c = setup["channels"].get(nid)
        if c is not None:
            ks = [k for k, x in enumerate(c["times"]) if abs(x - t) < TIME_EPS]
            if not ks:
                raise SkinReferenceError("channel %s has no key at t=%g" % (c["target"], t))
            local = c["mats"][ks[0]]
        world[nid] = ca.mul(world[n["parent"]], local) if n["parent"] else local
    return world


def joint_frames(setup, t):
    """Per skin joint: (K, B, P) with K = JointWorld INV_BIND_MATRIX (acting on bind-shape points),
    B = inverse(INV_BIND_MATRIX) (the rest frame, Blender's arm_mat), P = K B = JointWorld."""
    world = world_at(setup, t)
    out = []
    for nid, ibm in zip(setup["joint_nodes"], setup["skin"]["ibms"]):
        p = world[nid]
        out.append((ca.mul(p, ibm), inverse(ibm), p))
    return out


# ---------------------------------------------------------------- Blender's dual quaternions
def joint_dual_quaternion(k, b, p):
    """Blender's mat4_to_dquat(basemat=B, mat=K): (q, q_e, S or None), see the module comment."""
    sizes = [math.sqrt(sum(x * x for x in column(p, c))) for c in range(3)]
    dscale2 = sum((s - 1.0) ** 2 for s in sizes)
    if det3(k) < 0.0 or dscale2 > 1e-4 ** 2:
        y = normalize(column(p, 1))
        z = normalize(cross(column(p, 0), y))
        x = cross(y, z)
        p_r = [[x[i], y[i], z[i], p[i][3]] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]
        binv = inverse(b)
        r = ca.mul(p_r, binv)
        s = ca.mul(ca.mul(b, ca.mul(inverse(p_r), p)), binv)
    else:
        r, s = k, None
    q = quat_from_rotation(r)
    t = [r[0][3], r[1][3], r[2][3]]
    # q_e = 1/2 (0, t) q: translate after rotating (Kavan et al. 2008, eq. 1)
    qe = [-0.5 * (t[0] * q[1] + t[1] * q[2] + t[2] * q[3]),
          0.5 * (t[0] * q[0] + t[1] * q[3] - t[2] * q[2]),
          0.5 * (-t[0] * q[3] + t[1] * q[0] + t[2] * q[1]),
          0.5 * (t[0] * q[2] - t[1] * q[1] + t[2] * q[0])]
    return q, qe, s


def dqs_blender(points, influences, dqs):
    """Blender 3.4's armature deform with "preserve volume", per vertex (see the module comment)."""
    out = []
    for v, infl in zip(points, influences):
        sq = [0.0] * 4
        se = [0.0] * 4
        sm = None
        s_weight = 0.0
        total = 0.0
        for j, w in infl:
            if w == 0.0:
                continue
            q, qe, s = dqs[j]
            total += w
            # antipodality against the running sum (add_weighted_dq_dq)
            ws = -w if (q[0] * sq[0] + q[1] * sq[1] + q[2] * sq[2] + q[3] * sq[3]) < 0.0 else w
            for a in range(4):
                sq[a] += ws * q[a]
                se[a] += ws * qe[a]
            if s is not None:
                if sm is None:
                    sm = [[0.0] * 4 for _ in range(4)]
                for r in range(4):
                    for c in range(4):
                        sm[r][c] += w * s[r][c]
                s_weight += w
        if total <= 0.0001:
            out.append(list(v))
            continue
        sq = [x / total for x in sq]
        se = [x / total for x in se]
        p = v
        if sm is not None:
            add = total - s_weight        # joints without scale contribute identity
            for a in range(4):
                sm[a][a] += add
            sm = [[x / total for x in row] for row in sm]
            p = ca.transform_point(sm, p)
        w_, x_, y_, z_ = sq
        t0, t1, t2, t3 = se
        len2 = w_ * w_ + x_ * x_ + y_ * y_ + z_ * z_
        m = [[w_ * w_ + x_ * x_ - y_ * y_ - z_ * z_, 2 * (x_ * y_ - w_ * z_), 2 * (x_ * z_ + w_ * y_)],
             [2 * (x_ * y_ + w_ * z_), w_ * w_ + y_ * y_ - x_ * x_ - z_ * z_, 2 * (y_ * z_ - w_ * x_)],
             [2 * (x_ * z_ - w_ * y_), 2 * (y_ * z_ + w_ * x_), w_ * w_ + z_ * z_ - x_ * x_ - y_ * y_]]
        # 2 vec(q_e q*): the translation of the blended (unnormalised) dual quaternion times |q|^2
        tr = [2 * (-t0 * x_ + w_ * t1 - t2 * z_ + y_ * t3),
              2 * (-t0 * y_ + t1 * z_ - x_ * t3 + w_ * t2),
              2 * (-t0 * z_ + x_ * t2 + w_ * t3 - t1 * y_)]
        out.append([(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + tr[i]) / len2 for i in range(3)])
    return out


def quaternion_angle_deg(q1, q2):
    """Angle of the rotation between two unit quaternions (0..180 degrees)."""
    d = min(1.0, abs(sum(a * b for a, b in zip(q1, q2))))
    return math.degrees(2.0 * math.acos(d))


def sharing_pairs(setup):
    """Pairs of joint indices that both influence some vertex (nonzero weights)."""
    pairs = set()
    for infl in setup["skin"]["influences"]:
        js = sorted({j for j, w in infl if w != 0.0})
        for a in range(len(js)):
            for b in range(a + 1, len(js)):
                pairs.add((js[a], js[b]))
    return sorted(pairs)


def antipodal_reason(setup, t, frames=None):
    """None, or why key time t must be skipped: two joints sharing a vertex whose rigid parts are
    rotated within ANTIPODAL_MARGIN_DEG of 180 degrees from each other. Also returns the largest
    such angle."""
    frames = frames or joint_frames(setup, t)
    quats = [joint_dual_quaternion(*f)[0] for f in frames]
    worst = (0.0, None)
    for a, b in sharing_pairs(setup):
        ang = quaternion_angle_deg(quats[a], quats[b])
        if ang > worst[0]:
            worst = (ang, (a, b))
    if worst[1] is not None and worst[0] > 180.0 - ANTIPODAL_MARGIN_DEG:
        names = [setup["skin"]["joints"][i] for i in worst[1]]
        return ("joints %s and %s (sharing vertices) are rotated %.2f degrees apart, within %g of 180: "
                "the dual quaternion sign is arbitrary there" % (names[0], names[1], worst[0],
                                                                  ANTIPODAL_MARGIN_DEG)), worst[0]
    return None, worst[0]


def skin_at(setup, t):
    """(LBS, DQS) positions at key time t, from the file alone."""
    frames = joint_frames(setup, t)
    world = world_at(setup, t)
    lbs = ca.lbs(setup["points"], setup["skin"], setup["joint_nodes"], world)
    dqs = dqs_blender(setup["bind_points"], setup["skin"]["influences"],
                      [joint_dual_quaternion(*f) for f in frames])
    return lbs, dqs


# ---------------------------------------------------------------- comparison
def max_distance(flat, pts):
    worst, at = 0.0, -1
    for i, p in enumerate(pts):
        d = math.sqrt((flat[3 * i] - p[0]) ** 2 + (flat[3 * i + 1] - p[1]) ** 2 + (flat[3 * i + 2] - p[2]) ** 2)
        if d > worst:
            worst, at = d, i
    return worst, at


def check_reference(assets, ref_path):
    """Returns a list of failure messages; prints the deviations."""
    fails = []
    with open(ref_path, encoding="utf-8") as fh:
        ref = json.load(fh)
    name = os.path.basename(ref_path)
    if sorted(ref) != sorted(REF_KEYS):
        return ["%s: keys %s, expected %s" % (name, sorted(ref), REF_KEYS)]
    setup = load(os.path.join(assets, ref["file"]))
    n = len(setup["points"])
    print("== %s (%s: %d vertices, %d key times, extent %.6f m)"
          % (name, ref["file"], n, len(setup["times"]), setup["extent"]))
    if abs(ref["extent"] - setup["extent"]) > 1e-6 * setup["extent"]:
        fails.append("%s: extent %r, the file's rest bounding box gives %r" % (name, ref["extent"], setup["extent"]))
    skipped_times = [s["time"] for s in ref["skipped"]]
    want = sorted(ref["times"] + skipped_times)
    if len(want) != len(setup["times"]) or any(abs(a - b) > TIME_EPS for a, b in zip(want, setup["times"])):
        fails.append("%s: times + skipped %s != the file's key times %s" % (name, want, setup["times"]))
    if not (len(ref["lbs"]) == len(ref["dqs"]) == len(ref["times"])):
        return fails + ["%s: %d lbs and %d dqs arrays for %d times" % (name, len(ref["lbs"]), len(ref["dqs"]), len(ref["times"]))]
    for t in setup["times"]:
        reason, angle = antipodal_reason(setup, t)
        is_skipped = any(abs(t - s) < TIME_EPS for s in skipped_times)
        if (reason is not None) != is_skipped:
            fails.append("%s: t=%g is %s but the largest rotation between joints sharing vertices is %.2f deg"
                         % (name, t, "skipped" if is_skipped else "not skipped", angle))
    worst = {"lbs": (0.0, None, None), "dqs": (0.0, None, None)}
    lbs_vs_dqs = 0.0
    for k, t in enumerate(ref["times"]):
        lbs, dqs = skin_at(setup, t)
        for method, pts in (("lbs", lbs), ("dqs", dqs)):
            flat = ref[method][k]
            if len(flat) != 3 * n:
                fails.append("%s: %s at t=%g has %d numbers for %d vertices" % (name, method, t, len(flat), n))
                continue
            d, at = max_distance(flat, pts)
            if d > worst[method][0]:
                worst[method] = (d, t, at)
        lbs_vs_dqs = max(lbs_vs_dqs, max_distance(ref["lbs"][k], dqs)[0])
    ext = setup["extent"]
    for method in ("lbs", "dqs"):
        d, t, at = worst[method]
        print("  %s from the file vs Blender: max %.2e m = %.2e of the extent%s"
              % (method.upper(), d, d / ext, "" if t is None else " (t=%g, vertex %d)" % (t, at)))
        if d > TOLERANCE * ext:
            fails.append("%s: %s deviates %.2e of the extent from Blender's (t=%g, vertex %d)"
                         % (name, method.upper(), d / ext, t, at))
    print("  (for scale: Blender's LBS vs our DQS differ by up to %.3f m = %.2e of the extent)"
          % (lbs_vs_dqs, lbs_vs_dqs / ext))
    if ref["skipped"]:
        for s in ref["skipped"]:
            print("  skipped t=%g: %s" % (s["time"], s["why"]))
    return fails


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    assets = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.dirname(here)
    ref_dir = os.path.join(assets, "reference", "skinning")
    refs = sorted(f for f in os.listdir(ref_dir) if f.endswith(".json")) if os.path.isdir(ref_dir) else []
    dae = []
    for dirpath, dirnames, filenames in os.walk(assets):
        dirnames.sort()
        for f in sorted(filenames):
            if not f.lower().endswith(".dae"):
                continue
            clips = ca.read_clips(ET.parse(os.path.join(dirpath, f)).getroot())
            if len(clips) > 1:
                # one file's clips would make a reference several times the size of the others'
                print("%s: %d clips, not covered: a reference holds one clip (check_assets.py and "
                      "reimport_check.py compare each clip with Blender's deformation at sample vertices)"
                      % (f, len(clips)))
                continue
            dae.append(os.path.splitext(f)[0])
    fails = ["no reference for %s.dae" % d for d in dae if d + ".json" not in refs]
    if not refs:
        fails.append("no references in %s" % ref_dir)
    for r in refs:
        try:
            fails += check_reference(assets, os.path.join(ref_dir, r))
        except (SkinReferenceError, ca.CheckError, KeyError, ValueError, IndexError) as e:
            fails.append("%s: %s: %s" % (r, type(e).__name__, e))
    print()
    if fails:
        print("%d check(s) FAILED" % len(fails))
        for f in fails:
            print("  - " + f)
        return 1
    print("skinning references agree (%d files, LBS and DQS within %g of the extent)" % (len(refs), TOLERANCE))
    return 0


if __name__ == "__main__":
    sys.exit(main())
