// Values at the edge of what a number can hold, as options and in files: NaN is refused by every
// option, ranges are said in plain numbers and in full, and a mesh that float coordinates cannot
// shape (placed too far by a node's transform, or too small) is refused by name before TetGen.
#include <gtest/gtest.h>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "scene/MeshFile.h"

namespace tetglow::test {
namespace {

std::string tinyScene(const std::string& integrator = R"("spp": 1)") {
    return R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
               "integrator": {)" +
           integrator + R"(},
               "media": [{"shape": {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}, "sigma_s": 1, "emission": 1}]})";
}

TEST(OptionValues, NanIsRefusedByEveryNumberOption) {
    const std::string scene = writeTemp("scene.json", tinyScene()), out = " -o " + tempDir() + "/x.exr";
    const std::string mesh = writeTemp("box.obj", objText(boxQuads()));
    // --noise nan was accepted and ignored.
    for (const std::string& command : std::vector<std::string>{
             "render " + scene + " --noise nan" + out, "render " + scene + " --frame nan" + out,
             "render " + scene + " --time nan" + out, "render " + scene + " --exposure nan" + out,
             "render " + scene + " --seed nan" + out, "tetrahedralize " + mesh + " --quality nan",
             "tetrahedralize " + mesh + " --max-volume nan", "validate slab --tau nan", "validate slab --g nan",
             "compare-boundary " + mesh + " --shells nan", "compare-boundary " + mesh + " --steps nan"}) {
        SCOPED_TRACE(command);
        const auto r = runTetglow(command, 60);
        expectOneLineError(r, 2, "got 'nan'");
    }
}

// --noise -1 and --frame -1 printed the largest double in 309 digits.
TEST(OptionValues, NoiseAndFrameRangesAreReadable) {
    const std::string scene = writeTemp("scene.json", tinyScene()), out = " -o " + tempDir() + "/x.exr";
    const auto noise = runTetglow("render " + scene + " --noise -1" + out);
    expectOneLineError(noise, 2, "--noise: expected a finite positive number, got '-1'");
    EXPECT_LT(noise.err.size(), 120u) << noise.err;
    const auto frame = runTetglow("render " + scene + " --frame -1" + out);
    expectOneLineError(frame, 2, "--frame: expected an integer in 0..2147483647, got '-1'");
    EXPECT_LT(frame.err.size(), 120u) << frame.err;
}

// 2^63 was called "expected an integer >= 0", which it is.
TEST(OptionValues, ASeedOfTwoToTheSixtyThreeSaysTheRealRange) {
    const std::string scene = writeTemp("scene.json", tinyScene()), out = " -o " + tempDir() + "/x.exr";
    expectOneLineError(runTetglow("render " + scene + " --seed 9223372036854775808" + out), 2,
                       "--seed: expected an integer in 0..9223372036854775807, got '9223372036854775808'");
    const std::string big = writeTemp("big.json", tinyScene(R"("spp": 1, "seed": 9223372036854775808)"));
    expectOneLineError(runTetglow("render " + big + out), 1,
                       "/integrator/seed: expected an integer in 0..9223372036854775807, got 9223372036854775808");
}

// A glTF node's transform that puts a box beyond float precision (reported as TetGen's "nearly
// touching faces"), or shrinks it to nothing (tetrahedralized to a volume of 2e-131): refused
// naming the node and the transform.
TEST(MeshPrecision, FarNodeIsNamed) {
    const TriangleMesh cube = boxQuads().fanned();
    const struct {
        std::string transform, expected;
    } cases[] = {{"\"translation\": [1e25, 0, 0]",
                  "node 'Far': its transform (translation (1e+25, 0, 0), scale 1) "
                  "leaves a mesh that is beyond float precision"},
                 {"\"scale\": [1e-44, 1e-44, 1e-44]", "leaves a mesh that is too small to represent"}};
    for (const auto& c : cases) {
        SCOPED_TRACE(c.transform);
        const Gltf g = gltf({cube}, {{"Far", 0, {}, c.transform}}, {0}, "");
        const std::string path = writeTemp("far.glb", glb(g));
        const auto r = runTetglow("tetrahedralize " + path, 60);
        expectOneLineError(r, 1, c.expected);
        EXPECT_NE(r.err.find("far.glb: node 'Far': its transform ("), std::string::npos) << r.err;
    }
}

// A sphere 1e-300 across was "every triangle has zero area".
TEST(MeshPrecision, AMeshTooSmallToRepresentSaysItsSize) {
    TriangleMesh cube = boxQuads().fanned();
    for (auto& p : cube.positions) p *= 1e-300;
    const std::string path = tempDir() + "/speck.obj";
    writeObj(cube, path);
    const auto r = runTetglow("tetrahedralize " + path, 60);
    expectOneLineError(r, 1, "the mesh is too small to represent: 4e-300 across");
}

// Two `vertex` elements: the faces would index the first without a word.
TEST(MeshPrecision, APlyWithTwoVertexElementsIsRefused) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n5 5 5\n6 5 5\n5 6 5\n3 0 1 2\n";
    const std::string path = writeTemp("two.ply", ply);
    try {
        readMesh(path);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": a second 'vertex' element in the header (faces index one vertex list)");
    }
}

}  // namespace
}  // namespace tetglow::test
