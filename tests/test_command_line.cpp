// The command line under hostile use: unknown words are named, bad values are usage errors in
// plain numbers, and every command that writes treats its outputs the same way (an output that
// is a folder or names an input is refused, missing folders are created, a failed write leaves
// nothing behind).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "base/OutputFile.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;

// A box of glowing medium, 4x4 pixels, one sample: renders in a moment.
std::string tinyScene() {
    return R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
               "integrator": {"spp": 1},
               "media": [{"shape": {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}, "sigma_s": 1, "emission": 1}]})";
}

std::string boxObj() {
    return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
           "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 "
           "6\n";
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(CommandLine, UnknownSubcommandIsNamed) {
    const auto r = runTetglow("frobnicate");
    expectOneLineError(r, 2, "unknown subcommand 'frobnicate'");
    EXPECT_NE(r.err.find("render"), std::string::npos) << "lists the subcommands: " << r.err;
    expectOneLineError(runTetglow("generate squid"), 2,
                       "unknown subcommand 'squid' of 'tetglow generate'; one of: fish, fish-photophores, fish-eyes, "
                       "fish-lure-core, cloud");
    expectOneLineError(runTetglow(""), 2, "needs a subcommand: one of");
}

TEST(CommandLine, UnknownOptionIsNamedBeforeOtherChecks) {
    // CLI11 checked the missing scene "x" first and never named --frob.
    expectOneLineError(runTetglow("render --frob x"), 2, "unknown option '--frob'");
    expectOneLineError(runTetglow("tetrahedralize m.obj --max-volum=3"), 2, "unknown option '--max-volum'");
}

TEST(CommandLine, RangeErrorsArePlainNumbers) {
    const std::string scene = writeTemp("scene.json", tinyScene());
    for (const char* arg : {"--step -1", "--seed -5", "--time 1e999", "--radius nan"}) {
        const auto r = runTetglow("render " + scene + " " + arg);
        expectOneLineError(r, 2, std::string(arg) == "--seed -5" ? "expected an integer in 0.." : "expected a finite");
        EXPECT_LT(r.err.size(), 120u) << "no 309-digit numbers: " << r.err;
    }
}

TEST(CommandLine, EmptyValueIsAnErrorNotIgnored) {
    const std::string scene = writeTemp("scene.json", tinyScene());
    for (const char* arg : {"-o ''", "--resolution ''"})
        expectOneLineError(runTetglow("render " + scene + " " + arg), 2, "expected a value, got ''");
    expectOneLineError(runTetglow("generate fish -o ''"), 2, "expected a value, got ''");
}

TEST(CommandLine, ResolutionDoesNotWrap) {
    const std::string scene = writeTemp("scene.json", tinyScene());
    for (const char* size : {"4294967297x8", "8x-4294967295", "8x", "x8", "8x8x"})
        expectOneLineError(runTetglow("render " + scene + " --resolution " + size + " -o " + tempDir() + "/x.exr"), 2,
                           "expected WxH with W and H in 1..16384, got '" + std::string(size) + "'");
    EXPECT_FALSE(fs::exists(tempDir() + "/x.exr"));
}

TEST(CommandLine, NegativeSeedIsRefusedNotWrapped) {
    expectOneLineError(runTetglow("validate slab --photons 2 --seed -1"), 2,
                       "--seed: expected an integer in 0..9223372036854775807, got '-1'");
    const std::string mesh = writeTemp("box.obj", boxObj());
    expectOneLineError(runTetglow("compare-boundary " + mesh + " --points 1 --rays 1 --seed -1"), 2, "got '-1'");
}

// An output that is an input, by another spelling (a symbolic link): refused, the input intact.
TEST(Outputs, OutputThatNamesAnInputIsRefused) {
    const std::string scene = writeTemp("scene.json", tinyScene()), mesh = writeTemp("box.obj", boxObj());
    const std::string dir = tempDir();
    fs::create_symlink(scene, dir + "/scene-link.exr");
    fs::create_symlink(scene, dir + "/scene-link.json");
    fs::create_symlink(mesh, dir + "/box-link.tet");
    const std::string commands[] = {"render " + scene + " -o " + dir + "/scene-link.exr",
                                    "convert " + scene + " -o " + dir + "/scene-link.json",
                                    "tetrahedralize " + mesh + " -o " + dir + "/box-link.tet",
                                    "compare-boundary " + mesh + " --points 1 --rays 1 --csv " + dir + "/./box.obj"};
    for (const auto& command : commands) {
        SCOPED_TRACE(command);
        expectOneLineError(runTetglow(command), 1, "the output is an input");
    }
    EXPECT_EQ(slurp(scene), tinyScene());
    EXPECT_EQ(slurp(mesh), boxObj());
}

// The files a scene pulls in are inputs too: its mesh (under a name render would write to), a
// pbrt Include, and the mesh that convert's own mesh file would replace. All used to be overwritten.
TEST(Outputs, OutputThatNamesAFileTheSceneReadsIsRefused) {
    const std::string dir = tempDir();
    const std::string mesh = writeTemp("out-medium-0.obj", boxObj());
    const std::string scene = writeTemp(
        "mesh.json", R"({"camera": {"position": [0.5, 0.5, 4], "look_at": [0.5, 0.5, 0], "resolution": [4, 4]},
        "integrator": {"spp": 1}, "media": [{"shape": {"type": "mesh", "file": "out-medium-0.obj"}, "sigma_s": 1, "emission": 1}]})");
    const std::string include =
        writeTemp("light.exr", "LightSource \"distant\" \"point from\" [0 0 1] \"point to\" [0 0 0]\n");
    const std::string pbrt =
        writeTemp("inc.pbrt",
                  "LookAt 0 0 4 0 0 0 0 1 0\nCamera \"perspective\"\nFilm \"image\" \"integer xresolution\" [4] "
                  "\"integer yresolution\" [4]\nWorldBegin\nInclude \"light.exr\"\nWorldEnd\n");
    fs::create_symlink(mesh, dir + "/mesh-link.exr");
    const std::string commands[] = {"render " + scene + " -o " + dir + "/mesh-link.exr",
                                    "render " + pbrt + " -o " + include,
                                    "convert " + scene + " -o " + dir + "/out.json"};
    for (const auto& command : commands) {
        SCOPED_TRACE(command);
        expectOneLineError(runTetglow(command), 1, "the output is an input");
    }
    EXPECT_EQ(slurp(mesh), boxObj());
    EXPECT_EQ(slurp(include).rfind("LightSource", 0), 0u);
}

TEST(Outputs, OutputThatIsAFolderIsAnError) {
    const std::string scene = writeTemp("scene.json", tinyScene()), mesh = writeTemp("box.obj", boxObj());
    const std::string dir = tempDir() + "/folder";
    fs::create_directories(dir + "/x.exr");
    fs::create_directories(dir + "/x.json");
    const std::string commands[] = {"render " + scene + " -o " + dir + "/x.exr",
                                    "convert " + scene + " -o " + dir + "/x.json",
                                    "tetrahedralize " + mesh + " -o " + dir, "generate fish -o " + dir,
                                    "compare-boundary " + mesh + " --points 1 --rays 1 --csv " + dir};
    for (const auto& command : commands) {
        SCOPED_TRACE(command);
        const auto r = runTetglow(command);
        expectOneLineError(r, 1, "the output must name a file, not a folder");
        EXPECT_EQ(r.err.find("filesystem error"), std::string::npos) << r.err;
    }
}

// Every command creates the folders its output lies in, and says so clearly when it cannot.
TEST(Outputs, MissingFoldersAreCreatedTheSameWayByEveryCommand) {
    const std::string scene = writeTemp("scene.json", tinyScene()), mesh = writeTemp("box.obj", boxObj());
    const std::string dir = tempDir();
    const std::pair<std::string, std::string> runs[] = {
        {"render " + scene + " -o ", "a/b/x.exr"},
        {"convert " + scene + " -o ", "c/d/x.json"},
        {"tetrahedralize " + mesh + " -o ", "e/f/x.tet"},
        {"tetrahedralize " + mesh + " -o ", "g/h/x.vtk"},
        {"generate fish --rings 8 --segments 8 -o ", "i/j/x.obj"},
        {"compare-boundary " + mesh + " --points 1 --rays 1 --csv ", "k/l/x.csv"},
    };
    writeTemp("plain", "a file, not a folder");
    for (const auto& [command, output] : runs) {
        SCOPED_TRACE(command + output);
        const auto r = runTetglow(command + dir + "/" + output);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::is_regular_file(dir + "/" + output));
        expectOneLineError(runTetglow(command + dir + "/plain/" + output), 1,
                           "cannot create the folder " + dir + "/plain/");
    }
}

// `convert scene.pbrt -o out.json` (no folder in the name) failed with "filesystem error:
// cannot make absolute path" while writing the scene's output name.
TEST(Outputs, ConvertWithoutAFolderInTheOutputName) {
    const std::string dir = tempDir();
    const fs::path before = fs::current_path();
    fs::current_path(dir);
    SceneDesc scene = loadScene(std::string(TETGLOW_SOURCE_DIR) + "/scenes/fog-box.pbrt");
    EXPECT_NO_THROW(writeScene(scene, "fog-box.json"));
    fs::current_path(before);
    EXPECT_EQ(loadScene(dir + "/fog-box.json").output, dir + "/fog-box.exr");
}

// A write that fails half-way leaves neither the file nor its temporary.
TEST(Outputs, FailedWriteLeavesNothingBehind) {
    const std::string dir = tempDir() + "/out";
    fs::create_directories(dir);
    EXPECT_THROW(writeStream(dir + "/x.txt",
                             [](std::ostream& out) {
                                 out << "half a file";
                                 throw std::runtime_error("disk on fire");
                             }),
                 InputError);
    EXPECT_THROW(writeAtomically(dir + "/y.exr",
                                 [](const std::string& temporary) {
                                     std::ofstream(temporary) << "half an image";
                                     throw std::runtime_error("no");
                                 }),
                 InputError);
    EXPECT_TRUE(fs::is_empty(dir));
    try {
        writeStream(dir + "/x.txt", [](std::ostream&) { throw std::runtime_error("disk on\nfire"); });
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir + "/x.txt: cannot write: disk on fire");
    }
}

}  // namespace
}  // namespace tetglow::test
