#include "voxc/program/Random.h"

namespace voxc {

uint32_t anchorHash(uint32_t seed, uint32_t iteration, uint32_t sweep, glm::ivec3 anchorWorld, RandomStream stream) {
    uint32_t h = mix32(uint32_t(stream));
    h = mix32(uint32_t(anchorWorld.z) ^ h);
    h = mix32(uint32_t(anchorWorld.y) ^ h);
    h = mix32(uint32_t(anchorWorld.x) ^ h);
    h = mix32(sweep ^ h);
    h = mix32(iteration ^ h);
    return mix32(seed ^ h);
}

} // namespace voxc
