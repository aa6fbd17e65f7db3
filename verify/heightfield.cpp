// Heightfields: procedural fBm / ridged multifractal baked into a texture, RAW heightmaps, and bilinear sampling
// the way a GPU sampler filters (clamp addressing, limited sub-texel precision).
#include "verify/scene.h"
#include "verify/internal.h"

#include "base/splitmix64.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace fftess::verify::detail {

namespace {

// splitmix64's next() on state x (base/splitmix64.h): a well-distributed hash of the lattice point.
uint64_t mix64(uint64_t x) { return SplitMix64{x}.next(); }

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

namespace {

float bilinear(const std::vector<float>& t, int w, int h, int subtexelBits, float tx, float tz) {
  const float sx = tx * static_cast<float>(w) - 0.5f;
  const float sz = tz * static_cast<float>(h) - 0.5f;
  float x0 = std::floor(sx), z0 = std::floor(sz);
  float fx = sx - x0, fz = sz - z0;
  if (subtexelBits > 0) {
    const float q = std::ldexp(1.0f, subtexelBits);
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

} // namespace

float sampleBilinear(const Displacement& d, float tx, float tz) {
  return bilinear(*d.texels, d.texWidth, d.texHeight, d.subtexelBits, tx, tz);
}

float sampleBilinearLevel(const Displacement& d, int level, float tx, float tz) {
  if (level <= 0) return sampleBilinear(d, tx, tz);
  const MipLevel& m = (*d.mips)[static_cast<size_t>(level - 1)];
  return bilinear(m.texels, m.width, m.height, d.subtexelBits, tx, tz);
}

float sampleTrilinear(const Displacement& d, float tx, float tz, float level) {
  const int top = d.mips ? static_cast<int>(d.mips->size()) : 0;
  float l = level;
  if (!(l > 0.0f)) l = 0.0f; // also NaN
  if (l > static_cast<float>(top)) l = static_cast<float>(top);
  const float l0 = std::floor(l);
  float f = l - l0;
  if (d.subtexelBits > 0) {
    const float q = std::ldexp(1.0f, d.subtexelBits);
    f = std::nearbyint(f * q) / q;
  }
  const int i0 = static_cast<int>(l0);
  const float h0 = sampleBilinearLevel(d, i0, tx, tz);
  if (!(f > 0.0f)) return h0;
  const float h1 = sampleBilinearLevel(d, std::min(i0 + 1, top), tx, tz);
  return h0 + f * (h1 - h0);
}

// binary32: 1 sign, 8 exponent (bias 127), 23 mantissa bits; binary16: 1, 5 (bias 15), 10.
uint16_t floatToHalf(float f) {
  uint32_t x;
  std::memcpy(&x, &f, sizeof x);
  const uint32_t sign = (x >> 16) & 0x8000u;
  const uint32_t a = x & 0x7fffffffu;
  if (a >= 0x7f800000u) // infinity, NaN (quiet bit set, top 9 payload bits kept)
    return static_cast<uint16_t>(sign | 0x7c00u | (a > 0x7f800000u ? 0x200u | ((a >> 13) & 0x3ffu) : 0u));
  if (a >= 0x477ff000u) return static_cast<uint16_t>(sign | 0x7c00u); // >= 65520 = 65504 + half an ulp: tie -> inf
  // Round the integer q = m >> shift to nearest, ties to even (rem: the bits shifted out).
  auto roundShift = [](uint32_t m, int shift) {
    uint32_t q = m >> shift;
    const uint32_t rem = m & ((1u << shift) - 1u), half = 1u << (shift - 1);
    if (rem > half || (rem == half && (q & 1u))) ++q;
    return q;
  };
  const int e = static_cast<int>(a >> 23); // biased float exponent
  if (e < 113) {                           // below 2^-14: a half subnormal (or zero): q units of 2^-24
    if (e < 102) return static_cast<uint16_t>(sign); // < 2^-25: rounds to zero (2^-25 itself is a tie -> 0)
    const uint32_t m = (a & 0x7fffffu) | 0x800000u;  // value = m * 2^(e - 150)
    return static_cast<uint16_t>(sign | roundShift(m, 126 - e)); // q may carry into 0x400 = 2^-14: still right
  }
  // Normal: rebias the exponent, round the mantissa's low 13 bits away (a carry moves into the exponent).
  const uint32_t h = ((static_cast<uint32_t>(e - 112)) << 10) | ((a >> 13) & 0x3ffu);
  const uint32_t rem = a & 0x1fffu;
  const uint32_t r = h + ((rem > 0x1000u || (rem == 0x1000u && (h & 1u))) ? 1u : 0u);
  return static_cast<uint16_t>(sign | r);
}

float halfToFloat(uint16_t h) {
  const uint32_t sign = static_cast<uint32_t>(h & 0x8000u) << 16;
  const uint32_t e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
  uint32_t x;
  if (e == 0) {
    const float v = std::ldexp(static_cast<float>(m), -24); // exact: m < 2^10
    std::memcpy(&x, &v, sizeof x);
    x |= sign;
  } else if (e == 31) {
    x = sign | 0x7f800000u | (m << 13);
  } else {
    x = sign | ((e + 112) << 23) | (m << 13);
  }
  float f;
  std::memcpy(&f, &x, sizeof f);
  return f;
}

void applyTexelFormat(TexelFormat format, std::vector<float>& texels) {
  if (format != TexelFormat::R16Float) return;
  for (float& t : texels) t = halfToFloat(floatToHalf(t));
}

std::vector<MipLevel> buildMipChain(const std::vector<float>& texels, int width, int height, TexelFormat format) {
  std::vector<MipLevel> out;
  const std::vector<float>* src = &texels;
  int w = width, h = height;
  while (w > 1 || h > 1) {
    MipLevel m;
    m.width = std::max(1, w / 2);
    m.height = std::max(1, h / 2);
    m.texels.resize(static_cast<size_t>(m.width) * m.height);
    for (int j = 0; j < m.height; ++j) {
      const int z0 = std::min(2 * j, h - 1), z1 = std::min(2 * j + 1, h - 1);
      for (int i = 0; i < m.width; ++i) {
        const int x0 = std::min(2 * i, w - 1), x1 = std::min(2 * i + 1, w - 1);
        auto at = [&](int x, int z) { return (*src)[static_cast<size_t>(z) * w + x]; };
        m.texels[static_cast<size_t>(j) * m.width + i] = ((at(x0, z0) + at(x1, z0)) + (at(x0, z1) + at(x1, z1))) * 0.25f;
      }
    }
    applyTexelFormat(format, m.texels);
    out.push_back(std::move(m));
    src = &out.back().texels;
    w = out.back().width;
    h = out.back().height;
  }
  return out;
}

} // namespace fftess::verify::detail
