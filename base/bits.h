// The bits of a float and the float of some bits: the one helper every module and test uses to name a float exactly
// (special values, one-ulp steps, hex tables). Header-only, standard library only.
#pragma once

#include <cstdint>
#include <cstring>

namespace fftess {

// The IEEE-754 binary32 bits of f. Always through memcpy, never a pointer cast (g++ -O2 miscompiles those; see
// shared/notes/facts.md). NaN payloads and the sign of zero are kept.
inline uint32_t bitsOf(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// The float whose binary32 bits are u (any u: NaNs, infinities, denormals, -0).
inline float floatOf(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// The IEEE-754 binary64 bits of d.
inline uint64_t bitsOf(double d) {
  uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  return u;
}

// The double whose binary64 bits are u.
inline double doubleOf(uint64_t u) {
  double d;
  std::memcpy(&d, &u, sizeof d);
  return d;
}

} // namespace fftess
