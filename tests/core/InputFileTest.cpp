// readInputFile reads only regular files, never past its cap and never blocking on what a path
// names; readCommandLineFile also reads a pipe or device, up to one byte past the cap.
#include "FileHelpers.h"
#include "voxc/core/InputFile.h"

#include <sys/stat.h>
#include <unistd.h>

namespace voxc {
namespace {

TEST(InputFile, ReadsARegularFileUpToTheCap) {
    const std::string dir = test::freshDir("input_regular");
    test::putFile(dir + "a.rules", "0123456789");
    InputFileRead atCap = readInputFile(dir + "a.rules", 10);
    ASSERT_TRUE(atCap.bytes) << atCap.message;
    EXPECT_EQ(*atCap.bytes, "0123456789");
    EXPECT_EQ(atCap.problem, InputFileProblem::None);

    InputFileRead pastCap = readInputFile(dir + "a.rules", 9);
    EXPECT_FALSE(pastCap.bytes);
    EXPECT_EQ(pastCap.problem, InputFileProblem::TooLarge);
    EXPECT_EQ(pastCap.code(), "E0012");
    EXPECT_NE(pastCap.message.find("larger than the limit of 9 bytes"), std::string::npos) << pastCap.message;
}

TEST(InputFile, RefusesWhatIsNotARegularFileWithoutReading) {
    const std::string dir = test::freshDir("input_kinds");
    const std::string fifo = dir + "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // No writer: a blocking open would wait forever; the test would hang instead of failing.
    InputFileRead fromFifo = readInputFile(fifo, 100);
    EXPECT_EQ(fromFifo.problem, InputFileProblem::NotRegular);
    EXPECT_EQ(fromFifo.code(), "E0100");
    EXPECT_EQ(fromFifo.message, "cannot read file '" + fifo + "': it is a FIFO (named pipe), not a regular file");

    EXPECT_EQ(readInputFile("/dev/zero", 100).problem, InputFileProblem::NotRegular);
    EXPECT_EQ(readInputFile(dir, 100).problem, InputFileProblem::NotRegular);
    EXPECT_EQ(readInputFile(dir + "none", 100).problem, InputFileProblem::Missing);
    EXPECT_EQ(readInputFile(dir + "none/deeper", 100).problem, InputFileProblem::Missing);
}

TEST(InputFile, RefusesTheProcessStandardInputWhenItIsAPipe) {
    int ends[2];
    ASSERT_EQ(::pipe(ends), 0);
    const int savedStdin = ::dup(0);
    ASSERT_EQ(::dup2(ends[0], 0), 0);
    InputFileRead fromStdin = readInputFile("/dev/stdin", 100);
    ::dup2(savedStdin, 0);
    ::close(savedStdin);
    ::close(ends[0]);
    ::close(ends[1]);
    EXPECT_EQ(fromStdin.problem, InputFileProblem::NotRegular);
    EXPECT_NE(fromStdin.message.find("FIFO"), std::string::npos) << fromStdin.message;
}

TEST(InputFile, CommandLineFilesMayBeStreamsButAreCapped) {
    InputFileRead zero = readCommandLineFile("/dev/zero", 1000);
    EXPECT_EQ(zero.problem, InputFileProblem::TooLarge);
    InputFileRead empty = readCommandLineFile("/dev/null", 1000);
    ASSERT_TRUE(empty.bytes) << empty.message;
    EXPECT_TRUE(empty.bytes->empty());
    EXPECT_EQ(readCommandLineFile(testing::TempDir(), 1000).problem, InputFileProblem::NotRegular);
}

} // namespace
} // namespace voxc
