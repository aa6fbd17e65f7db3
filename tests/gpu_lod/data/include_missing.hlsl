#include "includes/nowhere.hlsli"

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(4)] [patchconstantfunc("PatchHS")]
VertexOut HS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID) { return p[i]; }
