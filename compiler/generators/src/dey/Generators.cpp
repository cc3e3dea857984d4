#include "voxc/generators/dey/Generators.h"

#include "Records.h"

#include "voxc/core/Errors.h"

#include <array>
#include <functional>

namespace voxc::dey {

double GeneratorParams::number(std::string_view key) const {
    auto it = values_.find(key);
    VOXC_ASSERT(it != values_.end());
    return it->second[0];
}

glm::dvec3 GeneratorParams::vec(std::string_view key) const {
    auto it = values_.find(key);
    VOXC_ASSERT(it != values_.end());
    return {it->second[0], it->second[1], it->second[2]};
}

std::span<const GeneratorInfo> generators() {
    static const std::array<GeneratorInfo, 3> all{archGenerator(), caveGenerator(), overhangGenerator()};
    return all;
}

const GeneratorInfo* findGenerator(std::string_view name) {
    for (const GeneratorInfo& info : generators())
        if (info.name == name) return &info;
    return nullptr;
}

} // namespace voxc::dey
