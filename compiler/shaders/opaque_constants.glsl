// Field-expression constants kept from the shader compilers' own folding (docs/fuzzing.md).
// llvmpipe (lavapipe's NIR passes and its LLVM code builder) rewrites an operation with a
// constant zero operand as if signed zeros, infinities and NaN did not exist, `precise` or not:
// x + 0 -> x (so -0 stays -0), 0 - x -> -x (so +0 becomes -0), x * 0 -> +0 (also for a
// negative, infinite or NaN x), x / 0 -> NaN, 0 / x -> +0 (docs/fuzzing.md has the table).
// The interpreter computes these as IEEE does. Codegen passes the constants that could reach
// such an operation through opaqueConstant: the same value while the kernel runs (no dispatch
// has zero workgroups), but not one the compilers can fold. The test is the same for every
// invocation, so it costs a uniform select.
bool dispatchIsEmpty() { return gl_NumWorkGroups.x == 0u; }
float opaqueConstant(float c) { return dispatchIsEmpty() ? uintBitsToFloat(0x7FC00000u) : c; }
vec2 opaqueConstant(vec2 c) { return dispatchIsEmpty() ? vec2(uintBitsToFloat(0x7FC00000u)) : c; }
vec3 opaqueConstant(vec3 c) { return dispatchIsEmpty() ? vec3(uintBitsToFloat(0x7FC00000u)) : c; }

// A constant glslang leaves alone: it folds an expression of literals itself, in double from their
// decimal text, where the driver, which inlines this call, folds it in float as the interpreter
// computes it.
float driverFolded(float c) { return c; }
