// Signed distance builtins of field expressions, all `precise`, in the operation order of the
// interpreter (compiler/builtins/src/functions/Sdf.cpp). Needs math_functions.glsl (mathDot,
// mathLength, mathMix, mathMin, mathMax). sdf_union/subtract/intersect are emitted inline as
// mathMin/mathMax (a NaN operand ignored, as everywhere in field expressions).

float sdfSphere(vec3 p, vec3 center, float radius) {
    precise vec3 d = p - center;
    precise float r = mathLength(d) - radius;
    return r;
}

// Exact Euclidean box distance; negative half sizes count by their magnitude.
float sdfBox(vec3 p, vec3 center, vec3 halfSize) {
    precise vec3 q = abs(p - center) - abs(halfSize);
    precise float outside = mathLength(mathMax(q, vec3(0.0)));
    precise float inside = mathMin(mathMax(q.x, mathMax(q.y, q.z)), 0.0);
    precise float r = outside + inside;
    return r;
}

// Distance to the segment ab minus the radius; a == b is a sphere around a.
float sdfCapsule(vec3 p, vec3 a, vec3 b, float radius) {
    precise vec3 pa = p - a;
    precise vec3 ba = b - a;
    precise float baba = mathDot(ba, ba);
    precise float h = 0.0;
    if (baba > 0.0) h = mathMin(mathMax(mathDot(pa, ba) / baba, 0.0), 1.0);
    precise vec3 closest = pa - ba * h;
    precise float r = mathLength(closest) - radius;
    return r;
}

// Signed distance to dot(p, normal / |normal|) = offset; a zero normal gives -offset.
float sdfPlane(vec3 p, vec3 normal, float offset) {
    precise float n = mathLength(normal);
    if (!(n > 0.0)) return -offset;
    precise float r = mathDot(p, normal) / n - offset;
    return r;
}

float sdfHeightfield(vec3 p, float height) {
    precise float r = p.y - height;
    return r;
}

// Polynomial smooth minimum with blend radius k; k <= 0 is the hard minimum.
float sdfSmoothUnion(float a, float b, float k) {
    if (!(k > 0.0)) return mathMin(a, b);
    precise float h = mathMin(mathMax(0.5 + 0.5 * (b - a) / k, 0.0), 1.0);
    precise float r = mathMix(b, a, h) - k * h * (1.0 - h);
    return r;
}
float sdfSmoothIntersect(float a, float b, float k) { return -sdfSmoothUnion(-a, -b, k); }
float sdfSmoothSubtract(float a, float b, float k) { return sdfSmoothIntersect(a, -b, k); }

// Distance to grammar density: surface 0.5, inside 1, a ramp `width` voxels wide; width <= 0 is a step.
float sdfDensity(float d, float width) {
    if (!(width > 0.0)) return d < 0.0 ? 1.0 : (d > 0.0 ? 0.0 : 0.5);
    precise float r = mathMin(mathMax(0.5 - d / width, 0.0), 1.0);
    return r;
}
