// `tetglow farm` without a cluster: the batch scripts it would submit (--dry-run) and the
// options it refuses. tests/slurm/farm_test.sh runs it through a real Slurm.
#include <filesystem>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

const std::string kSphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

TEST(Farm, DryRunPrintsTheJobsItWouldSubmit) {
    const std::string dir = tempDir();
    const auto r = runTetglow("farm " + kSphere + " --parts 3 --spp 10 --seed 2 --threads 2 --partition gpu -o " + dir + "/s.exr --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* expected : {"--tetrahedralize-only", "#SBATCH --array=0-2", "ranges=( 0:3 3:6 6:10 )", "#SBATCH --cpus-per-task=2",
                                 "--threads 2 --frame", "#SBATCH --partition=gpu", "'--spp' '10' '--seed' '2'", " merge ", "s.farm/merge.status"})
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/s.farm")) << "a dry run writes nothing";
}

TEST(Farm, RefusesWhatCannotBeSplit) {
    const std::string dir = tempDir();
    struct Case {
        std::string args, message;
        int code;
    };
    const std::vector<Case> cases = {
        {"--parts 5 --spp 4 -o " + dir + "/a.exr", "--parts 5 is more than the 4 passes", 1},
        {"--parts 2 --time 3 -o " + dir + "/a.exr", "--time cannot be split", 1},
        {"--parts 2 -o " + dir + "/a.png", "the output must be an .exr file", 1},
        {"--parts 2 --frames 0:2 -o " + dir + "/a.exr", "--frames: expected A:B with 0 <= A < B <= 1 (the scene's frames)", 2},
        {"-o " + dir + "/a.exr", "--parts is required", 2},
    };
    for (const Case& c : cases) {
        const auto r = runTetglow("farm " + kSphere + " " + c.args + " --dry-run");
        EXPECT_EQ(r.exitCode, c.code) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace tetglow::test
