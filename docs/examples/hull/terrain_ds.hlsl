// The domain shader that goes with terrain_hs.hlsl (lod.evaluation_shader): fftess reads its [domain("quad")] and
// checks it against the hull shader and the scene. u runs from control point 0 to 1 (+x), v from 0 to 2 (-z); the
// position is the bilinear blend of the flat corners, raised to the heightmap. fftess example; our code.

cbuffer cbTerrain : register(b0)
{
    float4x4 gViewProj;
    float3 gEyePosW;
    float gMinDist;
    float gMaxDist;
    float gMinTess;
    float gMaxTess;
    float gHeightScale; // world height of texel value 1 (the domain shader's)
    float4 gWorldFrustumPlanes[6];
};

Texture2D gHeightMap : register(t0);
SamplerState samHeightmap : register(s0);

struct PatchTess
{
    float EdgeTess[4]   : SV_TessFactor;
    float InsideTess[2] : SV_InsideTessFactor;
};

struct HullOut
{
    float3 PosW : POSITION;
    float2 Tex  : TEXCOORD0;
    float4 PosH : TEXCOORD1;
};

struct DomainOut
{
    float4 PosH : SV_POSITION;
    float3 PosW : POSITION;
    float2 Tex  : TEXCOORD0;
};

[domain("quad")]
DomainOut DS(PatchTess patchTess, float2 uv : SV_DomainLocation, const OutputPatch<HullOut, 4> quad)
{
    DomainOut dout;
    dout.PosW = lerp(lerp(quad[0].PosW, quad[1].PosW, uv.x), lerp(quad[2].PosW, quad[3].PosW, uv.x), uv.y);
    dout.Tex = lerp(lerp(quad[0].Tex, quad[1].Tex, uv.x), lerp(quad[2].Tex, quad[3].Tex, uv.x), uv.y);
    dout.PosW.y = gHeightMap.SampleLevel(samHeightmap, dout.Tex, 0).r * gHeightScale;
    dout.PosH = mul(float4(dout.PosW, 1.0f), gViewProj);
    return dout;
}
