// `voxc view --script`: every action parses; malformed lines are located errors with stable codes.
#include "voxc/viewer/Script.h"

#include <gtest/gtest.h>

namespace voxc::viewer {
namespace {

std::vector<Action> parse(const std::string& text, Diagnostics& diagnostics) {
    return parseScript(SourceFile("actions.txt", text), diagnostics);
}

TEST(ScriptTest, ParsesEveryAction) {
    Diagnostics diagnostics;
    const std::vector<Action> actions = parse("# a comment\n"
                                              "camera 1,2,3:4,5,6\n"
                                              "  carve 10 20.5   # at a pixel\n"
                                              "add-ray 1,2,3 0,-1,0\n"
                                              "set cliffs.face.constraint[1].amplitude 4\n"
                                              "undo\nredo\nreload\nsave-edits out.json\nwait 0.5\nwait-change 30\n"
                                              "screenshot out.png\nwait-refined 60\n",
                                              diagnostics);
    ASSERT_FALSE(diagnostics.hasErrors());
    ASSERT_EQ(actions.size(), 12u);
    EXPECT_EQ(actions[0].kind, Action::Kind::Camera);
    EXPECT_EQ(actions[0].text, "1,2,3:4,5,6");
    EXPECT_EQ(actions[1].kind, Action::Kind::Carve);
    EXPECT_FALSE(actions[1].alongRay);
    EXPECT_EQ(actions[1].pixel, glm::vec2(10.0f, 20.5f));
    EXPECT_EQ(actions[1].loc.line, 3u);
    EXPECT_EQ(actions[1].loc.column, 3u);
    EXPECT_EQ(actions[2].kind, Action::Kind::Add);
    EXPECT_TRUE(actions[2].alongRay);
    EXPECT_EQ(actions[2].direction, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(actions[3].text, "cliffs.face.constraint[1].amplitude");
    EXPECT_EQ(actions[3].value, 4.0);
    EXPECT_EQ(actions[9].kind, Action::Kind::WaitChange);
    EXPECT_EQ(actions[10].text, "out.png");
    EXPECT_EQ(actions[11].kind, Action::Kind::WaitRefined);
    EXPECT_EQ(actions[11].value, 60.0);
}

TEST(ScriptTest, MalformedLinesAreLocatedErrors) {
    Diagnostics diagnostics;
    parse("zoom 2\ncarve 1\ncarve x 2\nadd-ray 1,2 0,0,1\nwait -1\nwait-refined 4000\n", diagnostics);
    const std::vector<Diagnostic>& all = diagnostics.all();
    ASSERT_EQ(all.size(), 6u);
    EXPECT_EQ(all[0].code, "E0008");
    EXPECT_EQ(all[0].loc.line, 1u);
    EXPECT_EQ(all[1].code, "E0006");
    EXPECT_EQ(all[2].code, "E0010");
    EXPECT_EQ(all[2].loc.column, 7u);
    EXPECT_EQ(all[3].code, "E0010");
    EXPECT_EQ(all[4].code, "E0007");
    EXPECT_EQ(all[5].code, "E0007");
    EXPECT_EQ(all[5].loc.line, 6u);
}

} // namespace
} // namespace voxc::viewer
