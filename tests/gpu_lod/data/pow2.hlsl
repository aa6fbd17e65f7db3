// D3D's pow2 partitioning, which glslang does not know.
struct CP { float3 P : POSITION; };
struct PF { float e[4] : SV_TessFactor; float i[2] : SV_InsideTessFactor; };
PF Factors(InputPatch<CP, 4> q) { PF f; f.e[0] = f.e[1] = f.e[2] = f.e[3] = q[0].P.x; f.i[0] = f.i[1] = 4; return f; }

[domain("quad")]
[partitioning("pow2")]
[outputtopology("triangle_cw")] [outputcontrolpoints(4)] [patchconstantfunc("Factors")]
CP Main(InputPatch<CP, 4> q, uint k : SV_OutputControlPointID) { return q[k]; }
