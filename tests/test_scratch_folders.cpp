// The suite cleans up after itself: ctest runs each test in a process of its own, and folders
// named by process once piled up in /tmp by the thousand.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;

TEST(ScratchFolders, ATestWritesItsFolders) {
    const std::string file = writeTemp("note.txt", "kept until the test ends");
    EXPECT_EQ(readFile(file), "kept until the test ends");
    EXPECT_EQ(runTetglow("--help").exitCode, 0);
    EXPECT_TRUE(fs::is_directory(processScratchDir()));
}

TEST(ScratchFolders, APassingTestLeavesNothingBehind) {
    const pid_t child = fork();
    ASSERT_NE(child, -1);
    if (child == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execl("/proc/self/exe", "tetglow_tests", "--gtest_filter=ScratchFolders.ATestWritesItsFolders",
              static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the child test failed";
    const fs::path tmp = fs::temp_directory_path();
    const std::string pid = std::to_string(child);
    EXPECT_FALSE(fs::exists(tmp / ("tetglow-test-" + pid + "-ScratchFolders.ATestWritesItsFolders")));
    EXPECT_FALSE(fs::exists(tmp / ("tetglow-run-" + pid)));
}

}  // namespace
}  // namespace tetglow::test
