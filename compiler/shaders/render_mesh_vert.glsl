#version 450
// The offscreen renderer's vertex stage (voxc/render/MeshRenderer.h): world-space vertices with a
// normal, a colour and the light that reaches it (ambient occlusion, sun visibility). Lines (wireframe, chunk borders) have a zero normal and are pulled a little
// towards the eye so that they win the depth test against the faces they lie on.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
layout(location = 3) in vec2 light;

layout(push_constant) uniform Frame {
    mat4 viewProjection;
    vec4 eye;   // xyz: the camera position; w: the fraction of the way to the eye a vertex moves
    vec4 light; // xyz: unit direction towards the light; w: the ambient share
} frame;

layout(location = 0) out vec3 surfaceNormal;
layout(location = 1) out vec3 surfaceColour;
layout(location = 2) out vec2 surfaceLight;

void main() {
    const vec3 pulled = mix(position, frame.eye.xyz, frame.eye.w);
    gl_Position = frame.viewProjection * vec4(pulled, 1.0);
    surfaceNormal = normal;
    surfaceColour = colour;
    surfaceLight = light;
}
