// Heightfields: procedural fBm / ridged multifractal baked into a texture, RAW heightmaps, and bilinear sampling
// the way a GPU sampler filters (clamp addressing, limited sub-texel precision).
#include "verify/internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sys/stat.h>

namespace fftess::verify::detail {

namespace {

uint64_t mix64(uint64_t x) {
  // splitmix64 finaliser: a well-distributed hash of the lattice point
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

double lattice(int64_t x, int64_t z, uint64_t seed, int octave) {
  uint64_t h = mix64(seed ^ mix64(static_cast<uint64_t>(x) * 0x100000001b3ull ^
                                  mix64(static_cast<uint64_t>(z) + static_cast<uint64_t>(octave) * 0x9e37ull)));
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0) * 2.0 - 1.0; // [-1, 1)
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

// Value noise in [-1, 1] at (x, z), lattice spacing 1.
double valueNoise(double x, double z, uint64_t seed, int octave) {
  double fx = std::floor(x), fz = std::floor(z);
  int64_t ix = static_cast<int64_t>(fx), iz = static_cast<int64_t>(fz);
  double sx = smooth(x - fx), sz = smooth(z - fz);
  double a = lattice(ix, iz, seed, octave), b = lattice(ix + 1, iz, seed, octave);
  double c = lattice(ix, iz + 1, seed, octave), d = lattice(ix + 1, iz + 1, seed, octave);
  double ab = a + (b - a) * sx, cd = c + (d - c) * sx;
  return ab + (cd - ab) * sz;
}

} // namespace

std::vector<float> generateHeightfield(const Displacement& d) {
  const int n = d.resolution;
  std::vector<double> h(static_cast<size_t>(n) * n);
  for (int z = 0; z < n; ++z) {
    for (int x = 0; x < n; ++x) {
      double px = static_cast<double>(x) / (n - 1) * d.frequency;
      double pz = static_cast<double>(z) / (n - 1) * d.frequency;
      double sum = 0, amp = 1, weight = 1;
      for (int o = 0; o < d.octaves; ++o) {
        double v = valueNoise(px, pz, d.seed, o);
        if (d.kind == DisplacementKind::Ridge) {
          double r = 1.0 - std::fabs(v);
          r = r * r * weight;
          weight = std::clamp(r * 2.0, 0.0, 1.0);
          v = r;
        }
        sum += v * amp;
        amp *= d.gain;
        px *= d.lacunarity;
        pz *= d.lacunarity;
      }
      h[static_cast<size_t>(z) * n + x] = sum;
    }
  }
  auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  double l = *lo, range = *hi - *lo;
  std::vector<float> out(h.size());
  for (size_t i = 0; i < h.size(); ++i)
    out[i] = range > 0 ? static_cast<float>((h[i] - l) / range) : 0.0f;
  return out;
}

bool readRawHeightmap(const std::string& path, int width, int height, int bits, std::vector<float>& out,
                      std::string& error) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    error = "heightmap file '" + path + "' is " + (S_ISDIR(st.st_mode) ? "a directory" : "not a regular file");
    return false;
  }
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) {
    error = "cannot open heightmap file '" + path + "'";
    return false;
  }
  const auto size = static_cast<uint64_t>(f.tellg());
  const uint64_t bytes = static_cast<uint64_t>(width) * static_cast<uint64_t>(height) * (bits / 8);
  if (size != bytes) {
    error = "heightmap file '" + path + "' has " + std::to_string(size) + " bytes, expected " +
            std::to_string(bytes) + " (" + std::to_string(width) + " x " + std::to_string(height) + " x " +
            std::to_string(bits / 8) + ")";
    return false;
  }
  f.seekg(0);
  std::vector<unsigned char> raw(bytes);
  f.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(bytes));
  if (!f) {
    error = "cannot read heightmap file '" + path + "'";
    return false;
  }
  out.resize(static_cast<size_t>(width) * height);
  for (size_t i = 0; i < out.size(); ++i) {
    if (bits == 8)
      out[i] = static_cast<float>(raw[i]) / 255.0f; // UNORM8, as the texture format converts it
    else
      out[i] = static_cast<float>(raw[2 * i] | (raw[2 * i + 1] << 8)) / 65535.0f; // UNORM16, little endian
  }
  return true;
}

float sampleBilinear(const Displacement& d, float tx, float tz) {
  const std::vector<float>& t = *d.texels;
  const int w = d.texWidth, h = d.texHeight;
  const float sx = tx * static_cast<float>(w) - 0.5f;
  const float sz = tz * static_cast<float>(h) - 0.5f;
  float x0 = std::floor(sx), z0 = std::floor(sz);
  float fx = sx - x0, fz = sz - z0;
  if (d.subtexelBits > 0) {
    const float q = std::ldexp(1.0f, d.subtexelBits);
    fx = std::nearbyint(fx * q) / q;
    fz = std::nearbyint(fz * q) / q;
  }
  auto clampi = [](float v, int n) {
    if (!(v > 0.0f)) return 0; // also NaN
    if (v >= static_cast<float>(n - 1)) return n - 1;
    return static_cast<int>(v);
  };
  const int ix0 = clampi(x0, w), ix1 = clampi(x0 + 1.0f, w);
  const int iz0 = clampi(z0, h), iz1 = clampi(z0 + 1.0f, h);
  auto at = [&](int x, int z) { return t[static_cast<size_t>(z) * w + x]; };
  const float a = at(ix0, iz0), b = at(ix1, iz0), c = at(ix0, iz1), e = at(ix1, iz1);
  const float r0 = a + fx * (b - a);
  const float r1 = c + fx * (e - c);
  return r0 + fz * (r1 - r0);
}

} // namespace fftess::verify::detail
