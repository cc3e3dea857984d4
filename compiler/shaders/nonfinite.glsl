// Non-finite densities (docs/language.md, "Non-finite values"), as voxc::NonFiniteCount does it
// on the CPU: a field stage stores 0 where its field is NaN or infinite, a grammar stores 0
// where a written value is not finite, and the stage counts them. The runtime copies this
// buffer out after every stage and resets it to {0, 0, 0xFFFFFFFF} (kBindingNonFinite).
layout(std430, set = 0, binding = 9) buffer NonFinite {
    uint countLow;   // replacements in the current stage, a 64-bit count in two halves
    uint countHigh;
    uint firstIndex; // the lowest grid index x + sx * (y + sy * z) replaced
} nonFinite;

// An exponent of all ones is an infinity or a NaN; tested on the bits, so no float
// optimisation of the driver can change the answer.
bool isFiniteFloat(float v) { return (floatBitsToUint(v) & 0x7F800000u) != 0x7F800000u; }

// `value` when finite; otherwise 0, counted at grid-local voxel `local`.
float finiteDensity(float value, ivec3 local) {
    if (isFiniteFloat(value)) return value;
    if (atomicAdd(nonFinite.countLow, 1u) == 0xFFFFFFFFu) atomicAdd(nonFinite.countHigh, 1u);
    atomicMin(nonFinite.firstIndex, uint(local.x + push.gridSize.x * (local.y + push.gridSize.y * local.z)));
    return 0.0;
}
