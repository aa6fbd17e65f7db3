// The batch text format shared by `fftess tessellate`, the golden data, the GPU oracle and the tests.
//
// Input, one patch per line (blank lines and lines starting with '#' are skipped by the caller):
//   DOMAIN PARTITIONING TOPOLOGY STAGE f0 f1 f2 f3 f4 f5
// Each factor is a decimal float or "0x" followed by exactly 8 hex digits (the IEEE-754 bits).
// Output block per patch (every line ends in '\n'):
//   patch N points P indices I
//   P lines "UUUUUUUU VVVVVVVV" (float bits, lowercase hex)
//   the I indices, 3 per line for triangles, 2 for lines (and every non-point isoline output), 1 for points.
#pragma once

#include <string>

#include "tessellator.h"

namespace fftess {

struct BatchError {
  int column = 0;    // 1-based token number on the line (0 = the line as a whole)
  std::string token; // the offending token (empty when a token is missing)
  std::string message; // the reason, naming what was expected (e.g. "factor Ueq1: hex factor needs 0x and exactly 8
                       // hex digits"); callers print "FILE:LINE: token COLUMN 'TOKEN': MESSAGE", or without the
                       // token part when token is empty
};

// True for lines the format ignores: empty, only whitespace, or first non-blank character '#'.
bool isBatchSkippable(const std::string& line);

// Parses one patch line (no comment: '#' is not special here). On failure returns false and fills err (the caller
// adds the source and line number). Tokens are checked left to right, so the first bad or missing token is the one
// reported. Errors: an unknown word; isoline with a triangle topology (isoline output is point or line); fewer than
// 10 tokens (token empty, column = the first missing one); extra tokens after f5; a bad factor.
bool parseBatchLine(const std::string& line, Patch& patch, BatchError& err);

// The batch line of a patch (no '\n'): "DOMAIN PARTITIONING TOPOLOGY STAGE" in the names of names.h (an hlsl stage
// with its stage word, e.g. hlsl-max-1axis), then the 6 factors as 0x + 8 lowercase hex digits of their IEEE-754 bits
// (NaN payloads, -0 and denormals kept), single spaces: "quad integer triangle_cw hw 0x40000000 ...". parseBatchLine
// reads it back to the same patch, bit for bit, for every patch it can read (an isoline patch with a triangle
// topology, which it refuses, is written but not read back; the hw stage's unused reduction and axes read back as
// the defaults).
std::string formatBatchLine(const Patch& patch);

// Parses one factor token: a decimal float (std::strtof, whole token consumed: correctly rounded; nan/inf accepted;
// out-of-range decimals become +-inf, denormals or zero) or 0x + exactly 8 hex digits (the IEEE-754 bits). C99 hex
// floats ("0x1p3", "-0x40800000") are not decimals and are refused. why (optional): the reason on failure.
bool parseFactor(const std::string& token, float& out, std::string* why = nullptr);

// Name of factor i (0..5) of a batch line for the domain: quad Ueq0 Veq0 Ueq1 Veq1 insideU insideV; tri Ueq0 Veq0
// Weq0 inside f4 f5; isoline density detail f2 f3 f4 f5 (the names unused by a domain are "fN").
const char* factorName(Domain domain, int i);

// Appends the output block of one tessellated patch (index n) to out, exactly as the golden .out files.
void appendHexBlock(std::string& out, int n, const Patch& patch, const Tessellator& result);
// The same from one patch's part of packed batch arrays (tessellator/parallel.h): numPoints points, numIndices
// indices.
void appendHexBlock(std::string& out, int n, const Patch& patch, const DomainPoint* points, int numPoints,
                    const int32_t* indices, int numIndices);

// Number of indices per output line for this patch's topology (3, 2 or 1).
int indicesPerLine(const Patch& patch);

// FNV-1a 64-bit hash of a byte string (the golden .hashes files hash each output block).
uint64_t fnv1a64(const std::string& bytes);

} // namespace fftess
