// Declarations every erosion pass shares (runtime/vulkan/src/GpuErosion.cpp builds the passes
// into a SolveProgram; the host step they reproduce is compiler/generators/src/terrain/Erosion.cpp,
// docs/terrain.md "Erosion"). One invocation per cell, cells row-major (x fastest). Every float
// result is `precise` and std::min / std::max / std::clamp are written out as the C++ library
// defines them (b < a ? b : a, a < b ? b : a, v < lo ? lo : (hi < v ? hi : v)), so signed zeros
// resolve as on the host and lavapipe's results are the host's bit for bit.

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
    ivec4 grid;  // x: width, y: height, z: the current S_h channel, w: the other S_h channel
    ivec4 mode;  // x: the pass's switch (rain: drops; surface: with water; transport: mei)
    vec4 values; // rain: intensity or amount, radius², centre x, centre y; evaporation: keep in x
    vec4 unused;
} push;

// Words 0..15: the step's constants (GpuErosion.cpp, kHeader*), then channel c at
// kChannels + c * width * height.
layout(std430, set = 0, binding = 0) buffer State { float state[]; };
layout(std430, set = 0, binding = 1) buffer Measure { uint measure; };

const int kCoefficient = 0, kPipeLength = 1, kArea = 2, kDt = 3, kSpeedLimit = 4, kCellSize = 5,
          kDepthLimit = 6, kLimited = 7, kCapacity = 8, kMinTilt = 9, kSuspensionRate = 10,
          kDepositionRate = 11, kChannels = 16;
const int kBase = 0, kRain = 1, kCapacityField = 2, kWater = 5, kSediment = 6, kFluxL = 7, kFluxR = 8,
          kFluxT = 9, kFluxB = 10, kVelocityU = 11, kVelocityV = 12, kSuspended = 13, kSurface = 14;

float constant(int which) { return state[which]; }
int cells() { return push.grid.x * push.grid.y; }
int at(int channel, int i) { return kChannels + channel * cells() + i; }
int at(int channel, int x, int y) { return at(channel, y * push.grid.x + x); }
float load(int channel, int i) { return state[at(channel, i)]; }
float load(int channel, int x, int y) { return state[at(channel, x, y)]; }
void store(int channel, int i, float v) { state[at(channel, i)] = v; }

float stdMin(float a, float b) { return b < a ? b : a; }
float stdMax(float a, float b) { return a < b ? b : a; }
float stdClamp(float v, float lo, float hi) { return v < lo ? lo : (hi < v ? hi : v); }

// The cell of this invocation, or -1 past the grid.
int cellOfInvocation() {
    int i = int(gl_GlobalInvocationID.x);
    return i < cells() ? i : -1;
}
