// `generate` writes the format its output's extension names (a cloud as x.stl held OBJ text, and
// init then called it "not an STL file"), and refuses an extension it does not write.
#include <filesystem>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "scene/MeshFile.h"

namespace tetglow::test {
namespace {

TEST(GenerateFormats, WritesTheFormatTheExtensionNames) {
    const std::string dir = tempDir();
    const TriangleMesh expected = icosphere(1, 1.0);
    for (const std::string name : {"ball.obj", "ball.stl", "ball.ply", "BALL.STL"}) {
        SCOPED_TRACE(name);
        const auto r = runTetglow("generate sphere --subdivisions 1 -o " + dir + "/" + name);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const TriangleMesh read = readMesh(dir + "/" + name);
        EXPECT_EQ(read.triangles.size(), expected.triangles.size());
        EXPECT_NEAR(signedVolume(read), signedVolume(expected), 1e-5);
        if (name != "ball.obj") {
            EXPECT_NE(readFile(dir + "/" + name).rfind("# generated", 0), 0u) << "not OBJ text";
        }
    }
    // The user's way: the cloud as STL, then init on it.
    ASSERT_EQ(runTetglow("generate cloud --subdivisions 1 -o " + dir + "/x.stl").exitCode, 0);
    const auto init = runTetglow("init " + dir + "/x.stl -o " + dir + "/s.json");
    EXPECT_EQ(init.exitCode, 0) << init.err;
}

TEST(GenerateFormats, RefusesAnExtensionItDoesNotWrite) {
    const std::string dir = tempDir();
    for (const std::string name : {"x.glb", "x.off", "x"}) {
        SCOPED_TRACE(name);
        expectOneLineError(runTetglow("generate cloud --subdivisions 1 -o " + dir + "/" + name), 1,
                           "a mesh is written as .obj, .ply or .stl");
        EXPECT_FALSE(std::filesystem::exists(dir + "/" + name));
    }
}

}  // namespace
}  // namespace tetglow::test
