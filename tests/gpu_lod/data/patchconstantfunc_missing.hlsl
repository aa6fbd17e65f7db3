// The patch-constant function named by the attribute does not exist (it is called Factors).
struct CP
{
  float3 P : POSITION;
};

[domain("quad")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(4)]
[patchconstantfunc("PatchFactors")]
CP Main(InputPatch<CP, 4> q, uint k : SV_OutputControlPointID)
{
  return q[k];
}
