// names.h: one table per enum, so every printed name parses back to its value and every listed name is accepted.
#include <catch2/catch.hpp>

#include <string>

#include "tessellator/names.h"

using namespace fftess;

TEST_CASE("names: every enum value round-trips through toString and parse", "[tessellator][names]") {
  for (Domain d : {Domain::Quad, Domain::Tri, Domain::Isoline}) {
    Domain back = Domain::Quad == d ? Domain::Tri : Domain::Quad;
    REQUIRE(parseDomain(toString(d), back));
    CHECK(back == d);
  }
  for (Partitioning p :
       {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd, Partitioning::FractionalEven}) {
    Partitioning back = p == Partitioning::Integer ? Partitioning::Pow2 : Partitioning::Integer;
    REQUIRE(parsePartitioning(toString(p), back));
    CHECK(back == p);
  }
  for (OutputPrimitive p : {OutputPrimitive::Point, OutputPrimitive::Line, OutputPrimitive::TriangleCw,
                            OutputPrimitive::TriangleCcw}) {
    OutputPrimitive back = p == OutputPrimitive::Point ? OutputPrimitive::Line : OutputPrimitive::Point;
    REQUIRE(parseOutputPrimitive(toString(p), back));
    CHECK(back == p);
  }
  int stages = 0;
  for (Reduction r : {Reduction::Min, Reduction::Max, Reduction::Average})
    for (ReductionAxes a : {ReductionAxes::OneAxis, ReductionAxes::TwoAxis}) {
      const Stage s{true, r, a};
      Stage back;
      INFO(toString(s));
      REQUIRE(parseStage(toString(s), back));
      CHECK(back.hlsl);
      CHECK(back.reduction == r);
      CHECK(back.axes == a);
      ++stages;
    }
  CHECK(stages == 6);
  Stage hw{false, Reduction::Max, ReductionAxes::OneAxis}; // reduction and axes do not name a hw stage
  CHECK(std::string(toString(hw)) == "hw");
}

TEST_CASE("names: the lists are the tables, in help order, and nothing else parses", "[tessellator][names]") {
  CHECK(joinNames(domainNames()) == "quad|tri|isoline");
  CHECK(joinNames(partitioningNames()) == "integer|pow2|fractional_even|fractional_odd");
  CHECK(joinNames(outputPrimitiveNames()) == "point|line|triangle_cw|triangle_ccw");
  CHECK(joinNames(stageNames(), " | ") ==
        "hw | hlsl-avg | hlsl-min | hlsl-max | hlsl-avg-1axis | hlsl-min-1axis | hlsl-max-1axis");
  for (const std::string& n : stageNames()) {
    Stage s;
    REQUIRE(parseStage(n.c_str(), s));
    CHECK(toString(s) == n);
  }
  for (const std::string& n : partitioningNames()) {
    Partitioning p;
    REQUIRE(parsePartitioning(n.c_str(), p));
    CHECK(toString(p) == n);
  }
  Domain d = Domain::Tri;
  CHECK_FALSE(parseDomain("Quad", d)); // exact, case-sensitive
  CHECK_FALSE(parseDomain("quad ", d));
  CHECK(d == Domain::Tri); // unchanged on failure
  Stage s;
  CHECK_FALSE(parseStage("hlsl", s));
  CHECK(std::string(toString(static_cast<Partitioning>(9))) == "?");
  CHECK(joinNames({}) == "");
}
