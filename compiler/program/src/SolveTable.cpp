#include "voxc/program/SolveTable.h"

#include "voxc/core/Errors.h"

#include <cstring>

namespace voxc {

const SolveTable& CurvesBlock::solved() const {
    if (!table) throw InternalError("the " + source + " block '" + name + "' was not solved before its table was read "
                                    "(stages::solveBlocks)");
    return *table;
}

size_t solveTableWordCount(const std::vector<std::shared_ptr<const SolveTable>>& tables) {
    size_t words = 1 + tables.size();
    for (const auto& table : tables) words += 6 + table->density.size() + table->material.size();
    return words;
}

void writeSolveTableWords(const std::vector<std::shared_ptr<const SolveTable>>& tables, std::span<int32_t> out) {
    if (out.size() != solveTableWordCount(tables)) throw InternalError("writeSolveTableWords: the span has the wrong size");
    out[0] = int32_t(tables.size());
    size_t next = 1 + tables.size();
    for (size_t t = 0; t < tables.size(); ++t) {
        const SolveTable& table = *tables[t];
        out[1 + t] = int32_t(next);
        for (int a = 0; a < 3; ++a) out[next++] = table.min[a];
        for (int a = 0; a < 3; ++a) out[next++] = table.size[a];
        static_assert(sizeof(float) == sizeof(int32_t));
        std::memcpy(out.data() + next, table.density.data(), table.density.size() * sizeof(float)); // the float bits
        next += table.density.size();
        for (uint8_t m : table.material) out[next++] = int32_t(m);
    }
}

std::vector<int32_t> solveTableWords(const std::vector<std::shared_ptr<const SolveTable>>& tables) {
    std::vector<int32_t> words(solveTableWordCount(tables));
    writeSolveTableWords(tables, words);
    return words;
}

} // namespace voxc
