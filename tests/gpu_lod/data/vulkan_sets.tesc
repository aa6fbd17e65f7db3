#version 450
// Vulkan GLSL as a Vulkan sample ships its TCS: descriptor sets, locations, a UBO instance and a heightmap.

layout(set = 0, binding = 0) uniform UBO
{
	mat4 projection;
	vec4 frustumPlanes[6];
	float tessellationFactor;
} ubo;

layout(set = 0, binding = 1) uniform sampler2D samplerHeight;

layout (vertices = 4) out;

layout (location = 0) in vec3 inNormal[];
layout (location = 1) in vec2 inUV[];

layout (location = 0) out vec3 outNormal[4];

void main()
{
	if (gl_InvocationID == 0)
	{
		float h = textureLod(samplerHeight, inUV[0], 0.0).r;
		gl_TessLevelInner[0] = ubo.tessellationFactor + h + ubo.frustumPlanes[2].x;
		gl_TessLevelOuter[0] = 1.0;
	}
	gl_out[gl_InvocationID].gl_Position =  gl_in[gl_InvocationID].gl_Position;
	outNormal[gl_InvocationID] = inNormal[gl_InvocationID];
}
