// Two hull shaders of one file (near and far rings) and a helper: lod.entry must name one of the hull shaders.
struct VertexOut { float3 PosW : POSITION; };
struct Factors { float Edge[4] : SV_TessFactor; float Inside[2] : SV_InsideTessFactor; };

Factors Uniform(float f) { Factors t; t.Edge[0] = f; t.Edge[1] = f; t.Edge[2] = f; t.Edge[3] = f; t.Inside[0] = f; t.Inside[1] = f; return t; }
Factors NearPatch(InputPatch<VertexOut, 4> patch) { return Uniform(16.0f); }
Factors FarPatch(InputPatch<VertexOut, 4> patch) { return Uniform(2.0f); }

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_ccw")] [outputcontrolpoints(4)] [patchconstantfunc("NearPatch")]
VertexOut NearHS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID) { return p[i]; }

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_ccw")] [outputcontrolpoints(4)] [patchconstantfunc("FarPatch")]
VertexOut FarHS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID) { return p[i]; }
