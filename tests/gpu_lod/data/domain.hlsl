struct HullOut { float3 PosW : POSITION; };
struct PatchTess { float EdgeTess[4] : SV_TessFactor; float InsideTess[2] : SV_InsideTessFactor; };

[domain("quad")]
float4 DS(PatchTess pt, float2 uv : SV_DomainLocation, const OutputPatch<HullOut, 4> quad) : SV_Position
{
  return float4(lerp(quad[0].PosW, quad[3].PosW, uv.x), 1.0f);
}
