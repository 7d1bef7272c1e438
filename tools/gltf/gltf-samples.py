#!/usr/bin/env python3
"""The third-party glTF sample files the glTF tests use when present, where each comes from, and a
check that a folder holds exactly those bytes. The files are never committed (their licences are
their authors'); the tests read them from

    -Dskinlab.gltfSamples=DIR  or  SKINLAB_GLTF_SAMPLES=DIR  or  ../shared/gltf-samples

(the last relative to the repository, beside ../shared/corpus) and skip, saying so, when a file
is missing. Layout: DIR/<Name>/<file>, as below.

    python3 tools/gltf/gltf-samples.py                    # check the default folder
    python3 tools/gltf/gltf-samples.py --dir DIR          # check DIR
    python3 tools/gltf/gltf-samples.py --from-assimp REPO --dir DIR
                                                          # copy the assimp ones out of a git clone
                                                          # (bare or not) of assimp/assimp

Sources:
  - assimp/assimp, test/models/glTF2/ (commit 21bea12f1278090c09a94c39ca090d9fb458ccd9): its copies
    of Khronos samples and its own simple_skin; byte-identical copies.
  - KhronosGroup/glTF-Sample-Models (2.0/<Name>/glTF-Embedded/<Name>.gltf) and glTF-Sample-Assets
    (Models/<Name>/glTF-Embedded/<Name>.gltf), one text file with data URIs each: the file's text. The copies here were taken as text, so their line endings may be LF
    where the original has CRLF (SimpleSkin): the JSON is the same, the checksum below is of the
    copy. They were checked to parse, their data URIs to decode to the declared byteLength, and
    glTF-Validator to report no error (it checks accessor min/max against the data).

Fox is the text of its glTF-Embedded file without the texture, which was not copied (a PNG data
URI); its buffer was checked against the file's own numbers (positions min/max, 2520 unit
rotation keys, increasing key times, weights summing to one, joints below 24). This version of
Fox declares byteStride on its animation and inverse-bind-matrix views, which glTF-Validator
reports as errors (fixed in later versions of the sample); the content is unaffected.

Fox's blend reference (assets/reference/threejs/blends/Fox-notexture.gltf.blends.json.gz, made by
bench/threejs/blend-reference.mjs) was computed from a binary copy of the same fox, bevyengine/bevy
@0cb3eaef6755f9482f49f220e71b1afbb40cfdb4:assets/models/animated/Fox.glb (sha256
d97044e701822bac5a62696459b27d7b375aada5de8574ed4362edbba94771f7, its JSON says so), because the
session that made it could not fetch the text file: three.js poses that copy exactly as it poses
Fox-notexture.gltf (every position of the single-clip reference, rest and the three clips at all
45 times, equal to the last digit), and tools/gltf/check-references.py checks the blend reference
against Fox-notexture.gltf itself where it is present.

Samples wanted but not here, and why (see docs/references.md): CesiumMan (615 kB as embedded
text), RecursiveSkeletons (940 kB), BrainStem (4 MB),
InterpolationTest (binary buffers only): the only way to fetch them in the session that made this
list was as text pages, too slow for their size; RiggedFigure: the stored copy is a pre-release
glTF 2.0 export (node "jointName", one animation per joint), not the current sample. Any copy with the same layout works: add it to
MANIFEST with its source and checksum.
"""

import argparse
import hashlib
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ASSIMP_COMMIT = "21bea12f1278090c09a94c39ca090d9fb458ccd9"

# (folder/file, sha256, source)
MANIFEST = [
    ("AnimatedMorphCube/AnimatedMorphCube.gltf", "0b910ed4b52fd9fbb565911fc7f9f285edb0f30fa4913a93143466d439d1092e",
     "assimp:test/models/glTF2/AnimatedMorphCube/glTF/AnimatedMorphCube.gltf"),
    ("AnimatedMorphCube/AnimatedMorphCube.bin", "4aba93918adba56c1cc688a38c527bc647e26f2c386802e119b4d01b7250dd23",
     "assimp:test/models/glTF2/AnimatedMorphCube/glTF/AnimatedMorphCube.bin"),
    ("MorphPrimitivesTest/MorphPrimitivesTest.gltf", "a51388b330a49586388e052dc66f74e95cdbc1efcdddea4248f65e200e1d335a",
     "assimp:test/models/glTF2/MorphPrimitivesTest/glTF/MorphPrimitivesTest.gltf"),
    ("MorphPrimitivesTest/MorphPrimitivesTest.bin", "59ec1d7ca5c8d7605b69aa57cee3da2994384831a290e5271ecd963002c31c76",
     "assimp:test/models/glTF2/MorphPrimitivesTest/glTF/MorphPrimitivesTest.bin"),
    ("MorphPrimitivesTest/uv_texture.jpg", "d498c54b30f096b663b161f37ee64397253d6fa15ee4f8c03082c890f6065031",
     "assimp:test/models/glTF2/MorphPrimitivesTest/glTF/uv_texture.jpg"),
    ("SimpleMorph/SimpleMorph.gltf", "98aca5b5b9f156aa5492c7a3656d9dff6b7ac54be3b28f35f814c6a809c63008",
     "assimp:test/models/glTF2/SimpleMorph/glTF/SimpleMorph.gltf"),
    ("SimpleMorph/simpleMorphAnimation.bin", "bba8e6c8579b04fca092057a83266582a2f22fbe390d16f0eb92b577c60f9776",
     "assimp:test/models/glTF2/SimpleMorph/glTF/simpleMorphAnimation.bin"),
    ("SimpleMorph/simpleMorphGeometry.bin", "44e308fa30e6864c143c44d43bcf0dd3a48c0e21b8abd33344cf4949166c12ea",
     "assimp:test/models/glTF2/SimpleMorph/glTF/simpleMorphGeometry.bin"),
    ("simple_skin/simple_skin.gltf", "2ccb43a4a0a8d2663088684b53e254358308f48e3f4bcafa999e5b5898e2e0fa",
     "assimp:test/models/glTF2/simple_skin/simple_skin.gltf"),
    ("simple_skin/quad_skin.glb", "883d4a74183881959ed44ac3c7f9ab2a34f9ba9e3248517a353e88a14d94d405",
     "assimp:test/models/glTF2/simple_skin/quad_skin.glb"),
    ("SimpleSkin/SimpleSkin.gltf", "84fb708ab3967238154752fcc819f07656a163f55b39d0ae96b3f65adc22ea82",
     "KhronosGroup/glTF-Sample-Models@3f6a8bc303a621eb0232dd0f8bc638e3ad0f84a1:2.0/SimpleSkin/glTF-Embedded/SimpleSkin.gltf"
     " (text, LF line endings)"),
    ("AnimatedTriangle/AnimatedTriangle.gltf", "7add176d00a1275208a383fbaed6fbdd6e486f6ad8f6580ec7f0bc5b20c48a17",
     "KhronosGroup/glTF-Sample-Assets@5bad5aaa0bbb5d0f9cdc934e626f27d0df1e79b8:"
     "Models/AnimatedTriangle/glTF-Embedded/AnimatedTriangle.gltf"),
    ("Fox/Fox-notexture.gltf", "2d079dd51d9a4693b0231062ae393a8a4b80774434d71bbba8db065004170187",
     "KhronosGroup/glTF-Sample-Models@115ce5cd952fad2df5c3a2b1a82d169fd6f20936:2.0/Fox/glTF-Embedded/Fox.gltf"
     " with its embedded texture left out (images, textures, samplers and the material's"
     " baseColorTexture removed; written by json.dump with indent 4); geometry, skin and the three"
     " clips as in the file"),
    ("RiggedSimple/RiggedSimple.gltf", "cdf2182ac7887e4c19062dca669191e56f05b6c3d919f199ac0448b22c1dbcf3",
     "KhronosGroup/glTF-Sample-Models@2e6fed56b2c776e01d52412e1695541e05a94dd7:2.0/RiggedSimple/glTF-Embedded/RiggedSimple.gltf"),
]


def default_dir():
    return os.environ.get("SKINLAB_GLTF_SAMPLES") or os.path.normpath(os.path.join(ROOT, "..", "shared", "gltf-samples"))


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 16), b""):
            h.update(block)
    return h.hexdigest()


def copy_from_assimp(repo, folder):
    for rel, _, source in MANIFEST:
        if not source.startswith("assimp:"):
            continue
        data = subprocess.run(["git", "-C", repo, "show", "%s:%s" % (ASSIMP_COMMIT, source[len("assimp:"):])],
                              check=True, capture_output=True).stdout
        target = os.path.join(folder, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "wb") as f:
            f.write(data)


def check(folder):
    bad = 0
    for rel, digest, source in MANIFEST:
        path = os.path.join(folder, rel)
        if not os.path.isfile(path):
            print("missing   %s  (from %s)" % (rel, source))
            bad += 1
        elif sha256(path) != digest:
            print("DIFFERENT %s  (expected the bytes of %s)" % (rel, source))
            bad += 1
        else:
            print("ok        %s" % rel)
    return bad


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dir", default=default_dir())
    parser.add_argument("--from-assimp", metavar="REPO")
    args = parser.parse_args()
    if args.from_assimp:
        copy_from_assimp(args.from_assimp, args.dir)
    bad = check(args.dir)
    print("%s: %d of %d files present and identical" % (args.dir, len(MANIFEST) - bad, len(MANIFEST)))
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
