// The camera's uniforms, included by uniforms.tesc.
uniform vec3 uEye;
