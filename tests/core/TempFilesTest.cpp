// The signal handler, exercised in forked children (gtest death tests) that raise the signal
// themselves at a chosen point, so no test depends on timing. Only the children install it.
#include "FileHelpers.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/TempFiles.h"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace voxc {
namespace {

namespace fs = std::filesystem;

using test::freshDir;
using test::putFile;
using test::readFile;

size_t entriesIn(const std::string& dir) {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

class core_TempFilesDeathTest : public testing::TestWithParam<int> {};

// The signal arrives halfway through writing a replacement: the temp file goes, the user's file
// stays as it was, and the process dies of that very signal.
TEST_P(core_TempFilesDeathTest, signalDuringAWriteRemovesTheTempFile) {
    const int signal = GetParam();
    const std::string dir = freshDir("during_write_" + std::to_string(signal));
    putFile(dir + "out.ply", "the user's mesh");
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            writeFileAtomically(dir + "out.ply", [&](std::ostream& out) {
                out << std::string(1 << 20, 'x');
                out.flush();
                ::raise(signal);
            });
        },
        testing::KilledBySignal(signal), "");
    EXPECT_EQ(readFile(dir + "out.ply"), "the user's mesh");
    EXPECT_EQ(entriesIn(dir), 1u);
}

INSTANTIATE_TEST_SUITE_P(eachSignal, core_TempFilesDeathTest, testing::Values(SIGINT, SIGTERM, SIGHUP));

// What a commit of several files leaves registered while it renames: a backup that the handler
// puts back over the replaced file.
TEST(core_TempFilesDeathTest, restoreEntryPutsTheBackupBack) {
    const std::string dir = freshDir("restore");
    putFile(dir + "mesh.mtl", "new library");
    putFile(dir + "mesh.mtl.backup", "the user's library");
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            CleanupEntry backup(dir + "mesh.mtl.backup");
            backup.restoreOnSignal(dir + "mesh.mtl");
            ::raise(SIGTERM);
        },
        testing::KilledBySignal(SIGTERM), "");
    EXPECT_EQ(readFile(dir + "mesh.mtl"), "the user's library");
    EXPECT_EQ(entriesIn(dir), 1u);
}

// Before its file is renamed, a backup is a second link to the unchanged file: putting it back
// must keep the file and drop the extra link.
TEST(core_TempFilesDeathTest, restoreEntryOfAnUnreplacedFileKeepsIt) {
    const std::string dir = freshDir("restore_same");
    putFile(dir + "mesh.mtl", "the user's library");
    fs::create_hard_link(dir + "mesh.mtl", dir + "mesh.mtl.backup");
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            CleanupEntry backup(dir + "mesh.mtl.backup");
            backup.restoreOnSignal(dir + "mesh.mtl");
            ::raise(SIGINT);
        },
        testing::KilledBySignal(SIGINT), "");
    EXPECT_EQ(readFile(dir + "mesh.mtl"), "the user's library");
    EXPECT_EQ(entriesIn(dir), 1u);
}

// A registered name that was never activated (the file may belong to someone else) is left alone.
TEST(core_TempFilesDeathTest, inactiveEntryIsLeftAlone) {
    const std::string dir = freshDir("inactive");
    putFile(dir + "someone_elses.tmp", "not voxc's");
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            CleanupEntry entry(dir + "someone_elses.tmp");
            ::raise(SIGINT);
        },
        testing::KilledBySignal(SIGINT), "");
    EXPECT_EQ(readFile(dir + "someone_elses.tmp"), "not voxc's");
}

// A temp directory (a package being built) goes with everything in it, however many files; the
// directory beside it stays.
TEST(core_TempFilesDeathTest, treeEntryRemovesTheDirectoryAndItsFiles) {
    const std::string dir = freshDir("tree");
    fs::create_directories(dir + "pkg.tmp/kernels/deeper");
    for (int i = 0; i < 300; ++i) putFile(dir + "pkg.tmp/kernels/k" + std::to_string(i) + ".spv", "spirv");
    putFile(dir + "pkg.tmp/manifest.json", "{}");
    putFile(dir + "pkg.tmp/kernels/deeper/x", "x");
    fs::create_directories(dir + "pkg");
    putFile(dir + "pkg/manifest.json", "the old package");
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            CleanupEntry entry(dir + "pkg.tmp");
            entry.removeTreeOnSignal();
            ::raise(SIGTERM);
        },
        testing::KilledBySignal(SIGTERM), "");
    EXPECT_FALSE(fs::exists(dir + "pkg.tmp"));
    EXPECT_EQ(readFile(dir + "pkg/manifest.json"), "the old package");
    EXPECT_EQ(entriesIn(dir), 1u);
}

// `nohup voxc ...`: a signal ignored at start stays ignored, so the process lives on.
TEST(core_TempFilesDeathTest, ignoredSignalStaysIgnored) {
    EXPECT_EXIT(
        {
            std::signal(SIGHUP, SIG_IGN);
            installTempFileCleanup();
            ::raise(SIGHUP);
            std::exit(7);
        },
        testing::ExitedWithCode(7), "");
}

TEST(core_TempFiles, entriesAreReleased) {
    const int before = cleanupEntriesInUse();
    {
        CleanupEntry first(testing::TempDir() + "a");
        CleanupEntry second(testing::TempDir() + "b");
        second.removeOnSignal();
        EXPECT_EQ(cleanupEntriesInUse(), before + 2);
        CleanupEntry moved = std::move(first);
        EXPECT_EQ(cleanupEntriesInUse(), before + 2);
    }
    EXPECT_EQ(cleanupEntriesInUse(), before);
}

} // namespace
} // namespace voxc
