// fftess names: the spelling of every tessellator enum in the batch format, the CLI, scene files and reports.
//
// One table per enum (names.cpp) gives both directions: toString() prints a value with it and the parse functions
// read with it, so a name accepted on input is the name printed on output. Help texts and error messages list the
// accepted names with the *Names() functions and joinNames() instead of spelling the lists out.
#pragma once

#include <string>
#include <vector>

#include "tessellator/tessellator.h"

namespace fftess {

// The name of a domain: "quad", "tri" or "isoline".
// d: any Domain value; a value outside the enum gives "?".
const char* toString(Domain d);

// The name of a partitioning: "integer", "pow2", "fractional_even" or "fractional_odd" (D3D11's
// [partitioning(...)] attribute values, with fractional_even/fractional_odd spelled as in HLSL).
// p: any Partitioning value; a value outside the enum gives "?".
const char* toString(Partitioning p);

// The name of an output primitive: "point", "line", "triangle_cw" or "triangle_ccw" (HLSL's [outputtopology]).
// p: any OutputPrimitive value; a value outside the enum gives "?".
const char* toString(OutputPrimitive p);

// The name of a stage: "hw" for the hardware stage, or "hlsl-" + reduction ("avg", "min", "max") + "-1axis" for
// the one-axis quad reduction: hw | hlsl-avg | hlsl-min | hlsl-max | hlsl-avg-1axis | hlsl-min-1axis |
// hlsl-max-1axis.
// s: any Stage; reduction and axes are ignored when s.hlsl is false; a reduction or axes value outside its enum
// gives "?".
const char* toString(const Stage& s);

// Reads a domain name (as toString prints it). Returns false and leaves out unchanged if s is not one.
// s: a NUL-terminated string, not null; the comparison is exact (case-sensitive, no surrounding spaces).
bool parseDomain(const char* s, Domain& out);

// Reads a partitioning name (as toString prints it). Returns false and leaves out unchanged if s is not one.
// s: a NUL-terminated string, not null; exact comparison.
bool parsePartitioning(const char* s, Partitioning& out);

// Reads an output primitive name (as toString prints it). Returns false and leaves out unchanged if s is not one.
// s: a NUL-terminated string, not null; exact comparison.
bool parseOutputPrimitive(const char* s, OutputPrimitive& out);

// Reads a stage name (as toString prints it). Returns false and leaves out unchanged if s is not one. "hw" gives
// the default Stage (hlsl false, Average, TwoAxis).
// s: a NUL-terminated string, not null; exact comparison.
bool parseStage(const char* s, Stage& out);

// Every accepted name of an enum, in the order help texts and error messages list them (the table order).
// The vectors live for the whole program; the names are exactly those toString() prints and the parse functions
// accept.
const std::vector<std::string>& domainNames();
const std::vector<std::string>& partitioningNames();
const std::vector<std::string>& outputPrimitiveNames();
const std::vector<std::string>& stageNames();

// The names joined for a help text or an error message, e.g. joinNames(stageNames(), " | ") gives
// "hw | hlsl-avg | ... | hlsl-max-1axis".
// names: any list (empty gives ""); separator: any string, "|" by default as in the batch format's help.
std::string joinNames(const std::vector<std::string>& names, const std::string& separator = "|");

} // namespace fftess
