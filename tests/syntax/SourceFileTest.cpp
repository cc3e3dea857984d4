#include "voxc/syntax/SourceFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace voxc {
namespace {

TEST(syntax_SourceFile, LinesWithoutTerminators) {
    SourceFile source("t.vox", "one\r\ntwo\n\nfour");
    EXPECT_EQ(source.lineCount(), 4u);
    EXPECT_EQ(source.line(1), "one");
    EXPECT_EQ(source.line(2), "two");
    EXPECT_EQ(source.line(3), "");
    EXPECT_EQ(source.line(4), "four");
    EXPECT_EQ(source.line(5), "");
    EXPECT_EQ(source.line(0), "");
}

TEST(syntax_SourceFile, LoadReportsMissingFilesAndDirectories) {
    Diagnostics diagnostics;
    EXPECT_FALSE(loadSourceFile("/no/such/file.vox", diagnostics));
    EXPECT_FALSE(loadSourceFile(testing::TempDir(), diagnostics));
    ASSERT_EQ(diagnostics.all().size(), 2u);
    EXPECT_EQ(diagnostics.all()[0].code, "E0100");
    EXPECT_EQ(diagnostics.all()[1].code, "E0100");
    EXPECT_NE(diagnostics.all()[1].message.find("directory"), std::string::npos);
}

TEST(syntax_SourceFile, LoadsText) {
    const std::string path = testing::TempDir() + "voxc_source_test.vox";
    std::ofstream(path, std::ios::binary) << "world { }\n";
    Diagnostics diagnostics;
    auto source = loadSourceFile(path, diagnostics);
    ASSERT_TRUE(source);
    EXPECT_EQ(source->text(), "world { }\n");
    EXPECT_EQ(source->path(), path);
    EXPECT_FALSE(reportIfNotText(*source, diagnostics));
    EXPECT_TRUE(diagnostics.all().empty());
    std::filesystem::remove(path);
}

TEST(syntax_SourceFile, BinaryContentIsNotText) {
    auto codeFor = [](const std::string& text) {
        Diagnostics diagnostics;
        reportIfNotText(SourceFile("t", text), diagnostics);
        return diagnostics.all().empty() ? std::string() : diagnostics.all()[0].code;
    };
    EXPECT_EQ(codeFor(std::string("ab\0cd", 5)), "E0101");
    EXPECT_EQ(codeFor("\xFF\xFE"), "E0101");          // not UTF-8
    EXPECT_EQ(codeFor("\xC0\xAF"), "E0101");          // overlong '/'
    EXPECT_EQ(codeFor("\xED\xA0\x80"), "E0101");      // surrogate
    EXPECT_EQ(codeFor("\xE2\x82"), "E0101");          // truncated
    EXPECT_EQ(codeFor("caf\xC3\xA9 \xF0\x9F\x98\x80"), ""); // é and an emoji
    EXPECT_EQ(codeFor(""), "");
}

} // namespace
} // namespace voxc
