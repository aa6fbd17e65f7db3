// Included by hs_in_include.hlsl: the hull shader and its patch-constant function.
struct Corner { float3 W : POSITION; };
struct Levels { float o[4] : SV_TessFactor; float n[2] : SV_InsideTessFactor; };

Levels PatchLevels(InputPatch<Corner, 4> c)
{
  Levels l;
  float f = Scale / distance(c[0].W, EyeW);
  l.o[0] = f; l.o[1] = f; l.o[2] = f; l.o[3] = f; l.n[0] = f; l.n[1] = f;
  return l;
}

[domain("quad")] [partitioning("fractional_odd")] [outputtopology("triangle_cw")]
[outputcontrolpoints(4)] [patchconstantfunc("PatchLevels")]
Corner TerrainHS(InputPatch<Corner, 4> c, uint i : SV_OutputControlPointID) { return c[i]; }
