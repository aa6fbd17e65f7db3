// An HLSL constant hull shader in the forms engines use: a cbuffer, a global, a texture, attributes.
cbuffer cbPerFrame : register(b0)
{
  float4x4 gViewProj;
  float3 gEyePosW;
  float gMinDist;
  float gMaxDist;
  float gUnusedMember;
};

float gMaxTess;
Texture2D gHeightMap;
SamplerState samHeightmap { Filter = MIN_MAG_LINEAR_MIP_POINT; AddressU = CLAMP; AddressV = CLAMP; };

struct VertexOut
{
  float3 PosW    : POSITION;
  float2 Tex     : TEXCOORD0;
  float2 BoundsY : TEXCOORD1;
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

float factorAt(float3 p, float2 uv)
{
  float h = gHeightMap.SampleLevel(samHeightmap, uv, 0).r;
  float d = distance(float3(p.x, h, p.z), gEyePosW);
  float s = saturate((d - gMinDist) / (gMaxDist - gMinDist));
  return pow(2, lerp(gMaxTess, 0.0f, s));
}

PatchTess ConstantHS(InputPatch<VertexOut, 4> patch, uint patchID : SV_PrimitiveID)
{
  PatchTess pt;
  float3 c = 0.25f * (patch[0].PosW + patch[1].PosW + patch[2].PosW + patch[3].PosW);
  float y = patch[0].BoundsY.x;
  pt.EdgeTess[0] = factorAt(0.5f * (patch[0].PosW + patch[2].PosW), patch[0].Tex);
  pt.EdgeTess[1] = factorAt(0.5f * (patch[0].PosW + patch[1].PosW), patch[1].Tex);
  pt.EdgeTess[2] = factorAt(0.5f * (patch[1].PosW + patch[3].PosW), patch[2].Tex);
  pt.EdgeTess[3] = factorAt(0.5f * (patch[2].PosW + patch[3].PosW), patch[3].Tex) + y;
  pt.InsideTess[0] = factorAt(c, patch[0].Tex);
  pt.InsideTess[1] = pt.InsideTess[0];
  return pt;
}

[domain("quad")]
[partitioning("fractional_even")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("ConstantHS")]
[maxtessfactor(64.0f)]
HullOut HS(InputPatch<VertexOut, 4> p, uint i : SV_OutputControlPointID, uint patchId : SV_PrimitiveID)
{
  HullOut hout;
  hout.PosW = p[i].PosW;
  return hout;
}

RasterizerState WireframeRS
{
  FillMode = Wireframe;
  CullMode = None;
};

technique11 Terrain
{
  pass P0
  {
    SetVertexShader(CompileShader(vs_5_0, VS()));
    SetHullShader(CompileShader(hs_5_0, HS()));
    SetRasterizerState(WireframeRS);
  }
}
