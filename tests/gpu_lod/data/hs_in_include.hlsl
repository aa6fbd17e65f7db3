// The engine's shader file: constants here, the hull shader itself in an included file.
cbuffer PerView { float3 EyeW; float Scale; };
#include "includes/terrain_hs.hlsli"
