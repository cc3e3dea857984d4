#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <gtest/gtest.h>

namespace voxc {
namespace {

TEST(syntax_Diagnostics, RendersTheBriefsForm) {
    SourceFile source("examples/bad.vox", std::string(11, '\n') + "    symbol {\n");
    Diagnostic d{Severity::Error, "E0004", {12, 5, 6}, "symbol has 2 rows but size [3, 3, 1] declares 3", {}};
    EXPECT_EQ(render(d, source), "examples/bad.vox:12:5: error E0004: symbol has 2 rows but size [3, 3, 1] declares 3\n"
                                 "   12 |     symbol {\n"
                                 "      |     ^~~~~~\n");
}

TEST(syntax_Diagnostics, RendersNotesWarningsAndFileLevelDiagnostics) {
    SourceFile source("a.vox", "rule a\nrule b\n");
    Diagnostic d{Severity::Warning, "W0203", {2, 6, 1}, "overlap", {{{1, 6, 1}, "first here"}, {{}, "unlocated"}}};
    EXPECT_EQ(render(d, source), "a.vox:2:6: warning W0203: overlap\n"
                                 "    2 | rule b\n"
                                 "      |      ^\n"
                                 "a.vox:1:6: note: first here\n"
                                 "    1 | rule a\n"
                                 "      |      ^\n"
                                 "a.vox: note: unlocated\n");
    EXPECT_EQ(render({Severity::Error, "E0100", {}, "cannot read", {}, nullptr}, source), "a.vox: error E0100: cannot read\n");
}

TEST(syntax_Diagnostics, ImportedFileDiagnosticsRenderAgainstTheirFileAndComeLast) {
    SourceFile checked("a.vox", "lsystem net {\n  rules = \"r.rules\";\n}\n");
    auto rules = std::make_shared<const SourceFile>("r.rules", "C;FXZ;tunnel;1\n");
    Diagnostics diagnostics;
    diagnostics.report({Severity::Error, "E0002", {1, 4, 1}, "unknown symbol 'X'", {}, rules});
    diagnostics.error("E0007", {2, 11, 9}, "in the checked file");
    // The same message and place in another file is not a duplicate.
    diagnostics.error("E0002", {1, 4, 1}, "unknown symbol 'X'");
    std::vector<Diagnostic> taken = diagnostics.take();
    ASSERT_EQ(taken.size(), 3u);
    EXPECT_FALSE(taken[0].file);
    EXPECT_FALSE(taken[1].file);
    EXPECT_EQ(renderAll({taken[2]}, checked), "r.rules:1:4: error E0002: unknown symbol 'X'\n"
                                              "    1 | C;FXZ;tunnel;1\n"
                                              "      |    ^\n");
}

TEST(syntax_Diagnostics, CaretClipsToTheLineAndKeepsTabsAndUtf8Aligned) {
    SourceFile source("t.vox", "\tx = \xC3\xA9\xC3\xA9 y\r\n");
    // Column 6 is 'y' counted in characters: tab, x, space, =, space, é, é, space, y -> 'y' is column 9.
    Diagnostic d{Severity::Error, "E0001", {1, 9, 40}, "m", {}};
    EXPECT_EQ(render(d, source), "t.vox:1:9: error E0001: m\n"
                                 "    1 | \tx = \xC3\xA9\xC3\xA9 y\n"
                                 "      | \t       ^\n");
}

// A long line is shown as 160 characters around the caret (60 before it), marked with "...".
TEST(syntax_Diagnostics, LongLinesShowAWindowAroundTheCaret) {
    std::string line;
    for (int i = 0; i < 1000; ++i) line += char('a' + i % 26);
    SourceFile source("t.vox", line + "\n");
    Diagnostic d{Severity::Error, "E0001", {1, 501, 1000}, "m", {}};
    EXPECT_EQ(render(d, source), "t.vox:1:501: error E0001: m\n"
                                 "    1 | ..." + line.substr(440, 160) + "...\n"
                                 "      | " + std::string(63, ' ') + "^" + std::string(99, '~') + "\n");
    // Near the start nothing is cut before; near the end nothing after.
    d.loc = {1, 3, 1};
    EXPECT_EQ(render(d, source), "t.vox:1:3: error E0001: m\n    1 | " + line.substr(0, 160) + "...\n      |   ^\n");
    d.loc = {1, 1000, 1};
    EXPECT_EQ(render(d, source), "t.vox:1:1000: error E0001: m\n    1 | ..." + line.substr(840) + "\n      | " +
                                     std::string(3 + 159, ' ') + "^\n");
}

TEST(syntax_Diagnostics, DeduplicatesIdenticalDiagnostics) {
    Diagnostics diagnostics;
    diagnostics.error("E0002", {1, 1, 1}, "unknown");
    diagnostics.error("E0002", {1, 1, 1}, "unknown");
    diagnostics.error("E0002", {1, 2, 1}, "unknown");
    diagnostics.warning("E0002", {1, 1, 1}, "unknown");
    EXPECT_EQ(diagnostics.all().size(), 3u);
    EXPECT_EQ(diagnostics.errorCount(), 2);
}

TEST(syntax_Diagnostics, CapsErrorsButKeepsWarnings) {
    Diagnostics diagnostics;
    for (uint32_t i = 1; i <= 30; ++i) diagnostics.error("E0001", {i, 1, 1}, "bad");
    diagnostics.warning("W0201", {31, 1, 1}, "still reported");
    const auto& all = diagnostics.all();
    ASSERT_EQ(all.size(), size_t(Diagnostics::kMaxErrors) + 2);
    EXPECT_EQ(all[Diagnostics::kMaxErrors].code, "");
    EXPECT_EQ(all[Diagnostics::kMaxErrors].message, "too many errors; stopping after the first 20");
    EXPECT_EQ(all.back().code, "W0201");
    EXPECT_TRUE(diagnostics.hasErrors());
}

} // namespace
} // namespace voxc
