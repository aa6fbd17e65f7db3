struct ControlPoint { float3 PosW : POSITION; };
struct Tess { float E[4] : SV_TessFactor; float I[2] : SV_InsideTessFactor; };

Tess Constant(InputPatch<ControlPoint, 4> patch)
{
  Tess pt;
  float f = 2.0f
  pt.E[0] = f; pt.E[1] = f; pt.E[2] = f; pt.E[3] = f; pt.I[0] = f; pt.I[1] = f;
  return pt;
}

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(4)] [patchconstantfunc("Constant")]
ControlPoint HS(InputPatch<ControlPoint, 4> p, uint i : SV_OutputControlPointID) { return p[i]; }
