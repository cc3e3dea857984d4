#!/bin/sh
# Regenerates tests/lsystem/rule_cases/*.expected (rendered rule-file diagnostics) from the code.
# Review the diff before committing.
# Usage: scripts/update-lsystem-goldens.sh [build-dir]   (default: build)
set -e
build=${1:-build}
cmake --build "$build" --target voxc_lsystem_tests
VOXC_UPDATE_GOLDENS=1 "$build/tests/lsystem/voxc_lsystem_tests" --gtest_filter='cases/lsystem_RuleFileGolden.*' --gtest_brief=1
