// A terrain hull shader in the form of Frank Luna's Terrain.fx ("3D Game Programming with DirectX 11", the terrain
// chapter): a cbuffer with the camera and the distance range, control points carrying the world position, the
// texture coordinate and the patch's height bounds (BoundsY), a patch-constant function that culls the patch's box
// against the frustum planes and gives each edge 2^lerp(gMaxTess, gMinTess, s) from its midpoint's distance to the
// eye. Row vectors: mul(v, M). fftess example (docs/examples/hull/README.md); our code.
//
// Control points as the grid's index buffer sends them: 0 = (-x, +z), 1 = (+x, +z), 2 = (-x, -z), 3 = (+x, -z); the
// domain shader (terrain_ds.hlsl) runs u from 0 to 1 (+x) and v from 0 to 2 (-z), so SV_TessFactor[0..3] are the
// edges u = 0 (points 0-2), v = 0 (0-1), u = 1 (1-3), v = 1 (2-3).

cbuffer cbTerrain : register(b0)
{
    float4x4 gViewProj;
    float3 gEyePosW;
    float gMinDist;   // distance where the factor starts to fall from 2^gMaxTess
    float gMaxDist;   // distance where it reaches 2^gMinTess
    float gMinTess;   // exponents
    float gMaxTess;
    float gHeightScale; // world height of texel value 1 (the domain shader's)
    float4 gWorldFrustumPlanes[6];
};

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
    float2 Tex  : TEXCOORD0;
    float4 PosH : TEXCOORD1; // clip position of the control point (for a later stage; fftess reads only the factors)
};

float DistanceFactor(float3 p)
{
    float d = distance(p, gEyePosW);
    float s = saturate((d - gMinDist) / (gMaxDist - gMinDist));
    return pow(2.0f, lerp(gMaxTess, gMinTess, s));
}

// Whether the box lies entirely behind one plane (the plane's normal points into the frustum).
bool BoxBehindPlane(float3 centre, float3 halfSize, float4 plane)
{
    float reach = dot(halfSize, abs(plane.xyz));
    float signedDist = dot(float4(centre, 1.0f), plane);
    return signedDist + reach < 0.0f;
}

bool BoxOutsideFrustum(float3 lo, float3 hi)
{
    float3 centre = 0.5f * (lo + hi);
    float3 halfSize = 0.5f * (hi - lo);
    [unroll]
    for (int i = 0; i < 6; ++i)
    {
        if (BoxBehindPlane(centre, halfSize, gWorldFrustumPlanes[i]))
            return true;
    }
    return false;
}

PatchTess ConstantHS(InputPatch<VertexOut, 4> patch, uint patchID : SV_PrimitiveID)
{
    PatchTess pt;

    float3 lo = min(min(patch[0].PosW, patch[1].PosW), min(patch[2].PosW, patch[3].PosW));
    float3 hi = max(max(patch[0].PosW, patch[1].PosW), max(patch[2].PosW, patch[3].PosW));
    lo.y = patch[0].BoundsY.x;
    hi.y = patch[0].BoundsY.y;

    if (BoxOutsideFrustum(lo, hi))
    {
        pt.EdgeTess[0] = 0.0f;
        pt.EdgeTess[1] = 0.0f;
        pt.EdgeTess[2] = 0.0f;
        pt.EdgeTess[3] = 0.0f;
        pt.InsideTess[0] = 0.0f;
        pt.InsideTess[1] = 0.0f;
        return pt;
    }

    float3 e0 = 0.5f * (patch[0].PosW + patch[2].PosW);
    float3 e1 = 0.5f * (patch[0].PosW + patch[1].PosW);
    float3 e2 = 0.5f * (patch[1].PosW + patch[3].PosW);
    float3 e3 = 0.5f * (patch[2].PosW + patch[3].PosW);
    float3 c = 0.25f * (patch[0].PosW + patch[1].PosW + patch[2].PosW + patch[3].PosW);

    pt.EdgeTess[0] = DistanceFactor(e0);
    pt.EdgeTess[1] = DistanceFactor(e1);
    pt.EdgeTess[2] = DistanceFactor(e2);
    pt.EdgeTess[3] = DistanceFactor(e3);
    pt.InsideTess[0] = DistanceFactor(c);
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
    hout.Tex = p[i].Tex;
    hout.PosH = mul(float4(p[i].PosW, 1.0f), gViewProj);
    return hout;
}
