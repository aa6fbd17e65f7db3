// The cbuffer and the vertex struct come from an #include, relative to this file.
#include "includes/common.hlsli"

struct PatchTess { float EdgeTess[4] : SV_TessFactor; float InsideTess[2] : SV_InsideTessFactor; };

PatchTess ConstantHS(InputPatch<VertexOut, 4> patch)
{
  PatchTess pt;
  float f = distance(patch[0].PosW, gEyePosW);
  pt.EdgeTess[0] = f; pt.EdgeTess[1] = f; pt.EdgeTess[2] = f; pt.EdgeTess[3] = f;
  pt.InsideTess[0] = f; pt.InsideTess[1] = f;
  return pt;
}

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(4)] [patchconstantfunc("ConstantHS")]
VertexOut HS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID) { return p[i]; }
