struct VertexOut { float3 PosW : POSITION; };
struct PatchTess { float EdgeTess[4] : SV_TessFactor; float InsideTess[2] : SV_InsideTessFactor; };

PatchTess ConstantHS(InputPatch<VertexOut, 4> patch, uint patchID : SV_PrimitiveID)
{
  PatchTess pt;
  pt.EdgeTess[0] = 1; pt.EdgeTess[1] = 2; pt.EdgeTess[2] = 3; pt.EdgeTess[3] = 4;
  pt.InsideTess[0] = 5; pt.InsideTess[1] = 6;
  return pt;
}

[domain("quad")]
  [partitioning("fractional_odd")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("ConstantHS")]
VertexOut HS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID)
{
  return p[i];
}
