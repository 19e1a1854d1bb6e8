// What a command leaves on disk when it fails or is stopped: the old outputs as they were when
// the disk fills between the EXR and the PNG, no temporary when a signal comes in the middle of
// a write, the image kept on SIGTERM as on Ctrl-C, and an unwritable folder found before the
// render. Some cases need root to mount a small tmpfs; they skip, saying so, without it.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "render/ImageIO.h"

extern char** environ;

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;
const std::string kSphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

// A tmpfs mounted on `dir` while it lives (mounted() false where this process may not mount).
class Tmpfs {
public:
    Tmpfs(const std::string& dir, const std::string& options) : dir_(dir) {
        fs::create_directories(dir);
        mounted_ = std::system(("mount -t tmpfs -o " + options + " tmpfs " + dir + " 2>/dev/null").c_str()) == 0;
    }
    ~Tmpfs() {
        if (mounted_) std::system(("umount " + dir_).c_str());
    }
    bool mounted() const { return mounted_; }

private:
    std::string dir_;
    bool mounted_ = false;
};

std::vector<std::string> temporaries(const std::string& dir) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".tmp") found.push_back(entry.path().string());
    return found;
}

size_t pages(const std::string& path) { return (fs::file_size(path) + 4095) / 4096; }

TEST(OutputFaults, DiskFullAfterTheExrLeavesBothOldOutputs) {
    const std::string dir = tempDir(), disk = dir + "/disk";
    // The old outputs are small, so the disk fills in the new PNG even where the old EXR's room
    // is given back before the PNG is written. Noise makes the new PNG span several pages.
    const std::string common = "render " + kSphere + " --spp 1 --max-depth 3";
    ASSERT_EQ(runTetglow(common + " --resolution 8x8 --seed 1 -o " + dir + "/old.exr").exitCode, 0);
    ASSERT_EQ(runTetglow(common + " --resolution 160x160 --seed 2 -o " + dir + "/new.exr").exitCode, 0);
    ASSERT_GT(pages(dir + "/new.png"), 4u) << "the PNG must span pages for the disk to fill in its middle";
    // Room for the old outputs, the new EXR and half the new PNG.
    const size_t room =
        pages(dir + "/old.exr") + pages(dir + "/old.png") + pages(dir + "/new.exr") + pages(dir + "/new.png") / 2;
    const Tmpfs tmpfs(disk, "size=" + std::to_string(room * 4096));
    if (!tmpfs.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
    fs::copy_file(dir + "/old.exr", disk + "/out.exr");
    fs::copy_file(dir + "/old.png", disk + "/out.png");
    const auto r = runTetglow(common + " --resolution 160x160 --seed 2 -o " + disk + "/out.exr");
    expectOneLineError(r, 1, disk + "/out.png: cannot write: ");
    EXPECT_TRUE(readFile(disk + "/out.exr") == readFile(dir + "/old.exr"))
        << "the new EXR replaced the old one although the command failed";
    EXPECT_TRUE(readFile(disk + "/out.png") == readFile(dir + "/old.png")) << "the PNG was replaced";
    EXPECT_EQ(temporaries(disk), std::vector<std::string>());
}

// convert writes a scene's meshes and its JSON all or none: when the disk fills at the second
// mesh, the first is as it was (it was written, and renamed over the old one, before the second).
TEST(OutputFaults, DiskFullAtTheSecondMeshOfAConvertLeavesEveryOldFile) {
    const std::string dir = tempDir(), disk = dir + "/disk";
    const auto scene = [&](const std::string& name, double radius, int subdivisions) {
        return writeTemp(name, R"({"camera": {"position": [0, 0, 9], "look_at": [0, 0, 0]},
          "lights": [{"type": "environment", "radiance": 1}],
          "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": )" +
                                   std::to_string(radius) + R"(, "subdivisions": 0}, "sigma_s": 1},
                    {"shape": {"type": "sphere", "center": [3, 0, 0], "radius": 1, "subdivisions": )" +
                                   std::to_string(subdivisions) + R"(}, "sigma_s": 1}]})");
    };
    const std::string oldScene = scene("old.json", 1, 0), newScene = scene("new.json", 0.5, 4);
    ASSERT_EQ(runTetglow("convert " + oldScene + " -o " + dir + "/old/out.json").exitCode, 0);
    ASSERT_EQ(runTetglow("convert " + newScene + " -o " + dir + "/new/out.json").exitCode, 0);
    ASSERT_GT(pages(dir + "/new/out-medium-1.obj"), 4u) << "the second mesh must span pages for the disk to fill";
    // Room for the old files and the new first mesh, not for the new second one.
    size_t room = pages(dir + "/new/out-medium-0.obj") + 1;
    for (const char* file : {"out.json", "out-medium-0.obj", "out-medium-1.obj"}) room += pages(dir + "/old/" + file);
    const Tmpfs tmpfs(disk, "size=" + std::to_string(room * 4096));
    if (!tmpfs.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
    for (const char* file : {"out.json", "out-medium-0.obj", "out-medium-1.obj"})
        fs::copy_file(dir + "/old/" + file, disk + "/" + file);
    const auto r = runTetglow("convert " + newScene + " -o " + disk + "/out.json");
    expectOneLineError(r, 1, disk + "/out-medium-1.obj: cannot write: ");
    for (const char* file : {"out.json", "out-medium-0.obj", "out-medium-1.obj"})
        EXPECT_TRUE(readFile(disk + "/" + file) == readFile(dir + "/old/" + file)) << file << " was replaced";
    EXPECT_EQ(temporaries(disk), std::vector<std::string>());
}

// Starts `tetglow args...` (the binary runTetglow runs), stderr to `log`; its pid.
pid_t start(const std::vector<std::string>& args, const std::string& log) {
    std::vector<std::string> argv = {std::getenv("TETGLOW_TEST_BINARY") ? std::getenv("TETGLOW_TEST_BINARY")
                                                                        : TETGLOW_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (auto& a : argv) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, pointers[0], &actions, nullptr, pointers.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    return pid;
}

// The exit code as a shell reports it (128 + the signal for a process killed by one).
int finish(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(OutputFaults, CtrlCWhileTheExrIsWrittenKeepsTheImageAndNoTemporary) {
    const std::string dir = tempDir(), out = dir + "/big.exr";
    ::setenv("TETGLOW_CACHE_DIR", (dir + "/cache").c_str(), 1);
    // A large image at one sample: the EXR takes long enough to write that the signal lands in it.
    const pid_t pid = start(
        {"render", kSphere, "--resolution", "2048x2048", "--spp", "1", "--max-depth", "1", "-o", out}, dir + "/log");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (temporaries(dir).empty() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    ASSERT_FALSE(temporaries(dir).empty()) << "no temporary appeared: " << readFile(dir + "/log");
    ::kill(pid, SIGINT);
    EXPECT_EQ(finish(pid), 130) << readFile(dir + "/log");
    EXPECT_EQ(temporaries(dir), std::vector<std::string>());
    EXPECT_EQ(readExr(out).width, 2048) << "the image is written whole";
    EXPECT_TRUE(fs::exists(dir + "/big.png"));
    EXPECT_NE(readFile(dir + "/log").find("interrupted (SIGINT)"), std::string::npos) << readFile(dir + "/log");
}

// scancel and Slurm's time limit send SIGTERM: the render so far is kept, as on Ctrl-C.
TEST(OutputFaults, SigtermKeepsTheRenderLikeCtrlC) {
    const std::string dir = tempDir(), out = dir + "/partial.exr";
    ::setenv("TETGLOW_CACHE_DIR", (dir + "/cache").c_str(), 1);
    const pid_t pid = start({"render", kSphere, "--spp", "100000", "--resolution", "64x64", "-o", out}, dir + "/log");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (readFile(dir + "/log").find("render: ") == std::string::npos && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ::kill(pid, SIGTERM);
    EXPECT_EQ(finish(pid), 143) << readFile(dir + "/log");
    EXPECT_NE(readFile(dir + "/log").find("interrupted (SIGTERM): wrote"), std::string::npos) << readFile(dir + "/log");
    EXPECT_EQ(readExr(out).width, 64);
    EXPECT_TRUE(fs::exists(dir + "/partial.png"));
}

TEST(OutputFaults, UnwritableFolderIsAnErrorBeforeTheRender) {
    const std::string dir = tempDir(), locked = dir + "/locked";
    fs::create_directories(locked);
    // As root a folder's mode does not stop a write; a read-only mount does.
    const bool root = ::geteuid() == 0;
    const Tmpfs tmpfs(locked, "ro,size=64k");
    if (root && !tmpfs.mounted()) GTEST_SKIP() << "cannot mount a read-only tmpfs here";
    if (!root) fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    const auto r = runTetglow("render " + kSphere + " --resolution 32x32 --spp 64 -o " + locked + "/out.exr", 120);
    expectOneLineError(r, 1, locked + "/out.exr: cannot write in the folder " + locked + ": ");
    EXPECT_EQ(r.err.find("render: "), std::string::npos) << "the render started: " << r.err;
    if (!root) fs::permissions(locked, fs::perms::owner_all);
}

}  // namespace
}  // namespace tetglow::test
