// verify/did_you_mean.h: the edit distance and the nearest name, the one "did you mean" rule of the scene loader and
// the command line.
#include "verify/did_you_mean.h"

#include <catch2/catch.hpp>

using fftess::verify::editDistance;
using fftess::verify::nearestName;

TEST_CASE("editDistance counts inserts, deletes, replacements and adjacent swaps as one edit each", "[did_you_mean]") {
  CHECK(editDistance("", "") == 0);
  CHECK(editDistance("", "abc") == 3);
  CHECK(editDistance("abc", "") == 3);
  CHECK(editDistance("kitten", "sitting") == 3);
  CHECK(editDistance("adjacency_clmp", "adjacency_clamp") == 1); // insert
  CHECK(editDistance("epickk", "epick") == 1);                   // delete
  CHECK(editDistance("epeck", "epick") == 1);                    // replace
  CHECK(editDistance("sweep", "swepe") == 1);                    // swap
  CHECK(editDistance("CHECK", "check") == 0);                    // ASCII case ignored
  // A metric: symmetric, and the triangle inequality on a few words.
  const char* words[] = {"screen_sphere", "screen_sphre", "sphere", "patch_center", "", "x"};
  for (const char* a : words)
    for (const char* b : words) {
      CHECK(editDistance(a, b) == editDistance(b, a));
      for (const char* c : words) CHECK(editDistance(a, c) <= editDistance(a, b) + editDistance(b, c));
    }
}

TEST_CASE("nearestName suggests a close name, a unique prefix, or nothing", "[did_you_mean]") {
  const std::vector<std::string> schemes{"constant", "screen_sphere", "distance_pow2", "bonaventura", "clip_diameter",
                                         "patch_center", "geomorph", "shader"};
  CHECK(nearestName("screen_sphre", schemes) == "screen_sphere");
  CHECK(nearestName("Screen_Sphere", schemes) == "screen_sphere"); // case only
  CHECK(nearestName("geomorf", schemes) == "geomorph");
  CHECK(nearestName("quadratic", schemes).empty()); // nothing close
  CHECK(nearestName("screen_sphere", schemes).empty()); // the name itself is never suggested
  const std::vector<std::string> kernels{"epick", "epeck", "float"};
  CHECK(nearestName("epik", kernels) == "epick");
  CHECK(nearestName("epek", kernels) == "epeck");
  CHECK(nearestName("e", kernels).empty()); // one letter: no guess
  // Ties go to the earlier candidate; a longer distance loses.
  CHECK(nearestName("ab", {"ax", "bb"}) == "ax");
  CHECK(nearestName("of", {"on", "off", "auto"}) == "off"); // at the same distance, the one that starts with it
  CHECK(nearestName("abcdefghi", {"abcdefgxx", "abcdefghx"}) == "abcdefghx");
  // The limit: max(1, |word| / 3) edits.
  CHECK(nearestName("abcdef", {"abcdxx"}) == "abcdxx");
  CHECK(nearestName("abcdef", {"abcxxx"}).empty());
  // A unique prefix when nothing is close; two candidates with that prefix: no guess.
  const std::vector<std::string> groups{"checker", "domain formula", "heights", "mip", "lod precision", "tessellator"};
  CHECK(nearestName("lod", groups) == "lod precision");
  CHECK(nearestName("l", groups).empty());
  CHECK(nearestName("ab", {"abcdef", "abxyz"}).empty());
}
