// `tetglow farm` without a cluster: the batch scripts and sbatch commands it would submit
// (--dry-run), the values it refuses before writing anything, and how it quotes the rest for
// the two parsers that read a script (sbatch's #SBATCH lines, bash). tests/slurm/farm_test.sh
// runs it through a real Slurm.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "cli/FarmChecks.h"
#include "cli/FarmScripts.h"

namespace tetglow::test {
namespace {

const std::string kSphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Farm, DryRunPrintsTheJobsItWouldSubmit) {
    const std::string dir = tempDir(), work = dir + "/s.farm";
    const auto r = runTetglow(
        "farm " + kSphere + " --parts 3 --spp 10 --seed 2 --cpus-per-task 2 --partition gpu,cpu --account proj-1" +
        " --time 1-02:00:00 --mem 8G --sbatch-arg=--qos=high --sbatch-arg=--comment='a \"b\" c' -o " + dir +
        "/s.exr --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& expected : std::vector<std::string>{
             "--tetrahedralize-only", "#SBATCH --array=0-2", "ranges=( 0:3 3:6 6:10 )", "#SBATCH --cpus-per-task=\"2\"",
             "--threads 2 --frame", "#SBATCH --partition=\"gpu,cpu\"", "#SBATCH --account=\"proj-1\"",
             "#SBATCH --time=\"1-02:00:00\"", "#SBATCH --mem=\"8G\"", "#SBATCH \"--qos=high\"",
             "#SBATCH \"--comment=a \\\"b\\\" c\"", "'--spp' '10' '--seed' '2'", " merge ", "s.farm/merge.status",
             // The commands, with the dependencies farm gives them.
             "prepare=$(sbatch --parsable '" + work + "/prepare.sh')",
             "render=$(sbatch --parsable --dependency=afterok:$prepare --kill-on-invalid-dep=yes '" + work +
                 "/render.sh')",
             "\nsbatch --parsable --dependency=afterany:$prepare:$render '" + work + "/merge.sh'\n"})
        EXPECT_TRUE(contains(r.out, expected)) << expected << "\n" << r.out;
    EXPECT_EQ(r.out.find("#SBATCH --cpus-per-task=\"2\""),
              r.out.find("#SBATCH --cpus-per-task=\"2\"", r.out.find("# " + work + "/render.sh")))
        << "only the array's tasks take --cpus-per-task";
    EXPECT_FALSE(std::filesystem::exists(work)) << "a dry run writes nothing";
}

// Adaptive sampling splits: every task renders to the same target (each replays the pilot that
// plans the tiles, render/AdaptiveSampling.h), so the parts merge into the single render.
TEST(Farm, HandsTheNoiseTargetToEveryTask) {
    const auto r =
        runTetglow("farm " + kSphere + " --parts 3 --spp 64 --noise 0.004 -o " + tempDir() + "/s.exr --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "'--noise' '0.004'")) << r.out;
    EXPECT_TRUE(contains(r.out, "ranges=( 0:21 21:42 42:64 )")) << r.out;
}

TEST(Farm, HelpSaysWhatEachTaskGets) {
    const auto r = runTetglow("farm --help");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* expected :
         {"--cpus-per-task", "its render threads (default 1)", "--account", "--mem", "--sbatch-arg", "sbatch --time"})
        EXPECT_TRUE(contains(r.out, expected)) << expected << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "all cores")) << r.out;
}

TEST(Farm, TakesTheOutputFromTheScene) {
    std::string scene = readFile(kSphere);
    scene.insert(scene.find('{') + 1, "\"output\": \"renders/ball.exr\", ");
    const std::string path = writeTemp("farm-output/scene.json", scene);
    const auto r = runTetglow("farm " + path + " --parts 2 --spp 2 --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string work = std::filesystem::path(path).parent_path().string() + "/renders/ball.farm";
    EXPECT_TRUE(contains(r.out, " -o '" + work.substr(0, work.size() - 5) + ".exr'")) << r.out;
    EXPECT_TRUE(contains(r.out, "'" + work + "/part-0000-001.exr'")) << r.out;
}

// Without -o and without the scene's "output", the image goes where render puts it: SCENE.exr
// in the working folder.
TEST(Farm, DefaultsTheOutputAsRenderDoes) {
    const auto r = runTetglow("farm " + kSphere + " --parts 2 --spp 2 --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string output = (std::filesystem::current_path() / "sphere.exr").string();
    EXPECT_TRUE(contains(r.out, " -o '" + output + "'")) << r.out;
    EXPECT_TRUE(contains(r.out, "'" + output.substr(0, output.size() - 4) + ".farm/part-0000-001.exr'")) << r.out;
}

TEST(Farm, RefusesWhatCannotBeSplit) {
    const std::string dir = tempDir();
    std::string timed = readFile(kSphere);
    timed.replace(timed.find("\"spp\": 64"), 9, "\"spp\": 64, \"time\": 3");
    const std::string timedScene = writeTemp("farm-timed.json", timed);
    struct Case {
        std::string args, message;
        int code;
    };
    const std::vector<Case> cases = {
        {kSphere + " --parts 5 --spp 4 -o " + dir + "/a.exr", "--parts 5 is more than the 4 passes", 1},
        {timedScene + " --parts 2 -o " + dir + "/a.exr", "renders for a time (\"time\"), which cannot be split", 1},
        {kSphere + " --parts 2 -o " + dir + "/a.png", "the output must be an .exr file", 1},
        {kSphere + " --parts 2 --frames 0:2 -o " + dir + "/a.exr",
         "--frames: expected A:B with 0 <= A < B <= 1 (the scene's frames)", 2},
        {kSphere + " -o " + dir + "/a.exr", "--parts is required", 2},
    };
    for (const Case& c : cases) expectOneLineError(runTetglow("farm " + c.args + " --dry-run"), c.code, c.message);
}

// A value that would put a line of its own into a script (a command bash runs, or an #SBATCH
// option) is refused with one line, before any file is written.
TEST(Farm, RefusesValuesThatWouldBreakOutOfTheirLine) {
    using tetglow::cli::shellQuote;
    const std::string dir = tempDir();
    const std::string out = " -o " + dir + "/a.exr", command = "touch " + dir + "/pwned";
    struct Case {
        std::string args, message;
        int code;
    };
    const std::vector<Case> cases = {
        {"--partition " + shellQuote("test\n" + command) + out, "--partition: expected names of letters, digits", 2},
        {"--partition 'a b'" + out, "--partition: expected names", 2},
        {"--account " + shellQuote("x\n#SBATCH --wrap=id") + out, "--account: expected a name of letters", 2},
        {"--time 1h" + out, "--time: expected a Slurm time limit", 2},
        {"--time " + shellQuote("10\nid") + out, "--time: expected a Slurm time limit", 2},
        {"--mem lots" + out, "--mem: expected memory per node", 2},
        {"--sbatch-arg=-pgpu" + out, "expected one long option of sbatch's", 2},
        {"--sbatch-arg=" + shellQuote("--comment=a\nid") + out,
         "expected one long option of sbatch's, --NAME or --NAME=VALUE on one line", 2},
        {"--sbatch-arg=--output=/tmp/x" + out, "farm sets --output itself", 2},
        {"--sbatch-arg=--out=/tmp/x" + out, "farm sets --output itself", 2},
        {"--sbatch-arg=--wrap=id" + out, "farm sets --wrap itself", 2},
        {"--sbatch-arg=--time=5" + out, "farm sets --time itself (give farm --time)", 2},
        // A backslash before a quote, a newline and a command: what sbatch's parser would unescape.
        {"-o " + shellQuote(dir + "/x\\'\n" + command + "\n/a.exr"),
         "holds a control character: refusing to write it into a batch script", 1},
        {"-o " + shellQuote(dir + "/back\\slash/a.exr"),
         "holds a backslash, which turns off Slurm's file name patterns", 1},
    };
    for (const Case& c : cases) {
        const auto r = runTetglow("farm " + kSphere + " --parts 2 --spp 2 " + c.args);
        expectOneLineError(r, c.code, c.message);
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 0)
            << c.args << ": nothing may be written";
    }
}

// Quotes, '#', spaces and '%' are fine in a path: each line quotes them for its parser, and
// '%' is doubled where Slurm reads a file name pattern (--output). No path is a printf format.
TEST(Farm, QuotesPathsForBashAndForSbatch) {
    const std::string dir = tempDir() + "/it's \"a\" #1 100%d %20";
    const auto r = runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + tetglow::cli::shellQuote(dir + "/s.exr") +
                              " --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string sbatchDir = tempDir() + "/it's \\\"a\\\" #1 100%%d %%20/s.farm";
    const std::string bashDir = tetglow::cli::shellQuote(dir + "/s.farm");
    for (const std::string& expected : std::vector<std::string>{
             "#SBATCH --output=\"" + sbatchDir + "/task-%a.log\"", "#SBATCH --output=\"" + sbatchDir + "/merge.log\"",
             "printf -v name 'part-%04d-%03d.exr' \"$frame\" \"$part\"\n",
             "--pass-range \"${ranges[part]}\" -o " + bashDir + "/\"$name\"\n"})
        EXPECT_TRUE(contains(r.out, expected)) << expected << "\n" << r.out;
}

TEST(Farm, SbatchQuotingEscapesWhatSbatchUnescapes) {
    using tetglow::cli::sbatchQuote;
    EXPECT_EQ(sbatchQuote("plain"), "\"plain\"");
    EXPECT_EQ(sbatchQuote("a b#c'd"), "\"a b#c'd\"");
    EXPECT_EQ(sbatchQuote("q\"\\"), "\"q\\\"\\\\\"");
    EXPECT_EQ(tetglow::cli::literalOutputPattern("/a/100%/%a"), "/a/100%%/%%a");
}

// sbatch and scontrol as a script that logs each call and answers as told, first on the PATH.
struct FakeSlurm {
    std::string dir = tempDir() + "/fake-slurm", log = dir + "/calls", oldPath = std::getenv("PATH");
    FakeSlurm(const std::string& sbatch, const std::string& scontrol) {
        writeTemp("fake-slurm/sbatch", "#!/bin/sh\necho \"sbatch $*\" >> '" + log + "'\n" + sbatch + "\n");
        writeTemp("fake-slurm/scontrol", "#!/bin/sh\n" + scontrol + "\n");
        writeTemp("fake-slurm/scancel", "#!/bin/sh\necho \"scancel $*\" >> '" + log + "'\n");
        for (const char* tool : {"/sbatch", "/scontrol", "/scancel"})
            std::filesystem::permissions(dir + tool, std::filesystem::perms::owner_all);
        ::setenv("PATH", (dir + ":" + oldPath).c_str(), 1);
    }
    ~FakeSlurm() { ::setenv("PATH", oldPath.c_str(), 1); }
    std::string calls() const { return readFile(log); }
};

// An array over the cluster's limit used to fail only at the array's sbatch, after the tet cache
// job was submitted (and that job still ran), with a message that did not name the limit.
TEST(Farm, ArrayOverTheLimitIsRefusedBeforeAnythingIsSubmitted) {
    const std::string dir = tempDir();
    {
        const FakeSlurm slurm("echo 17", "exit 1");
        const auto r = runTetglow("farm " + kSphere + " --parts 1002 --spp 2000 -o " + dir + "/a.exr");
        expectOneLineError(r, 1,
                           "farm: 1002 tasks (1 frame(s) x 1002 parts) are more than the 1001 a job array may have "
                           "(Slurm's default MaxArraySize): give fewer --parts or --frames, or --max-array N");
        EXPECT_EQ(slurm.calls(), "") << "nothing may be submitted";
        expectOneLineError(runTetglow("farm " + kSphere + " --parts 1002 --spp 2000 --dry-run -o " + dir + "/a.exr"), 1,
                           "are more than the 1001 a job array may have");
        const auto raised =
            runTetglow("farm " + kSphere + " --parts 1002 --spp 2000 --max-array 2000 --dry-run -o " + dir + "/a.exr");
        EXPECT_EQ(raised.exitCode, 0) << raised.err;
        EXPECT_TRUE(contains(raised.out, "#SBATCH --array=0-1001\n")) << raised.out;
        expectOneLineError(
            runTetglow("farm " + kSphere + " --parts 4 --spp 8 --max-array 3 --dry-run -o " + dir + "/a.exr"), 1,
            "4 tasks (1 frame(s) x 4 parts) are more than the 3 a job array may have (--max-array): give fewer");
    }
    // The cluster's own limit, as scontrol reports it.
    const FakeSlurm slurm("echo 17", "echo 'MaxArraySize            = 3'");
    expectOneLineError(runTetglow("farm " + kSphere + " --parts 4 --spp 8 --dry-run -o " + dir + "/a.exr"), 1,
                       "more than the 3 a job array may have (the cluster's MaxArraySize, from scontrol show config)");
    EXPECT_EQ(runTetglow("farm " + kSphere + " --parts 3 --spp 8 --dry-run -o " + dir + "/a.exr").exitCode, 0);
}

// Frames x parts used to be an int: a turntable's million frames in 100000 parts overflowed it.
TEST(Farm, TaskCountDoesNotOverflow) {
    cli::FarmPlan p;
    p.frames = 1000000;
    p.parts = 100000;
    EXPECT_EQ(p.tasks(), int64_t(100000000000));
}

// On a machine without Slurm, sbatch's own error said nothing of what to do instead.
TEST(Farm, FailedSbatchNamesTheCommandAndSuggestsDryRun) {
    const std::string dir = tempDir();
    const FakeSlurm slurm("echo 'sbatch: fatal: Could not establish a configuration source' >&2; exit 1", "exit 1");
    const auto r = runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + dir + "/a.exr");
    expectOneLineError(r, 1,
                       "farm: sbatch --parsable '" + dir +
                           "/a.farm/prepare.sh' failed: sbatch: fatal: Could not establish a configuration source: "
                           "where Slurm is not set up, --dry-run prints the scripts and the sbatch commands");
}

// A job submitted before a later submission failed is cancelled, not left to run for nothing.
TEST(Farm, JobsSubmittedBeforeAFailedSubmissionAreCancelled) {
    const std::string dir = tempDir();
    const FakeSlurm slurm(
        "case \"$*\" in *render.sh*) echo 'sbatch: error: Batch job submission failed' >&2; exit "
        "1;; esac; echo 41",
        "exit 1");
    expectOneLineError(runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + dir + "/a.exr"), 1,
                       "render.sh' failed: sbatch: error: Batch job submission failed");
    EXPECT_TRUE(contains(slurm.calls(), "scancel 41\n")) << slurm.calls();
}

// Every real site needs `module load` or environment lines before the job's commands: they
// come after the #SBATCH lines (sbatch stops reading those at the first command) in every
// script, as written.
TEST(Farm, PreambleAndSetupLinesRunFirstInEveryJob) {
    const std::string dir = tempDir();
    const std::string preamble = writeTemp("site.sh", "module purge\nexport OMP_PROC_BIND='close'");
    const auto r = runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + dir + "/a.exr --preamble " + preamble +
                              " --setup 'module load gcc/12' --setup 'export NOTE=\"a b\"$HOME' --dry-run");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string lines =
        "module purge\nexport OMP_PROC_BIND='close'\nmodule load gcc/12\nexport NOTE=\"a b\"$HOME\n";
    size_t scripts = 0;
    for (size_t at = r.out.find("#!/bin/bash\n"); at != std::string::npos; at = r.out.find("#!/bin/bash\n", at + 1)) {
        ++scripts;
        const size_t mine = r.out.find(lines, at);
        ASSERT_NE(mine, std::string::npos) << r.out.substr(at);
        const size_t lastSbatch = r.out.rfind("\n#SBATCH ", mine);
        EXPECT_GT(lastSbatch, at);
        EXPECT_EQ(r.out.find('\n', lastSbatch + 1) + 1, mine) << "right after the #SBATCH lines:\n" << r.out.substr(at);
    }
    EXPECT_EQ(scripts, 3u) << r.out;
    expectOneLineError(runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + dir + "/a.exr --setup " +
                                  cli::shellQuote("module load x\nid") + " --dry-run"),
                       1, "the --setup line 'module load x\\nid' holds a control character");
    const std::string carriage = writeTemp("crlf.sh", "module load a\r\n");
    expectOneLineError(
        runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o " + dir + "/a.exr --preamble " + carriage + " --dry-run"),
        1, carriage + ": line 1 holds a control character other than a tab");
}

// The cache job fills the tet cache for every task: when it cannot, it fails, instead of
// reporting success and leaving every task to tetrahedralize again.
TEST(Farm, CacheJobFailsWhenTheCacheCannotBeWritten) {
    // runTetglow's cache folder, taken by a file.
    const std::string cache = processScratchDir() + "/cache";
    std::filesystem::remove_all(cache);
    std::filesystem::create_directories(std::filesystem::path(cache).parent_path());
    std::ofstream(cache) << "not a folder";
    const auto r = runTetglow("render " + kSphere + " --tetrahedralize-only");
    std::filesystem::remove(cache);
    expectOneLineError(r, 1, "render --tetrahedralize-only: medium ");
    EXPECT_TRUE(contains(r.err, ": cannot fill the tet cache: ")) << r.err;
}

// Output, parts and cache where other nodes cannot see them: a warning, and the run goes on.
TEST(Farm, WarnsAboutFoldersLocalToEachNode) {
    const auto tmp = runTetglow("farm " + kSphere + " --parts 2 --spp 2 -o /tmp/farm-warning-test/a.exr --dry-run");
    ASSERT_EQ(tmp.exitCode, 0) << tmp.err;
    for (const char* expected :
         {"farm: warning: the output /tmp/farm-warning-test/a.exr lies in /tmp", "which is local to each node",
          "farm: warning: the parts' folder /tmp/farm-warning-test/a.farm lies in /tmp",
          "farm: warning: the tet cache "})
        EXPECT_TRUE(contains(tmp.err, expected)) << expected << "\n" << tmp.err;
}

// Which file system a path is on comes from the mount table, given here as a cluster's would be,
// so that the answer does not depend on where this checkout lies.
TEST(Farm, LocalFoldersAreTmpAndMemoryFileSystems) {
    const std::string table =
        "overlay / overlay rw 0 0\n"
        "server:/home /cluster/home nfs4 rw 0 0\n"
        "tmpfs /cluster/home/scratch tmpfs rw 0 0\n"
        "tmpfs /run tmpfs rw 0 0\n";
    const auto warning = [&](const std::string& path) {
        std::istringstream mounts(table);
        return tetglow::cli::localPathWarning("the output", path, mounts);
    };
    EXPECT_EQ(warning("/cluster/home/ada/no-such-folder/a.exr"), "");
    EXPECT_EQ(warning("/no-such-folder/a.exr"), "");
    EXPECT_EQ(warning("/tmp/no-such-folder/a.exr"),
              "farm: warning: the output /tmp/no-such-folder/a.exr lies in /tmp, which is local to each node: "
              "tasks on other nodes will not see it");
    // The deepest mount point holding the path decides.
    EXPECT_TRUE(
        contains(warning("/cluster/home/scratch/no-such-folder/a.exr"), "lies on tmpfs /cluster/home/scratch,"));
    EXPECT_EQ(warning("/cluster/home/scratchpad/a.exr"), "");
}

}  // namespace
}  // namespace tetglow::test
