#pragma once
// State shared by the checker's passes over one file.
#include "Constants.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Diagnostics.h"

namespace voxc::check {

struct Context {
    Diagnostics& diagnostics;
    const Limits& limits;
    Constants constants;
};

} // namespace voxc::check
