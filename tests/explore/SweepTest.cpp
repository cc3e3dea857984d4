// --range A:B:STEP: inclusive, no drift, validated.
#include "voxc/core/Errors.h"
#include "voxc/explore/Sweep.h"

#include <gtest/gtest.h>

using namespace voxc;
using namespace voxc::explore;

TEST(Sweep, InclusiveIntegerRange) {
    EXPECT_EQ(sweepValues(parseSweepRange("1:5:2")), (std::vector<double>{1, 3, 5}));
    EXPECT_EQ(sweepValues(parseSweepRange("1:6:2")), (std::vector<double>{1, 3, 5}));
    EXPECT_EQ(sweepValues(parseSweepRange("4:4:1")), (std::vector<double>{4}));
    EXPECT_EQ(sweepValues(parseSweepRange("-2:0:1")), (std::vector<double>{-2, -1, 0}));
}

TEST(Sweep, FloatStepsLandOnTheWrittenDecimals) {
    // 0.3 + 2 * 0.2 and 0.1 * 3 are not exact in binary; the values are the decimals as written.
    EXPECT_EQ(sweepValues(parseSweepRange("0.3:0.7:0.2")), (std::vector<double>{0.3, 0.5, 0.7}));
    const std::vector<double> tenths = sweepValues(parseSweepRange("0:1:0.1"));
    ASSERT_EQ(tenths.size(), 11u);
    for (size_t i = 0; i < tenths.size(); ++i) EXPECT_EQ(tenths[i], double(i) / 10.0) << i;
    const std::vector<double> many = sweepValues(parseSweepRange("0:19.9:0.1"));
    ASSERT_EQ(many.size(), 200u);
    EXPECT_EQ(many.back(), 19.9);
}

TEST(Sweep, RejectsBadRanges) {
    EXPECT_THROW(parseSweepRange("0:1"), UserError);
    EXPECT_THROW(parseSweepRange("0:1:0.1:2"), UserError);
    EXPECT_THROW(parseSweepRange("a:1:0.1"), UserError);
    EXPECT_THROW(parseSweepRange("0:1:0"), UserError);
    EXPECT_THROW(parseSweepRange("0:1:-0.1"), UserError);
    EXPECT_THROW(parseSweepRange("1:0:0.1"), UserError);
    EXPECT_THROW(sweepValues(parseSweepRange("0:200:1")), UserError); // 201 values
    EXPECT_NO_THROW(sweepValues(parseSweepRange("0:199:1")));
}
