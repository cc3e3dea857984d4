#include "voxc/program/SolveTable.h"

#include "voxc/core/Errors.h"

#include <bit>

namespace voxc {

const SolveTable& CurvesBlock::solved() const {
    if (!table) throw InternalError("the " + source + " block '" + name + "' was not solved before its table was read "
                                    "(stages::solveBlocks)");
    return *table;
}

std::vector<int32_t> solveTableWords(const std::vector<std::shared_ptr<const SolveTable>>& tables) {
    std::vector<int32_t> words{int32_t(tables.size())};
    words.resize(1 + tables.size());
    for (size_t t = 0; t < tables.size(); ++t) {
        const SolveTable& table = *tables[t];
        words[1 + t] = int32_t(words.size());
        for (int a = 0; a < 3; ++a) words.push_back(table.min[a]);
        for (int a = 0; a < 3; ++a) words.push_back(table.size[a]);
        for (float d : table.density) words.push_back(std::bit_cast<int32_t>(d));
        for (uint8_t m : table.material) words.push_back(int32_t(m));
    }
    return words;
}

} // namespace voxc
