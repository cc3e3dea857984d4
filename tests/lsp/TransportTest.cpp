// The LSP framing's edge cases: what an editor sends, and what a broken or hostile client sends.
#include "voxc/lsp/Transport.h"

#include <gtest/gtest.h>
#include <sstream>

namespace {

using voxc::lsp::ReadResult;
using voxc::lsp::readMessage;

using Kind = ReadResult::Kind;

TEST(lsp_Transport, ReadsMessagesBackToBack) {
    std::istringstream in("Content-Length: 2\r\n\r\n{}Content-Type: x\r\ncontent-length:  3 \r\n\r\n[1]");
    const ReadResult first = readMessage(in);
    ASSERT_EQ(first.kind, Kind::Message);
    EXPECT_EQ(first.body, "{}");
    const ReadResult second = readMessage(in); // other headers ignored, the name's case too
    ASSERT_EQ(second.kind, Kind::Message);
    EXPECT_EQ(second.body, "[1]");
    EXPECT_EQ(readMessage(in).kind, Kind::End);
}

TEST(lsp_Transport, AcceptsBareNewlinesAndBlankLinesBetweenMessages) {
    std::istringstream in("\r\n\nContent-Length: 1\n\nx");
    const ReadResult read = readMessage(in);
    ASSERT_EQ(read.kind, Kind::Message);
    EXPECT_EQ(read.body, "x");
}

TEST(lsp_Transport, MalformedHeadersAreSkippedAndReadingGoesOn) {
    const std::string next = "Content-Length: 2\r\n\r\nok";
    for (const std::string& bad : {std::string("Content-Length: 12x\r\n\r\n"), std::string("no colon here\r\n\r\n"),
                                  std::string("X-Other: 1\r\n\r\n"),
                                  "X-Long: " + std::string(5000, 'a') + "\r\nContent-Length: 3\r\n\r\nabc"}) {
        std::istringstream in(bad + next);
        const ReadResult read = readMessage(in);
        EXPECT_EQ(read.kind, Kind::Malformed) << bad.substr(0, 40);
        EXPECT_FALSE(read.error.empty());
        const ReadResult after = readMessage(in);
        ASSERT_EQ(after.kind, Kind::Message) << bad.substr(0, 40);
        EXPECT_EQ(after.body, "ok");
    }
}

TEST(lsp_Transport, TooManyHeaderLinesIsMalformed) {
    std::string headers;
    for (int i = 0; i < 40; ++i) headers += "X-" + std::to_string(i) + ": 1\r\n";
    std::istringstream in(headers + "Content-Length: 1\r\n\r\nz");
    const ReadResult read = readMessage(in);
    EXPECT_EQ(read.kind, Kind::Malformed);
    EXPECT_NE(read.error.find("header lines"), std::string::npos);
}

TEST(lsp_Transport, OversizedBodyIsReadPastAndRefused) {
    const size_t size = voxc::lsp::kMaxContentLength + 1;
    std::istringstream in("Content-Length: " + std::to_string(size) + "\r\n\r\n" + std::string(size, ' ') +
                          "Content-Length: 2\r\n\r\nok");
    const ReadResult read = readMessage(in);
    EXPECT_EQ(read.kind, Kind::Malformed);
    EXPECT_NE(read.error.find("32 MiB"), std::string::npos);
    const ReadResult after = readMessage(in);
    ASSERT_EQ(after.kind, Kind::Message);
    EXPECT_EQ(after.body, "ok");
}

TEST(lsp_Transport, StreamEndingInsideAMessageEnds) {
    for (const char* cut : {"Content-Length: 10\r\n\r\nabc", "Content-Length: 10\r\n", "Content-Len"}) {
        std::istringstream in(cut);
        EXPECT_EQ(readMessage(in).kind, Kind::End) << cut;
    }
}

TEST(lsp_Transport, WritesTheLengthInBytes) {
    std::ostringstream out;
    voxc::lsp::writeMessage(out, "{\"a\":\"\xc3\xa9\"}");
    EXPECT_EQ(out.str(), "Content-Length: 10\r\n\r\n{\"a\":\"\xc3\xa9\"}");
}

} // namespace
