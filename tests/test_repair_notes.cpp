// A mesh repaired into a solid is never rendered in silence: `render`, `preview` and `farm`
// print each repair's summary (the line `tetrahedralize` prints), and a warning naming the
// medium and the share of its surface where holes larger than a tenth of it were filled.
#include <gtest/gtest.h>

#include "PreviewProcess.h"
#include "TestMeshes.h"

namespace tetglow::test {
namespace {

// The upper half of an icosphere: a dome without its base, a hole of a third of the surface
// once spanned.
std::string writeDome() {
    const TriangleMesh sphere = icosphere(2, 1.0, glm::dvec3(0));
    TriangleMesh dome;
    dome.positions = sphere.positions;
    for (const auto& t : sphere.triangles)
        if (sphere.positions[t[0]].y >= -1e-9 && sphere.positions[t[1]].y >= -1e-9 && sphere.positions[t[2]].y >= -1e-9)
            dome.triangles.push_back(t);
    const std::string path = tempDir() + "/dome.obj";
    writeObj(dome, path);
    return path;
}

std::string domeScene() {
    writeDome();
    return writeTemp("dome.json", R"({"camera": {"position": [0, 0.5, 4], "look_at": [0, 0.3, 0], "resolution": [4, 4]},
        "integrator": {"spp": 1},
        "media": [{"shape": {"type": "mesh", "file": "dome.obj"}, "sigma_s": 1, "emission": 1}]})");
}

void expectRepairSaid(const std::string& err) {
    EXPECT_NE(err.find("medium /media/0 (dome.obj): repaired: 1 hole spanned ("), std::string::npos) << err;
    EXPECT_NE(err.find("warning: medium /media/0 (dome.obj): holes spanning 3"), std::string::npos) << err;
    EXPECT_NE(err.find("% of its surface were filled"), std::string::npos) << err;
    EXPECT_NE(err.find("\"strict\": true"), std::string::npos) << "says how to refuse it: " << err;
    EXPECT_NE(err.find("tetrahedralize MESH -o fill.vtk"), std::string::npos) << "says how to inspect it: " << err;
}

TEST(RepairNotes, RenderSaysADomeWasFilled) {
    const auto r = runTetglow("render " + domeScene() + " -o " + tempDir() + "/dome.exr", 120);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectRepairSaid(r.err);
}

TEST(RepairNotes, FarmSaysADomeWasFilled) {
    const auto r = runTetglow("farm " + domeScene() + " --parts 1 -o " + tempDir() + "/dome.exr --dry-run", 120);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectRepairSaid(r.err);
}

TEST(RepairNotes, PreviewSaysADomeWasFilled) {
    const std::string scene = domeScene(), log = tempDir() + "/preview.log";
    {
        PreviewProcess preview(scene + " --port 0", log);
        preview.stop();
    }
    expectRepairSaid(readFile(log));
}

// A clean mesh says nothing about repairs.
TEST(RepairNotes, AClosedMeshIsNotCalledRepaired) {
    const std::string scene =
        writeTemp("ball.json", R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
        "integrator": {"spp": 1}, "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_s": 1, "emission": 1}]})");
    const auto r = runTetglow("render " + scene + " -o " + tempDir() + "/ball.exr", 120);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("repaired"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tetglow::test
