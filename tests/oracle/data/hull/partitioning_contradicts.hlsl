// expect: partitioning_contradicts.hlsl:47:1: error: [partitioning("integer")] contradicts the scene's
// tessellation.partitioning = "fractional_odd" (partitioning_contradicts.toml)
// fftess negative fixture (exit 2, that one line; also reported at the scene's key is fine): a small distance hull
// shader, complete and bound, whose only fault is the partitioning attribute against that scene. wrong_entry.toml
// uses it too, with a matching tessellation.partitioning and a wrong lod.entry.

cbuffer cbLod : register(b0)
{
    float3 gEyePosW;
    float gScale;
};

struct VertexOut
{
    float3 PosW : POSITION;
};

struct PatchTess
{
    float EdgeTess[4]   : SV_TessFactor;
    float InsideTess[2] : SV_InsideTessFactor;
};

struct HullOut
{
    float3 PosW : POSITION;
};

float EdgeFactor(float3 a, float3 b)
{
    return clamp(gScale / (1.0f + distance(0.5f * (a + b), gEyePosW)), 1.0f, 64.0f);
}

PatchTess PatchHS(InputPatch<VertexOut, 4> p, uint patchID : SV_PrimitiveID)
{
    PatchTess pt;
    pt.EdgeTess[0] = EdgeFactor(p[0].PosW, p[2].PosW);
    pt.EdgeTess[1] = EdgeFactor(p[0].PosW, p[1].PosW);
    pt.EdgeTess[2] = EdgeFactor(p[1].PosW, p[3].PosW);
    pt.EdgeTess[3] = EdgeFactor(p[2].PosW, p[3].PosW);
    pt.InsideTess[0] = max(pt.EdgeTess[1], pt.EdgeTess[3]);
    pt.InsideTess[1] = max(pt.EdgeTess[0], pt.EdgeTess[2]);
    return pt;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("PatchHS")]
HullOut HS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID)
{
    HullOut o;
    o.PosW = p[i].PosW;
    return o;
}
