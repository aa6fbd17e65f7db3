// Capture parsing: both formats read patch by patch; every malformed input names FILE:LINE.
#include <catch2/catch.hpp>

#include <sstream>

#include "compare/capture.h"

using namespace fftess;

namespace {

std::vector<CapturedPatch> readAll(const std::string& text, CaptureFormat f = CaptureFormat::Auto) {
  std::istringstream in(text);
  CaptureReader r(in, "cap.csv", f);
  std::vector<CapturedPatch> out;
  CapturedPatch p;
  while (r.next(p)) out.push_back(p);
  return out;
}

std::string errorOf(const std::string& text) {
  try {
    readAll(text);
  } catch (const CaptureError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("capture: CSV with header, comments, decimal and hex floats, rows in any order within a patch",
          "[compare][capture]") {
  const auto p = readAll("patch,primitive,vertex,u,v,w\n"
                         "# a comment\n"
                         "0,0,1,0.5,0,0.5\n"
                         "0,0,0,0,0,1\n"
                         "0,1,0,0x3f800000,0x00000000\n"
                         "0,1,1,1,1\n"
                         "\n"
                         "2,0,0,0.25,0.75\n");
  REQUIRE(p.size() == 2);
  CHECK(p[0].patch == 0);
  CHECK(p[0].verticesPerPrimitive == 2);
  REQUIRE(p[0].vertices.size() == 4);
  CHECK(p[0].vertices[0].u == 0);
  CHECK(p[0].vertices[1].u == 0x3f000000u);
  CHECK(p[0].vertices[2].u == 0x3f800000u);
  CHECK(p[0].line == 3);
  CHECK(p[1].patch == 2);
  CHECK(p[1].verticesPerPrimitive == 1);
  CHECK(p[0].indices.empty()); // CSV has no point numbering of its own
}

TEST_CASE("capture: hex blocks as fftess tessellate --format hex writes them", "[compare][capture]") {
  const auto p = readAll("patch 0 points 3 indices 3\n00000000 3f800000\n00000000 00000000\n3f800000 00000000\n"
                         "0 1 2\npatch 3 points 0 indices 0\npatch 4 points 2 indices 2\n00000000 00000000\n"
                         "3f800000 00000000\n1 0\n");
  REQUIRE(p.size() == 3);
  CHECK(p[0].verticesPerPrimitive == 3);
  CHECK(p[0].vertices[0].v == 0x3f800000u);
  CHECK(p[0].indices == std::vector<int32_t>{0, 1, 2});
  CHECK(p[1].patch == 3);
  CHECK(p[1].vertices.empty());
  CHECK(p[1].indices.empty());
  // The block's own numbering is kept: vertex i is point indices[i].
  CHECK(p[2].indices == std::vector<int32_t>{1, 0});
  CHECK(p[2].vertices[0].u == 0x3f800000u);
}

TEST_CASE("capture: bad input names file and line", "[compare][capture]") {
  CHECK(errorOf("0,0,0,0.5\n") == "cap.csv:1: expected 5 or 6 fields 'patch,primitive,vertex,u,v[,w]', found 4");
  CHECK(errorOf("0,0,0,0.5,zz\n").rfind("cap.csv:1: field 5 (v) 'zz'", 0) == 0);
  CHECK(errorOf("0,0,0,0,0\n0,0,3,0,0\n") == "cap.csv:2: field 3 (vertex) '3' is not 0, 1 or 2");
  CHECK(errorOf("# c\n1,0,0,0,0\n0,0,0,0,0\n").rfind("cap.csv:3: patch 0 after patch 1", 0) == 0);
  CHECK(errorOf("0,0,0,0,0\n0,0,2,0,0\n0,0,1,0,0\n0,1,0,0,0\n").rfind("cap.csv:4: patch 0 primitive 1", 0) == 0);
  CHECK(errorOf("0,0,0,0,0\n0,0,0,1,1\n").rfind("cap.csv:2: patch 0 primitive 0", 0) == 0);
  CHECK(errorOf("0,0,0,0,0\nx,0,0,0,0\n") == "cap.csv:2: field 1 (patch) 'x' is not a non-negative integer");
  CHECK(errorOf("patch 0 points 1 indices 1\n00000000\n").rfind("cap.csv:2: expected a point", 0) == 0);
  CHECK(errorOf("patch 0 points 1 indices 1\n00000000 00000000\n1\n").rfind("cap.csv:3: index '1'", 0) == 0);
  CHECK(errorOf("patch 0 points 1 indices 2\n00000000 00000000\n0\n") ==
        "cap.csv:3: file ends inside patch 0's indices");
  CHECK(errorOf("patch 0 points 1 indices 1\n00000000 00000000\n0\npatch 0 points 0 indices 0\n")
            .rfind("cap.csv:4: patch 0 comes after patch 0", 0) == 0);
}
