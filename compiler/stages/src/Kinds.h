#pragma once
// The records of the builtin stage kinds (kinds/*.cpp), listed by StageKinds.cpp.
#include "voxc/stages/StageKind.h"

namespace voxc::stages {

extern const StageKind kStartStage;
extern const StageKind kGrammarStage;
extern const StageKind kFieldStage;
extern const StageKind kCurvesStage;
extern const StageKind kSpeleothemStage;

} // namespace voxc::stages
