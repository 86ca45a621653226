// Improved Perlin noise (Perlin, "Improving Noise", SIGGRAPH 2002): gradient noise in 3D with
// the quintic fade curve and the 12 edge gradients, on the reference permutation. Values lie
// in about [-1, 1]; the lattice repeats every 256 units. One definition for every lane.
#pragma once

#include <cmath>
#include <cstdint>

namespace pf {

namespace noise_detail {
inline constexpr uint8_t kPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,
    69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,
    94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136,
    171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122,
    60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161,
    1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196, 135, 130, 116, 188, 159, 86,
    164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126,
    255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213,
    119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,   129, 22,  39,  253,
    19,  98,  108, 110, 79,  113, 224, 232, 178, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,
    192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138,
    236, 205, 93,  222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

inline int perm(int i) { return kPermutation[i & 255]; }
template <typename T>
T fade(T t) {
  return t * t * t * (t * (t * T(6) - T(15)) + T(10));
}
template <typename T>
T lerp(T t, T a, T b) {
  return a + t * (b - a);
}
template <typename T>
T grad(int hash, T x, T y, T z) {
  int h = hash & 15;
  T u = h < 8 ? x : y;
  T v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}
}  // namespace noise_detail

// Signed noise at (x, y, z); 0 at lattice points. Non-finite input gives 0. The executors use
// the float form; tests compute references with the double one (the same function).
template <typename T>
T perlinNoiseOf(T x, T y, T z) {
  using namespace noise_detail;
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return T(0);
  T fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  // The lattice repeats every 256: reduce in T first so huge inputs stay in int range.
  int X = static_cast<int>(fx - T(256) * std::floor(fx / T(256))) & 255;
  int Y = static_cast<int>(fy - T(256) * std::floor(fy / T(256))) & 255;
  int Z = static_cast<int>(fz - T(256) * std::floor(fz / T(256))) & 255;
  x -= fx;
  y -= fy;
  z -= fz;
  T u = fade(x), v = fade(y), w = fade(z);
  int A = perm(X) + Y, AA = perm(A) + Z, AB = perm(A + 1) + Z;
  int B = perm(X + 1) + Y, BA = perm(B) + Z, BB = perm(B + 1) + Z;
  return lerp(w,
              lerp(v, lerp(u, grad(perm(AA), x, y, z), grad(perm(BA), x - 1, y, z)),
                   lerp(u, grad(perm(AB), x, y - 1, z), grad(perm(BB), x - 1, y - 1, z))),
              lerp(v, lerp(u, grad(perm(AA + 1), x, y, z - 1), grad(perm(BA + 1), x - 1, y, z - 1)),
                   lerp(u, grad(perm(AB + 1), x, y - 1, z - 1), grad(perm(BB + 1), x - 1, y - 1, z - 1))));
}

inline float perlinNoise(float x, float y, float z) { return perlinNoiseOf<float>(x, y, z); }

}  // namespace pf
