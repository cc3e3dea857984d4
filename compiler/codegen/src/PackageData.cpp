// The buffers whose contents the compiler knows (an lsystem_cave's point sets, the host-solved
// tables of curves and terrain stages), as files of the package, so an engine can run a package
// from its directory alone.
#include "voxc/codegen/PackageWriter.h"

#include "voxc/core/Errors.h"
#include "voxc/program/PointSet.h"
#include "voxc/program/SolveTable.h"

#include <fmt/format.h>

namespace voxc::codegen {

std::vector<PackageData> packageData(const KernelPackage& package) {
    std::vector<PackageData> data;
    if (!package.pointSets.empty()) {
        try {
            data.push_back({kBindingPointSets, "data/point_sets.bin",
                            pointSetWords(package.pointSets, package.world.origin, package.world.size)});
        } catch (const PointSetLimitError& e) {
            throw UserError(fmt::format("the point sets' per-cell lists would need more than {} (at least {}); use a "
                                        "smaller radius or fewer points",
                                        e.cap, e.amount));
        }
    }
    if (!package.solveTables.empty())
        data.push_back({kBindingSolveTables, "data/solve_tables.bin", solveTableWords(package.solveTables)});
    return data;
}

std::string littleEndianWords(const std::vector<uint32_t>& words) {
    std::string bytes(words.size() * 4, '\0');
    for (size_t i = 0; i < words.size(); ++i)
        for (int b = 0; b < 4; ++b) bytes[4 * i + size_t(b)] = char((words[i] >> (8 * b)) & 0xFF);
    return bytes;
}

std::string littleEndianWords(const std::vector<int32_t>& words) {
    return littleEndianWords(std::vector<uint32_t>(words.begin(), words.end()));
}

} // namespace voxc::codegen
