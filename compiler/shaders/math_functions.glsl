// Math builtins of field expressions whose GLSL built-in may be computed in another operation
// order (or with a fused multiply-add), or leaves NaN operands undefined (min, max, clamp):
// written out with `precise` exactly as the interpreter computes them
// (compiler/builtins/src/functions/Math.cpp). GLSL's own abs, floor, sqrt, sin and cos are used
// directly, and its pow where that is defined (mathPow).

// NaN tested on the bits (exponent all ones, mantissa not zero), beyond any float optimisation.
bool mathIsNan(float x) { return (floatBitsToUint(x) & 0x7FFFFFFFu) > 0x7F800000u; }

// IEEE minNum / maxNum (SPIR-V NMin / NMax): b < a ? b : a (a < b ? b : a), ties keeping a,
// except that a NaN a gives b; a NaN b loses the comparison. So a NaN operand is ignored.
float mathMin(float a, float b) { return mathIsNan(a) ? b : (b < a ? b : a); }
float mathMax(float a, float b) { return mathIsNan(a) ? b : (a < b ? b : a); }
vec2 mathMin(vec2 a, vec2 b) { return vec2(mathMin(a.x, b.x), mathMin(a.y, b.y)); }
vec3 mathMin(vec3 a, vec3 b) { return vec3(mathMin(a.x, b.x), mathMin(a.y, b.y), mathMin(a.z, b.z)); }
vec2 mathMax(vec2 a, vec2 b) { return vec2(mathMax(a.x, b.x), mathMax(a.y, b.y)); }
vec3 mathMax(vec3 a, vec3 b) { return vec3(mathMax(a.x, b.x), mathMax(a.y, b.y), mathMax(a.z, b.z)); }
vec2 mathMin(vec2 a, float b) { return mathMin(a, vec2(b)); }
vec3 mathMin(vec3 a, float b) { return mathMin(a, vec3(b)); }
vec2 mathMax(vec2 a, float b) { return mathMax(a, vec2(b)); }
vec3 mathMax(vec3 a, float b) { return mathMax(a, vec3(b)); }

// pow: NaN where GLSL leaves it undefined (x < 0; x = 0 with y <= 0) or exp2(y * log2(x)) is NaN
// while the C library's pow is not (a NaN operand; x = 1 with y infinite; x infinite with
// y = 0), as Math.cpp's powOf; GLSL's pow elsewhere.
bool mathIsInf(float x) { return (floatBitsToUint(x) & 0x7FFFFFFFu) == 0x7F800000u; }
float mathPow(float x, float y) {
    bool undefined = mathIsNan(x) || mathIsNan(y) || x < 0.0 || (x == 0.0 && y <= 0.0) ||
                     (x == 1.0 && mathIsInf(y)) || (mathIsInf(x) && y == 0.0);
    return undefined ? uintBitsToFloat(0x7FC00000u) : pow(x, y);
}
vec2 mathPow(vec2 x, vec2 y) { return vec2(mathPow(x.x, y.x), mathPow(x.y, y.y)); }
vec3 mathPow(vec3 x, vec3 y) { return vec3(mathPow(x.x, y.x), mathPow(x.y, y.y), mathPow(x.z, y.z)); }

// mix(x, y, a) = x * (1 - a) + y * a, GLSL's definition.
float mathMix(float x, float y, float a) { precise float r = x * (1.0 - a) + y * a; return r; }
vec2 mathMix(vec2 x, vec2 y, vec2 a) { precise vec2 r = x * (1.0 - a) + y * a; return r; }
vec3 mathMix(vec3 x, vec3 y, vec3 a) { precise vec3 r = x * (1.0 - a) + y * a; return r; }
vec2 mathMix(vec2 x, vec2 y, float a) { return mathMix(x, y, vec2(a)); }
vec3 mathMix(vec3 x, vec3 y, float a) { return mathMix(x, y, vec3(a)); }

// smoothstep: t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t), GLSL's definition,
// also defined (as written) when e0 >= e1.
float mathSmoothstep(float e0, float e1, float x) {
    precise float t = mathMin(mathMax((x - e0) / (e1 - e0), 0.0), 1.0);
    precise float r = t * t * (3.0 - 2.0 * t);
    return r;
}
vec2 mathSmoothstep(vec2 e0, vec2 e1, vec2 x) {
    return vec2(mathSmoothstep(e0.x, e1.x, x.x), mathSmoothstep(e0.y, e1.y, x.y));
}
vec3 mathSmoothstep(vec3 e0, vec3 e1, vec3 x) {
    return vec3(mathSmoothstep(e0.x, e1.x, x.x), mathSmoothstep(e0.y, e1.y, x.y), mathSmoothstep(e0.z, e1.z, x.z));
}
vec2 mathSmoothstep(float e0, float e1, vec2 x) { return mathSmoothstep(vec2(e0), vec2(e1), x); }
vec3 mathSmoothstep(float e0, float e1, vec3 x) { return mathSmoothstep(vec3(e0), vec3(e1), x); }

// fract(x) = x - floor(x), GLSL's definition (1.0 for tiny negative x, as on the CPU).
float mathFract(float x) { precise float r = x - floor(x); return r; }
vec2 mathFract(vec2 x) { precise vec2 r = x - floor(x); return r; }
vec3 mathFract(vec3 x) { precise vec3 r = x - floor(x); return r; }

// dot and length summed left to right.
float mathDot(vec2 a, vec2 b) { precise float r = a.x * b.x + a.y * b.y; return r; }
float mathDot(vec3 a, vec3 b) { precise float r = a.x * b.x + a.y * b.y + a.z * b.z; return r; }
float mathLength(vec2 a) { return sqrt(mathDot(a, a)); }
float mathLength(vec3 a) { return sqrt(mathDot(a, a)); }
