// skinlab's scalar C++ skinning beside the shared reference (../shared/perf/skin_ref.cpp), which
// always transforms normals: LBS and DQS with positions only, so that "is DQS faster than LBS?" can
// be answered in C++ with and without normals. Written for skinlab from the formulas:
//   LBS  p' = (sum_k w_k M_k) p, the 3x4 matrices blended, then applied;
//   DQS  b = sum_k s_k w_k q_k with s_k = sign(q_0 . q_k) on the real parts (Kavan et al. 2008),
//        b / |b_real| applied as p' = p + 2 r x (r x p + r_w p) + t, t = 2 (r_w d - d_w r + r x d).
//
// Data: the reference's synthetic input, from our own implementation of the generator its header
// documents, bit for bit (splitmix64, seed 42, drawn in the same order): 64 joints with a
// normalised random quaternion and a translation in [-1,1)^3, as a row-major 3x4 matrix and a unit
// dual quaternion (d = (t, 0) r / 2); V vertices with a position in [-1,1)^3, a unit normal, K
// distinct joints in [0,64) and K weights 0.05 + U[0,1) divided by their sum. K = 4 (the default)
// is the reference's data; INFLUENCES=K (1 to 16) draws K per vertex the same way, as skinlab's
// SyntheticSkinData does.
//
// Variants (single thread, the reference's timing protocol and output line):
//   c-lbs-pos, c-dqs-pos : positions only; checksum sum(positions)
//   c-lbs-nrm, c-dqs-nrm : positions and normals, the normal by the blended linear part (LBS) or
//                          rotated (DQS), in the reference's order of float operations: a
//                          calibration, whose checksum sum(positions) + 0.5 sum(normals) equals
//                          skin_ref's c-lbs and c-dqs at K = 4 (so both programs skin the same data
//                          with the same loops), and whose time against skin_ref's shows the two
//                          builds run alike.
//
// Build: g++ -O3 -DNDEBUG -std=c++17 skin_positions.cpp -o skin_positions -lpthread
// Run:   [VARIANTS=c-lbs-pos,...] [INFLUENCES=K] ./skin_positions [rounds] [seconds_per_variant_per_round] [V...]
// Output: per (variant, V) "V=<V> <variant> min <ns> median <ns> ns/vertex  (n=<samples>)  checksum <c>",
// the reference's format (min and upper median over all samples of all rounds).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

constexpr int kJoints = 64;
constexpr int kMaxInfluences = 16;

// Steele, Lea and Flood's splitmix64 (2014); floats from the top 24 bits.
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t bits() {
    state_ += 0x9E3779B97F4A7C15ULL;
    uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  float unit() { return static_cast<float>(bits() >> 40) * (1.0f / 16777216.0f); }  // [0, 1)
  float symmetric() { return unit() * 2.0f - 1.0f; }                                 // [-1, 1)

 private:
  uint64_t state_;
};

struct Skin {
  int vertices = 0;
  int influences = 0;
  std::vector<float> matrices;         // 12 per joint, row-major 3x4
  std::vector<float> dualQuaternions;  // 8 per joint: real x y z w, dual x y z w
  std::vector<float> positions;        // 3 per vertex
  std::vector<float> normals;          // 3 per vertex
  std::vector<int32_t> joints;         // influences per vertex
  std::vector<float> weights;          // influences per vertex
};

void drawJoint(Random& r, Skin& s, int j) {
  float x = r.symmetric();
  float y = r.symmetric();
  float z = r.symmetric();
  float w = r.symmetric();
  float len = std::sqrt(x * x + y * y + z * z + w * w);
  x /= len;
  y /= len;
  z /= len;
  w /= len;
  float tx = r.symmetric();
  float ty = r.symmetric();
  float tz = r.symmetric();
  float* m = &s.matrices[12 * j];
  const float rows[12] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),     tx,
                          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),     ty,
                          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y), tz};
  std::copy(rows, rows + 12, m);
  float* q = &s.dualQuaternions[8 * j];
  const float dq[8] = {x, y, z, w,
                       0.5f * (tx * w + ty * z - tz * y), 0.5f * (-tx * z + ty * w + tz * x),
                       0.5f * (tx * y - ty * x + tz * w), -0.5f * (tx * x + ty * y + tz * z)};
  std::copy(dq, dq + 8, q);
}

void drawVertex(Random& r, Skin& s, size_t v) {
  const int k = s.influences;
  for (int c = 0; c < 3; ++c) s.positions[3 * v + c] = r.symmetric();
  float nx = r.symmetric();
  float ny = r.symmetric();
  float nz = r.symmetric();
  float len = std::sqrt(nx * nx + ny * ny + nz * nz);
  if (len < 1e-6f) {
    nx = 0;
    ny = 0;
    nz = 1;
    len = 1;
  }
  s.normals[3 * v] = nx / len;
  s.normals[3 * v + 1] = ny / len;
  s.normals[3 * v + 2] = nz / len;
  int32_t* joint = &s.joints[k * v];
  for (int got = 0; got < k;) {
    int32_t candidate = static_cast<int32_t>(r.bits() & (kJoints - 1));
    if (std::find(joint, joint + got, candidate) == joint + got) joint[got++] = candidate;
  }
  float* weight = &s.weights[k * v];
  float sum = 0;
  for (int i = 0; i < k; ++i) {
    weight[i] = 0.05f + r.unit();
    sum += weight[i];
  }
  for (int i = 0; i < k; ++i) weight[i] /= sum;
}

Skin makeSkin(int vertices, int influences, uint64_t seed = 42) {
  Skin s;
  s.vertices = vertices;
  s.influences = influences;
  s.matrices.resize(12 * kJoints);
  s.dualQuaternions.resize(8 * kJoints);
  s.positions.resize(3 * static_cast<size_t>(vertices));
  s.normals.resize(3 * static_cast<size_t>(vertices));
  s.joints.resize(static_cast<size_t>(influences) * vertices);
  s.weights.resize(static_cast<size_t>(influences) * vertices);
  Random r(seed);
  for (int j = 0; j < kJoints; ++j) drawJoint(r, s, j);
  for (size_t v = 0; v < static_cast<size_t>(vertices); ++v) drawVertex(r, s, v);
  return s;
}

// ---- LBS: blend the K matrices (12 floats each), apply to the point (and the normal) ----

template <int K>
inline void blendMatrices(const Skin& s, size_t v, float b[12]) {
  const int32_t* joint = &s.joints[K * v];
  const float* weight = &s.weights[K * v];
  const float* first = &s.matrices[12 * joint[0]];
  for (int c = 0; c < 12; ++c) b[c] = weight[0] * first[c];
  for (int i = 1; i < K; ++i) {
    const float* m = &s.matrices[12 * joint[i]];
    for (int c = 0; c < 12; ++c) b[c] += weight[i] * m[c];
  }
}

template <int K, bool kNormals>
void lbs(const Skin& s, float* outPositions, float* outNormals) {
  for (size_t v = 0; v < static_cast<size_t>(s.vertices); ++v) {
    float b[12];
    blendMatrices<K>(s, v, b);
    const float* p = &s.positions[3 * v];
    for (int row = 0; row < 3; ++row) {
      const float* m = b + 4 * row;
      outPositions[3 * v + row] = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    }
    if (kNormals) {
      const float* n = &s.normals[3 * v];
      for (int row = 0; row < 3; ++row) {
        const float* m = b + 4 * row;
        outNormals[3 * v + row] = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
      }
    }
  }
}

// ---- DQS: blend the K dual quaternions with the hemisphere sign, normalise, apply ----

template <int K>
inline void blendDualQuaternions(const Skin& s, size_t v, float b[8]) {
  const int32_t* joint = &s.joints[K * v];
  const float* weight = &s.weights[K * v];
  const float* pivot = &s.dualQuaternions[8 * joint[0]];
  for (int c = 0; c < 8; ++c) b[c] = weight[0] * pivot[c];
  for (int i = 1; i < K; ++i) {
    const float* q = &s.dualQuaternions[8 * joint[i]];
    // q and -q are one rotation: take the one on the pivot's side (a sign, not a branch: with
    // joints in random order a branch would mispredict half the time).
    float w = std::copysign(weight[i], pivot[0] * q[0] + pivot[1] * q[1] + pivot[2] * q[2] + pivot[3] * q[3]);
    for (int c = 0; c < 8; ++c) b[c] += w * q[c];
  }
}

// v + 2 r x (r x v + r_w v) for the unit quaternion r = (x, y, z, w)
inline void rotate(const float r[4], const float* in, float* out) {
  float cx = r[1] * in[2] - r[2] * in[1] + r[3] * in[0];
  float cy = r[2] * in[0] - r[0] * in[2] + r[3] * in[1];
  float cz = r[0] * in[1] - r[1] * in[0] + r[3] * in[2];
  out[0] = in[0] + 2 * (r[1] * cz - r[2] * cy);
  out[1] = in[1] + 2 * (r[2] * cx - r[0] * cz);
  out[2] = in[2] + 2 * (r[0] * cy - r[1] * cx);
}

template <int K, bool kNormals>
void dqs(const Skin& s, float* outPositions, float* outNormals) {
  for (size_t v = 0; v < static_cast<size_t>(s.vertices); ++v) {
    float b[8];
    blendDualQuaternions<K>(s, v, b);
    float inv = 1.0f / std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
    const float r[4] = {b[0] * inv, b[1] * inv, b[2] * inv, b[3] * inv};
    const float d[4] = {b[4] * inv, b[5] * inv, b[6] * inv, b[7] * inv};
    const float t[3] = {2 * (r[3] * d[0] - d[3] * r[0] + (r[1] * d[2] - r[2] * d[1])),
                        2 * (r[3] * d[1] - d[3] * r[1] + (r[2] * d[0] - r[0] * d[2])),
                        2 * (r[3] * d[2] - d[3] * r[2] + (r[0] * d[1] - r[1] * d[0]))};
    float* o = outPositions + 3 * v;
    rotate(r, &s.positions[3 * v], o);
    o[0] += t[0];
    o[1] += t[1];
    o[2] += t[2];
    if (kNormals) rotate(r, &s.normals[3 * v], outNormals + 3 * v);
  }
}

using Kernel = void (*)(const Skin&, float*, float*);

template <int K>
Kernel kernel(const std::string& name) {
  if (name == "c-lbs-pos") return lbs<K, false>;
  if (name == "c-lbs-nrm") return lbs<K, true>;
  if (name == "c-dqs-pos") return dqs<K, false>;
  if (name == "c-dqs-nrm") return dqs<K, true>;
  return nullptr;
}

// The kernels for K = 1, 2, ..., kMaxInfluences, each with its loops over K known to the compiler.
template <int K>
Kernel kernelUpTo(const std::string& name, int k) {
  if (k == K) return kernel<K>(name);
  if constexpr (K > 1) return kernelUpTo<K - 1>(name, k);
  return nullptr;
}

Kernel kernelFor(const std::string& name, int k) { return kernelUpTo<kMaxInfluences>(name, k); }

double checksum(const std::vector<float>& positions, const std::vector<float>& normals) {
  double sum = 0;
  for (float x : positions) sum += x;
  for (float x : normals) sum += 0.5 * x;
  return sum;
}

double nanoseconds() {
  return static_cast<double>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                 std::chrono::steady_clock::now().time_since_epoch())
                                 .count());
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= list.size()) {
    size_t comma = list.find(',', start);
    if (comma == std::string::npos) comma = list.size();
    if (comma > start) parts.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return parts;
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = argc > 1 ? std::atoi(argv[1]) : 3;
  double seconds = argc > 2 ? std::atof(argv[2]) : 0.3;
  std::vector<int> sizes;
  for (int i = 3; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  const char* influencesText = std::getenv("INFLUENCES");
  int influences = influencesText ? std::atoi(influencesText) : 4;
  const char* variantsText = std::getenv("VARIANTS");
  std::vector<std::string> names =
      split(variantsText ? variantsText : "c-lbs-pos,c-dqs-pos,c-lbs-nrm,c-dqs-nrm");
  if (rounds < 1 || !(seconds >= 0)) {
    std::fprintf(stderr, "skin_positions: rounds must be at least 1 and seconds not negative\n");
    return 2;
  }
  if (influences < 1 || influences > kMaxInfluences) {
    std::fprintf(stderr, "skin_positions: INFLUENCES must be 1 to %d, was %s\n", kMaxInfluences, influencesText);
    return 2;
  }
  struct Variant {
    std::string name;
    Kernel run;
    bool normals;
    std::vector<double> samples;
    double sum;
  };
  std::vector<Variant> variants;
  for (const std::string& name : names) {
    Kernel k = kernelFor(name, influences);
    if (!k) {
      std::fprintf(stderr, "skin_positions: unknown variant %s (c-lbs-pos, c-dqs-pos, c-lbs-nrm, c-dqs-nrm)\n",
                   name.c_str());
      return 2;
    }
    variants.push_back({name, k, name.size() > 4 && name.compare(name.size() - 4, 4, "-nrm") == 0, {}, 0});
  }
  for (int vertices : sizes) {
    if (vertices < 1) {
      std::fprintf(stderr, "skin_positions: vertex counts must be at least 1, was %d\n", vertices);
      return 2;
    }
    Skin skin = makeSkin(vertices, influences);
    std::vector<float> positions(3 * static_cast<size_t>(vertices));
    std::vector<float> normals(3 * static_cast<size_t>(vertices));
    std::vector<float> none;
    for (Variant& x : variants) {
      x.samples.clear();
      std::fill(positions.begin(), positions.end(), 0.f);
      std::fill(normals.begin(), normals.end(), 0.f);
      x.run(skin, positions.data(), normals.data());
      x.sum = checksum(positions, x.normals ? normals : none);
    }
    for (int round = 0; round < rounds; ++round) {
      for (Variant& x : variants) {
        for (int warm = 0; warm < 3; ++warm) x.run(skin, positions.data(), normals.data());
        double end = nanoseconds() + seconds * 1e9;
        for (int n = 0; n < 5 || nanoseconds() < end; ++n) {
          double start = nanoseconds();
          x.run(skin, positions.data(), normals.data());
          x.samples.push_back((nanoseconds() - start) / vertices);
        }
      }
    }
    for (Variant& x : variants) {
      std::sort(x.samples.begin(), x.samples.end());
      std::printf("V=%-8d %-9s min %7.3f  median %7.3f ns/vertex  (n=%zu)  checksum %.6f\n", vertices,
                  x.name.c_str(), x.samples.front(), x.samples[x.samples.size() / 2], x.samples.size(), x.sum);
    }
    std::fflush(stdout);
  }
  return 0;
}
