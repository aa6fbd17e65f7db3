// Point and connectivity generation per domain. Internal header of fftess_tessellator.
#pragma once

#include "tessellator/factors.h"
#include "stitch.h"

namespace fftess::legacy {

// Each writes the patch's points (and, for triangle output, its triangles) into out; culled patches write nothing.
// Point and Line output primitives for quad/tri only need the points; the caller adds the trivial index lists.
void generateQuad(const ProcessedQuad& q, bool triangles, MeshWriter& out);
void generateTri(const ProcessedTri& t, bool triangles, MeshWriter& out);
void generateIsoline(const ProcessedIsoline& l, bool points, MeshWriter& out);

} // namespace fftess
