#include "FileHelpers.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/stat.h>
#include <thread>

namespace voxc {
namespace {

namespace fs = std::filesystem;

using test::freshDir;
using test::putFile;
using test::readFile;

// The names in `dir`, sorted: after any write, only the outputs may be there, never a temp file.
std::vector<std::string> namesIn(const std::string& dir) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

using Names = std::vector<std::string>;

TEST(core_AtomicWrite, writesAndReplacesLeavingNoTempFile) {
    const std::string dir = freshDir("replace");
    writeFileAtomically(dir + "out.txt", "first");
    EXPECT_EQ(readFile(dir + "out.txt"), "first");
    writeFileAtomically(dir + "out.txt", [](std::ostream& out) { out << "second, " << 2; });
    EXPECT_EQ(readFile(dir + "out.txt"), "second, 2");
    EXPECT_EQ(namesIn(dir), Names{"out.txt"});
    EXPECT_EQ(cleanupEntriesInUse(), 0);
}

TEST(core_AtomicWrite, bigWriteArrivesWhole) {
    const std::string dir = freshDir("big");
    std::string bytes(3 << 20, '\0'); // bigger than the stream buffer, written in odd pieces
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 7 + i / 251);
    writeFileAtomically(dir + "big.bin", [&](std::ostream& out) {
        for (size_t at = 0; at < bytes.size(); at += 1000003)
            out.write(bytes.data() + at, std::streamsize(std::min<size_t>(1000003, bytes.size() - at)));
    });
    EXPECT_EQ(readFile(dir + "big.bin"), bytes);
}

TEST(core_AtomicWrite, failedWriteKeepsThePreviousFile) {
    const std::string dir = freshDir("failed");
    putFile(dir + "out.txt", "the user's");
    EXPECT_THROW(writeFileAtomically(dir + "out.txt",
                                     [](std::ostream& out) {
                                         out << "half";
                                         throw UserError("stopped halfway");
                                     }),
                 UserError);
    EXPECT_THROW(writeFileAtomically(dir + "out.txt", [](std::ostream& out) { out.setstate(std::ios::badbit); }),
                 UserError);
    EXPECT_EQ(readFile(dir + "out.txt"), "the user's");
    EXPECT_EQ(namesIn(dir), Names{"out.txt"});
    EXPECT_EQ(cleanupEntriesInUse(), 0);
}

TEST(core_AtomicWrite, unwritablePathsAreUserErrors) {
    const std::string dir = freshDir("unwritable");
    try {
        writeFileAtomically(dir + "no-such-dir/out.txt", "x");
        FAIL() << "no error";
    } catch (const UserError& error) {
        EXPECT_NE(std::string(error.what()).find("cannot write '" + dir + "no-such-dir/out.txt'"), std::string::npos);
    }
    fs::create_directory(dir + "taken");
    EXPECT_THROW(writeFileAtomically(dir + "taken", "x"), UserError);
    // A link to a device is not replaced by a file (nor is the device, whatever voxc's rights).
    fs::create_symlink("/dev/null", dir + "null.ply");
    EXPECT_THROW(writeFileAtomically(dir + "null.ply", "x"), UserError);
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    EXPECT_EQ(namesIn(dir), (Names{"null.ply", "taken"}));
}

TEST(core_OutputFiles, nothingChangesBeforeCommit) {
    const std::string dir = freshDir("before_commit");
    putFile(dir + "a.txt", "old a");
    {
        OutputFiles files;
        files.add(dir + "a.txt", "new a");
        files.add(dir + "b.txt", "new b");
        EXPECT_EQ(readFile(dir + "a.txt"), "old a");
        EXPECT_FALSE(fs::exists(dir + "b.txt"));
    } // never committed: the temp files go
    EXPECT_EQ(namesIn(dir), Names{"a.txt"});
    EXPECT_EQ(readFile(dir + "a.txt"), "old a");
    EXPECT_EQ(cleanupEntriesInUse(), 0);
}

TEST(core_OutputFiles, commitWritesEveryFile) {
    const std::string dir = freshDir("commit");
    putFile(dir + "a.txt", "old a");
    OutputFiles files;
    files.add(dir + "a.txt", "new a");
    files.add(dir + "b.txt", "new b");
    files.commit();
    EXPECT_EQ(readFile(dir + "a.txt"), "new a");
    EXPECT_EQ(readFile(dir + "b.txt"), "new b");
    EXPECT_EQ(namesIn(dir), (Names{"a.txt", "b.txt"})); // no backup left behind
    EXPECT_EQ(cleanupEntriesInUse(), 0);
}

// The OBJ + .mtl case: the second file of a set cannot be written, so the first is not touched.
TEST(core_OutputFiles, failedAddLeavesTheOtherFilesAlone) {
    const std::string dir = freshDir("failed_add");
    putFile(dir + "m.mtl", "the user's library");
    fs::create_directory(dir + "m.obj");
    OutputFiles files;
    files.add(dir + "m.mtl", "new library");
    EXPECT_THROW(files.add(dir + "m.obj", "new mesh"), UserError);
    EXPECT_EQ(readFile(dir + "m.mtl"), "the user's library");
}

// A rename that fails in the middle of a commit: the files renamed before it get their previous
// contents back, and a file the set created is removed.
TEST(core_OutputFiles, failedRenameRollsBackTheSet) {
    const std::string dir = freshDir("rollback");
    putFile(dir + "a.txt", "old a");
    putFile(dir + "c.txt", "old c");
    OutputFiles files;
    files.add(dir + "a.txt", "new a");
    files.add(dir + "new.txt", "created");
    files.add(dir + "c.txt", "new c");
    // Between writing and committing, c.txt becomes a non-empty directory, which rename cannot replace.
    fs::remove(dir + "c.txt");
    fs::create_directories(dir + "c.txt/inside");
    EXPECT_THROW(files.commit(), UserError);
    EXPECT_EQ(readFile(dir + "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(dir + "new.txt"));
    EXPECT_EQ(namesIn(dir), (Names{"a.txt", "c.txt"}));
    EXPECT_EQ(cleanupEntriesInUse(), 0);
}

TEST(core_AtomicWrite, symlinkIsWrittenThrough) {
    const std::string dir = freshDir("symlink");
    fs::create_directory(dir + "real");
    putFile(dir + "real/target.txt", "old");
    fs::create_symlink("real/target.txt", dir + "link.txt");
    writeFileAtomically(dir + "link.txt", "new");
    EXPECT_TRUE(fs::is_symlink(dir + "link.txt"));
    EXPECT_EQ(readFile(dir + "real/target.txt"), "new");
    EXPECT_EQ(namesIn(dir + "real"), Names{"target.txt"});
}

TEST(core_AtomicWrite, replacedFileKeepsItsPermissions) {
    const std::string dir = freshDir("permissions");
    putFile(dir + "private.txt", "old");
    fs::permissions(dir + "private.txt", fs::perms::owner_read | fs::perms::owner_write);
    writeFileAtomically(dir + "private.txt", "new");
    EXPECT_EQ(fs::status(dir + "private.txt").permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
}

// Threads writing one path at once never share a temp file: every write succeeds and the file
// ends as one writer's whole contents.
TEST(core_AtomicWrite, concurrentWritersNeverCollide) {
    const std::string dir = freshDir("concurrent");
    constexpr int kThreads = 8, kWrites = 25;
    std::vector<std::thread> threads;
    std::atomic<int> failures{0};
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            const std::string contents(4096 + size_t(t), char('a' + t));
            for (int i = 0; i < kWrites; ++i) {
                try {
                    writeFileAtomically(dir + "shared.txt", contents);
                } catch (const std::exception&) {
                    ++failures;
                }
            }
        });
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(failures.load(), 0);
    const std::string result = readFile(dir + "shared.txt");
    ASSERT_GE(result.size(), 4096u);
    EXPECT_EQ(result, std::string(result.size(), result[0]));
    EXPECT_EQ(result.size(), 4096u + size_t(result[0] - 'a'));
    EXPECT_EQ(namesIn(dir), Names{"shared.txt"});
}

} // namespace
} // namespace voxc
