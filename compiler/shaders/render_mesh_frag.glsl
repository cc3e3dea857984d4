#version 450
// The offscreen renderer's fragment stage: ambient plus one directional light on the material's
// linear colour, then the sRGB transfer curve, since the image is stored as plain 8-bit RGBA.
// The ambient term is scaled by the vertex's ambient occlusion, the directional one by its sun
// visibility (both 1 where the caller measured none).
// A zero normal (a line) takes its colour unlit.

layout(location = 0) in vec3 surfaceNormal;
layout(location = 1) in vec3 surfaceColour;
layout(location = 2) in vec2 surfaceLight;

layout(push_constant) uniform Frame {
    mat4 viewProjection;
    vec4 eye;
    vec4 light;
} frame;

layout(location = 0) out vec4 pixel;

float encodeSrgb(float linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

void main() {
    vec3 lit = surfaceColour;
    const float length2 = dot(surfaceNormal, surfaceNormal);
    if (length2 > 0.0) {
        const vec3 n = surfaceNormal * inversesqrt(length2);
        const float ambient = frame.light.w;
        lit *= ambient * surfaceLight.x + (1.0 - ambient) * surfaceLight.y * max(dot(n, frame.light.xyz), 0.0);
    }
    lit = clamp(lit, 0.0, 1.0);
    pixel = vec4(encodeSrgb(lit.r), encodeSrgb(lit.g), encodeSrgb(lit.b), 1.0);
}
