// writePackage replaces the package directory as a whole: stale kernels disappear, a failed
// write leaves the old package, concurrent writers leave one whole package, equal bytes touch
// nothing, and a directory voxc did not write is refused.
#include "SamplePrograms.h"
#include "PackageTree.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/core/Errors.h"
#include "voxc/core/TempFiles.h"

#include <atomic>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <optional>
#include <sstream>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace voxc::codegen {
namespace package_directory_test {

namespace fs = std::filesystem;
using Tree = test::PackageTree;

class codegen_PackageDirectory : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("voxc_pkgdir_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }

    // Everything under root_ except the package directory `pkg` itself and its contents.
    std::vector<std::string> siblingsOf(const std::string& pkg) const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(root_))
            if (entry.path().filename() != pkg) names.push_back(entry.path().filename().string());
        return names;
    }

    fs::path root_;
};

// The sample program's package, and a smaller one (one grammar, fewer kernels) as "another version".
const KernelPackage& samplePackage() {
    static const KernelPackage package = compileProgram(test::sampleProgram());
    return package;
}
const KernelPackage& smallerPackage() {
    static const KernelPackage package = [] {
        Program program = test::sampleProgram();
        program.grammars.pop_back();
        program.pipeline.pop_back();
        return compileProgram(program);
    }();
    return package;
}
const PackageSource kSource{"sample.vox", "text"};

using test::readTree;

// The package the directory held when it was opened, read through that handle; nullopt when it
// was swapped out while being read (its writer then deletes it, so a reader starts again).
std::optional<Tree> readSnapshot(const fs::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return std::nullopt;
    const fs::path handle = "/proc/self/fd/" + std::to_string(fd);
    std::optional<Tree> files = Tree{};
    try {
        for (const auto& entry : fs::recursive_directory_iterator(handle)) {
            if (!entry.is_regular_file()) continue;
            std::ifstream in(entry.path(), std::ios::binary);
            std::ostringstream bytes;
            bytes << in.rdbuf();
            if (!in) files.reset();
            if (!files) break;
            (*files)[fs::relative(entry.path(), handle).string()] = bytes.str();
        }
    } catch (const fs::filesystem_error&) {
        files.reset();
    }
    struct stat opened {}, now {};
    if (::fstat(fd, &opened) != 0 || ::stat(dir.c_str(), &now) != 0 || opened.st_ino != now.st_ino) files.reset();
    ::close(fd);
    return files;
}

void writeText(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

TEST_F(codegen_PackageDirectory, ReplacingRemovesStaleKernels) {
    const fs::path pkg = root_ / "pkg";
    EXPECT_EQ(writePackage(samplePackage(), pkg.string(), kSource), PackageWrite::Created);
    ASSERT_TRUE(fs::exists(pkg / "kernels/smooth_sweep0.spv"));
    const fs::perms groupOnly = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec;
    fs::permissions(pkg, groupOnly);
    EXPECT_EQ(writePackage(smallerPackage(), pkg.string(), kSource), PackageWrite::Replaced);
    EXPECT_EQ(readTree(pkg), packageFiles(smallerPackage(), kSource));
    EXPECT_FALSE(fs::exists(pkg / "kernels/smooth_sweep0.spv"));
    EXPECT_TRUE(siblingsOf("pkg").empty()); // the old package and the temp directory are gone
    EXPECT_EQ(cleanupEntriesInUse(), 0);
    EXPECT_EQ(fs::status(pkg).permissions(), groupOnly); // the directory's permissions are kept
}

TEST_F(codegen_PackageDirectory, EqualBytesLeaveTheDirectoryUntouched) {
    const fs::path pkg = root_ / "pkg";
    writePackage(samplePackage(), pkg.string(), kSource);
    std::map<std::string, std::pair<ino_t, int64_t>> before;
    const auto snapshot = [&] {
        std::map<std::string, std::pair<ino_t, int64_t>> stats;
        for (const fs::path& path : {pkg, pkg / "kernels"})
            for (const auto& entry : fs::directory_iterator(path)) {
                struct stat st {};
                EXPECT_EQ(::stat(entry.path().c_str(), &st), 0);
                stats[entry.path().string()] = {st.st_ino, int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
            }
        struct stat st {};
        EXPECT_EQ(::stat(pkg.c_str(), &st), 0);
        stats["."] = {st.st_ino, int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
        return stats;
    };
    before = snapshot();
    EXPECT_EQ(writePackage(samplePackage(), pkg.string(), kSource), PackageWrite::Unchanged);
    EXPECT_EQ(snapshot(), before);
    // Another source hash is another manifest: the package is replaced.
    EXPECT_EQ(writePackage(samplePackage(), pkg.string(), {"sample.vox", "edited text"}), PackageWrite::Replaced);
}

TEST_F(codegen_PackageDirectory, HowTheDirectoryIsSpelledDoesNotMatter) {
    const fs::path previous = fs::current_path();
    fs::current_path(root_);
    EXPECT_EQ(writePackage(samplePackage(), "pkg", kSource), PackageWrite::Created);
    EXPECT_EQ(writePackage(samplePackage(), "./pkg/", kSource), PackageWrite::Unchanged);
    EXPECT_EQ(writePackage(samplePackage(), (root_ / "pkg").string(), kSource), PackageWrite::Unchanged);
    EXPECT_EQ(writePackage(samplePackage(), "pkg/../pkg//", kSource), PackageWrite::Unchanged);
    fs::current_path(previous);
    EXPECT_EQ(readTree(root_ / "pkg").at("manifest.json").find(root_.string()), std::string::npos);
}

TEST_F(codegen_PackageDirectory, AnEmptyDirectoryIsReplaced) {
    fs::create_directories(root_ / "pkg");
    EXPECT_EQ(writePackage(samplePackage(), (root_ / "pkg").string(), kSource), PackageWrite::Replaced);
    EXPECT_EQ(readTree(root_ / "pkg"), packageFiles(samplePackage(), kSource));
}

TEST_F(codegen_PackageDirectory, DirectoriesVoxcDidNotWriteAreRefused) {
    const std::vector<std::pair<std::string, std::string>> foreign = {
        {"notes/readme.txt", "my notes"},                      // no manifest at all
        {"notes2/manifest.json", "{\"name\": \"my app\"}"},    // someone else's manifest
        {"notes3/kernels/shader.glsl", "void main() {}"},      // a file voxc never writes
    };
    for (const auto& [file, text] : foreign) {
        const fs::path path = root_ / file;
        writeText(path, text);
        const fs::path dir = root_ / fs::path(file).begin()->string();
        EXPECT_THROW(writePackage(samplePackage(), dir.string(), kSource), UserError) << file;
        std::ifstream in(path);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), text) << file;
    }
    // A voxc package with a user's file added to it is not replaced either.
    const fs::path pkg = root_ / "pkg";
    writePackage(samplePackage(), pkg.string(), kSource);
    writeText(pkg / "kernels/mine.txt", "keep me");
    try {
        writePackage(smallerPackage(), pkg.string(), kSource);
        FAIL() << "expected a UserError";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("kernels/mine.txt"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::exists(pkg / "kernels/mine.txt"));
    // A file where the directory should be.
    writeText(root_ / "file", "x");
    EXPECT_THROW(writePackage(samplePackage(), (root_ / "file").string(), kSource), UserError);
}

// A full disk, simulated with a file size limit: writing the new package fails part way, and
// the old package stays as it was, with no temp directory left beside it.
TEST_F(codegen_PackageDirectory, AFailedWriteLeavesTheOldPackage) {
    const fs::path pkg = root_ / "pkg";
    writePackage(smallerPackage(), pkg.string(), kSource);
    const Tree before = readTree(pkg);

    struct rlimit saved {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN); // write() then fails with EFBIG
    struct rlimit small = saved;
    small.rlim_cur = 4096; // below the size of the sweep kernels' SPIR-V
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string message;
    try {
        writePackage(samplePackage(), pkg.string(), kSource);
    } catch (const UserError& e) {
        message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);

    EXPECT_NE(message.find("cannot write package"), std::string::npos) << message;
    EXPECT_EQ(readTree(pkg), before);
    EXPECT_TRUE(siblingsOf("pkg").empty());
}

// Ctrl-C in the middle of writing the new package (raised from the file size limit's signal, so
// it lands inside a write, not at a chosen line) removes the temp directory; the old package stays.
TEST_F(codegen_PackageDirectory, SigintDuringTheWriteRemovesTheTempDirectory) {
    const fs::path pkg = root_ / "pkg";
    writePackage(smallerPackage(), pkg.string(), kSource);
    const Tree before = readTree(pkg);
    EXPECT_EXIT(
        {
            installTempFileCleanup();
            std::signal(SIGXFSZ, [](int) { ::raise(SIGINT); });
            struct rlimit small {};
            ::getrlimit(RLIMIT_FSIZE, &small);
            small.rlim_cur = 4096;
            ::setrlimit(RLIMIT_FSIZE, &small);
            writePackage(samplePackage(), pkg.string(), kSource);
            std::exit(0);
        },
        testing::KilledBySignal(SIGINT), "");
    EXPECT_EQ(readTree(pkg), before);
    EXPECT_TRUE(siblingsOf("pkg").empty());
}

// Writers replace the package concurrently while a reader checks that every manifest it sees
// comes with exactly its own kernels; at the end one whole package is there.
TEST_F(codegen_PackageDirectory, ConcurrentWritersLeaveOneWholePackage) {
    const fs::path pkg = root_ / "pkg";
    writePackage(samplePackage(), pkg.string(), kSource);
    const Tree a = packageFiles(samplePackage(), kSource), b = packageFiles(smallerPackage(), kSource);
    std::vector<std::thread> writers;
    for (int w = 0; w < 4; ++w)
        writers.emplace_back([&, w] {
            for (int round = 0; round < 6; ++round)
                writePackage(w % 2 ? smallerPackage() : samplePackage(), pkg.string(), kSource);
        });
    int mixed = 0, seen = 0; // complete reads; those that are neither package
    std::atomic<bool> done{false};
    std::thread reader([&] {
        while (!done) {
            const std::optional<Tree> tree = readSnapshot(pkg);
            if (!tree) continue;
            ++seen;
            mixed += *tree != a && *tree != b;
        }
    });
    for (std::thread& writer : writers) writer.join();
    done = true;
    reader.join();
    EXPECT_EQ(mixed, 0) << "of " << seen << " complete reads";
    const Tree final = readTree(pkg);
    EXPECT_TRUE(final == a || final == b);
    EXPECT_TRUE(siblingsOf("pkg").empty());
}

// A compile killed mid-write (SIGKILL, power loss) leaves its temp directory; the next compile
// into the same directory removes it, and leaves those of live processes and other files alone.
TEST_F(codegen_PackageDirectory, TempDirectoriesOfDeadProcessesAreRemoved) {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    ::waitpid(child, nullptr, 0); // `child` is now a pid of no process
    const std::string dead = ".pkg.voxc-tmp." + std::to_string(child) + ".0000abcd";
    const std::string live = ".pkg.voxc-tmp." + std::to_string(::getppid()) + ".0000abcd";
    writeText(root_ / dead / "kernels/start.comp", "partial");
    writeText(root_ / live / "manifest.json", "{}");
    writeText(root_ / ".pkg.voxc-tmp.notes", "a user's file");
    writePackage(samplePackage(), (root_ / "pkg").string(), kSource);
    EXPECT_FALSE(fs::exists(root_ / dead));
    EXPECT_TRUE(fs::exists(root_ / live / "manifest.json"));
    EXPECT_TRUE(fs::exists(root_ / ".pkg.voxc-tmp.notes"));
}

} // namespace package_directory_test
} // namespace voxc::codegen
