#include "SpeleothemCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc::bench {

Program speleothemProgram(int n, bool withStage) {
    const std::string text = fmt::format(R"(world {{ size = [{0}, 96, {0}]; chunk = 32; seed = 5; }}
start {{
  fill {{ value = 1; }}
  box {{ min = [0, 8, 0]; max = [{0}, 30, {0}]; value = 0; }}
  box {{ min = [0, 40, 0]; max = [{0}, 70, {0}]; value = 0; }}
  box {{ min = [0, 78, 0]; max = [{0}, 90, {0}]; value = 0; }}
}}
feature drips = speleothems {{ kind = hoodoo; cluster_low = -1; }}
pipeline {{ start; {1} }}
)",
                                         n, withStage ? "drips;" : "");
    CheckResult result = checkSource(SourceFile("speleothems.vox", text));
    if (result.hasErrors() || !result.program)
        throw InternalError("the speleothems bench program does not check:\n" + result.rendered());
    return std::move(*result.program);
}

} // namespace voxc::bench
