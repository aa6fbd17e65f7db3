// Internal to fftess_gl (gl_capture.cpp and its tests): what the capture does with the raw transform-feedback records
// of one draw, apart from drawing. A record is one captured primitive: perPrim vertices (1 point, 2 line, 3 triangle)
// of kCaptureStride words each, (u bits, v bits, draw-local gl_PrimitiveID, vertex id or 0). See docs/oracle.md.
#pragma once

#include "gl_capture.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fftess {
namespace oracle {
namespace records {

constexpr int kCaptureStride = 4; // uvec4 per captured vertex

// Test hook of the order-free capture (RunOptions::permuteSeed): shuffles the records of one draw (seeded
// Fisher-Yates with splitmix64) and rotates the vertices of each triangle cyclically by a seeded amount (winding
// kept; lines keep their direction), as a driver that emits in its own order and from its own first vertex would.
void permute(std::vector<uint32_t>& words, int perPrim, uint64_t seed);

// The order-free split: appends the (u, v) words of each record's vertices to *out[local], local = the record's
// draw-local patch id, whatever the order of the records. False with 'error' when a record names a patch outside
// the draw (local >= out.size()) or its vertices name different patches.
bool fileByPatch(const std::vector<uint32_t>& words, int perPrim, const std::vector<std::vector<uint32_t>*>& out,
                 std::string& error);

// Result::indices of an order-free capture, from coordinates: each primitive vertex's index in the point array,
// when every point's (u, v) bits occur once in the array and every primitive vertex is one of them; otherwise (the
// reference emits coincident points for some fractional factors, or the two passes disagree) indices stays empty:
// the numbering is not observable without an order assumption. Does nothing for a result without primitives.
void indicesByCoordinates(Result& r);

} // namespace records
} // namespace oracle
} // namespace fftess
