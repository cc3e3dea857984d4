// Ctrl-C while `voxc run` writes a big mesh: the temp file goes and the user's previous mesh stays
// byte for byte; while `voxc compile` makes its package directory, nothing is left. The voxc
// binary runs as a child; inotify reports the temp file's creation and SIGSTOP freezes the child
// there, so the signal provably lands mid-write without any timing.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <gtest/gtest.h>
#include <optional>
#include <poll.h>
#include <spawn.h>
#include <sstream>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> namesIn(const std::string& dir) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Starts voxc with `args`, output to `log`, and the cleanup signals at their default action (a
// test runner may have started us with SIGINT ignored, which voxc would rightly keep).
pid_t spawnVoxc(const std::vector<std::string>& args, const std::string& log) {
    std::vector<char*> argv;
    std::string binary = VOXC_BINARY;
    argv.push_back(binary.data());
    std::vector<std::string> copies = args;
    for (std::string& arg : copies) argv.push_back(arg.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, signal);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, binary.c_str(), &files, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    return error == 0 ? pid : -1;
}

// Waits until a file whose name starts with `prefix` is created in the watched directory, or the
// child exits (std::nullopt, with its wait status in `status`).
std::optional<std::string> awaitCreation(int watch, const std::string& prefix, pid_t child, int& status) {
    alignas(inotify_event) char events[64 * 1024];
    while (true) {
        if (::waitpid(child, &status, WNOHANG) == child) return std::nullopt;
        pollfd ready{watch, POLLIN, 0};
        // The poll interval only bounds how late an exit is noticed; nothing depends on it.
        if (::poll(&ready, 1, 100) <= 0) continue;
        const ssize_t length = ::read(watch, events, sizeof events);
        for (ssize_t at = 0; at < length;) {
            const auto* event = reinterpret_cast<const inotify_event*>(events + at);
            const std::string name = event->len > 0 ? event->name : "";
            if (name.rfind(prefix, 0) == 0) return name;
            at += ssize_t(sizeof(inotify_event) + event->len);
        }
    }
}

// Surface every few voxels: a mesh of tens of MB from a small file.
constexpr const char* kWaves = R"(world { size = [96, 96, 96]; chunk = 32; }
field waves = sin(x * 0.9) * sin(y * 0.9) * sin(z * 0.9) * 0.5 + 0.5;
pipeline { start; set waves; }
)";
// The same with a material, so an OBJ comes with a .mtl: the two are one set.
constexpr const char* kRockWaves = R"(material rock { id = 1; color = [0.4, 0.4, 0.4]; }
world { size = [64, 64, 64]; chunk = 32; }
start { box { min = [0, 0, 0]; max = [64, 64, 64]; material = rock; } }
field waves = sin(x * 0.9) * sin(y * 0.9) * sin(z * 0.9) * 0.5 + 0.5;
pipeline { start; set waves; }
)";

// Runs `voxc run waves.vox -o waves.EXTENSION` in a fresh `dir` holding the user's previous
// `outputs` (name -> contents) and sends SIGINT while the mesh's temp file is being written.
// Expects voxc killed by SIGINT, every previous file byte-identical and nothing else left.
void interruptMeshWrite(const std::string& name, const char* program, const std::string& extension,
                        const std::map<std::string, std::string>& outputs) {
    const std::string dir = testing::TempDir() + "files_" + name + "/";
    const std::string log = testing::TempDir() + "files_" + name + ".log";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "waves.vox") << program;
    const std::string mesh = "waves" + extension;

    // The write is caught mid-way unless the child wrote the whole file between the inotify
    // event and SIGSTOP; then it is run again, a bounded number of times.
    bool interrupted = false;
    for (int attempt = 0; attempt < 5 && !interrupted; ++attempt) {
        for (const auto& [file, contents] : outputs) std::ofstream(dir + file, std::ios::binary | std::ios::trunc) << contents;
        const int watch = inotify_init1(IN_CLOEXEC);
        ASSERT_GE(watch, 0) << std::strerror(errno);
        ASSERT_GE(inotify_add_watch(watch, dir.c_str(), IN_CREATE), 0) << std::strerror(errno);
        const pid_t child = spawnVoxc({"run", dir + "waves.vox", "--device", "lavapipe", "-o", dir + mesh}, log);
        ASSERT_GT(child, 0);
        int status = 0;
        const std::optional<std::string> temp = awaitCreation(watch, mesh + ".tmp-", child, status);
        ::close(watch);
        ASSERT_TRUE(temp) << "voxc exited (status " << status << ") without writing a temp file:\n" << readFile(log);
        ::kill(child, SIGSTOP);
        ASSERT_EQ(::waitpid(child, &status, WUNTRACED), child);
        ASSERT_TRUE(WIFSTOPPED(status)) << "voxc ended before it could be stopped:\n" << readFile(log);
        interrupted = fs::exists(dir + *temp);
        if (interrupted) ::kill(child, SIGINT);
        ::kill(child, SIGCONT);
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        if (!interrupted) continue;
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
            << "wait status " << status << ", want killed by SIGINT:\n" << readFile(log);
    }
    ASSERT_TRUE(interrupted) << "every attempt finished writing before it could be stopped";
    std::vector<std::string> expected{"waves.vox"};
    for (const auto& [file, contents] : outputs) {
        EXPECT_EQ(readFile(dir + file), contents) << file;
        expected.push_back(file);
    }
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(namesIn(dir), expected);
}

TEST(files_Sigint, ctrlCDuringAPlyWriteKeepsThePreviousMesh) {
    interruptMeshWrite("sigint_ply", kWaves, ".ply", {{"waves.ply", "the user's mesh, which must survive"}});
}

// The .mtl temp file is written before the OBJ's, so both are in flight when the signal comes.
TEST(files_Sigint, ctrlCDuringAnObjWriteKeepsThePreviousObjAndMtl) {
    interruptMeshWrite("sigint_obj", kRockWaves, ".obj",
                       {{"waves.obj", "the user's mesh"}, {"waves.mtl", "newmtl the_users_own\n"}});
}

// Ctrl-C as `voxc compile` makes its package's temp directory, stopped at the directory's
// creation event: the signal leaves nothing beside the source (the directory is armed for
// removal before mkdir() makes it). A compile that finished before it could be stopped is run
// again, a bounded number of times.
TEST(files_Sigint, ctrlCAsAPackageDirectoryIsMadeLeavesNothing) {
    const std::string dir = testing::TempDir() + "files_sigint_package/";
    const std::string log = testing::TempDir() + "files_sigint_package.log";
    bool interrupted = false;
    for (int attempt = 0; attempt < 5 && !interrupted; ++attempt) {
        fs::remove_all(dir);
        fs::create_directories(dir);
        std::ofstream(dir + "waves.vox") << kWaves;
        const int watch = inotify_init1(IN_CLOEXEC);
        ASSERT_GE(watch, 0) << std::strerror(errno);
        ASSERT_GE(inotify_add_watch(watch, dir.c_str(), IN_CREATE), 0) << std::strerror(errno);
        const pid_t child = spawnVoxc({"compile", dir + "waves.vox", "-o", dir + "pkg"}, log);
        ASSERT_GT(child, 0);
        int status = 0;
        const std::optional<std::string> temp = awaitCreation(watch, ".pkg.voxc-tmp.", child, status);
        ::close(watch);
        ASSERT_TRUE(temp) << "voxc exited (status " << status << ") without making a temp directory:\n" << readFile(log);
        ::kill(child, SIGSTOP);
        ASSERT_EQ(::waitpid(child, &status, WUNTRACED), child);
        if (!WIFSTOPPED(status)) continue; // the compile ended first
        interrupted = true;
        ::kill(child, SIGINT);
        ::kill(child, SIGCONT);
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
            << "wait status " << status << ", want killed by SIGINT:\n" << readFile(log);
        EXPECT_EQ(namesIn(dir), std::vector<std::string>{"waves.vox"});
    }
    ASSERT_TRUE(interrupted) << "every compile finished before it could be stopped";
}

} // namespace
