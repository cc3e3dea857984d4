#pragma once
// The program a test's source text checks to. Text that does not check (or, with
// Allowed::None, that draws any warning) fails the test with the rendered diagnostics and
// throws, so the test stops there instead of running an empty program.
#include "voxc/check/Check.h"

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

namespace voxc::test {

enum class Allowed { Warnings, None };

inline Program checkedProgram(const std::string& fileName, const std::string& text,
                              Allowed allowed = Allowed::Warnings) {
    CheckResult result = checkSource(SourceFile(fileName, text));
    const bool ok = allowed == Allowed::None ? result.diagnostics.empty() : !result.hasErrors();
    if (!ok || !result.program) {
        ADD_FAILURE() << result.rendered();
        throw std::runtime_error(fileName + " did not check");
    }
    return std::move(*result.program);
}

} // namespace voxc::test
