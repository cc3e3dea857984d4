// libFuzzer target: arbitrary bytes through voxc::checkSource (text check, parse, constant
// folding, every block's checks, field DAGs, warnings) and the rendering of its diagnostics.
// Besides crashes and sanitizer reports, a result that breaks CheckResult's contract (a program
// exactly when there is no error) is a finding.
#include "FuzzInput.h"
#include "FuzzLimits.h"
#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const voxc::CheckResult result = voxc::checkSource(voxc::fuzz::sourceFromBytes(data, size), voxc::fuzz::fuzzLimits());
    (void)result.rendered();
    VOXC_ASSERT(result.program.has_value() != result.hasErrors());
    return 0;
}
