// Included by include.hlsl.
cbuffer cbPerFrame
{
  float3 gEyePosW;
};

struct VertexOut { float4 PosH : SV_Position; float3 PosW : POSITION; };
