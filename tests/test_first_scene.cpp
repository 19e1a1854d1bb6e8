// `tetglow init`: a first scene around a mesh of one's own, that renders from anywhere and frames
// the mesh; and the hint an open vessel modelled as a solid with a cavity gets.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "JsonFiles.h"
#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::test {
namespace {

// The mesh in one folder, the scene in another, rendered from a third: the mesh is named
// relative to the scene, and the render succeeds.
TEST(Init, SceneRendersFromAnyFolder) {
    const std::string dir = tempDir();
    const std::string mesh = std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/fish.obj";
    const auto r = runTetglow("init " + mesh + " -o " + dir + "/mine/scene.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json scene = readJson(dir + "/mine/scene.json");
    const std::string file = scene["media"][0]["shape"]["file"];
    EXPECT_FALSE(std::filesystem::path(file).is_absolute()) << file;
    EXPECT_TRUE(std::filesystem::equivalent(dir + "/mine/" + file, mesh)) << file;
    const auto render =
        runTetglow("render " + dir + "/mine/scene.json --resolution 16x12 --spp 2 -o " + dir + "/elsewhere/x.exr");
    EXPECT_EQ(render.exitCode, 0) << render.err;
    // Does not overwrite a scene.
    expectOneLineError(runTetglow("init " + mesh + " -o " + dir + "/mine/scene.json"), 1,
                       "mine/scene.json: already exists");
    expectOneLineError(runTetglow("init " + writeTemp("bad.obj", "v 0 0 0\nf 1 2 3\n") + " -o " + dir + "/bad.json"), 1,
                       "bad.obj");
}

// Every corner of the mesh's bounding box lies inside the camera's view (a cone of half the
// field of view around its axis, which the frame holds), in front of it, and above the floor.
TEST(Init, CameraFramesTheMeshOnTheFloor) {
    const std::string dir = tempDir();
    TriangleMesh mesh = icosphere(2, 1.0);
    for (auto& p : mesh.positions) p = p * glm::dvec3(30, 5, 12) + glm::dvec3(100, -40, 7);  // any units, anywhere
    writeObj(mesh, dir + "/blob.obj");
    ASSERT_EQ(runTetglow("init " + dir + "/blob.obj -o " + dir + "/scene.json").exitCode, 0);
    const nlohmann::json scene = readJson(dir + "/scene.json");
    const glm::dvec3 eye = vec(scene["camera"]["position"]),
                     axis = glm::normalize(vec(scene["camera"]["look_at"]) - eye);
    const double halfFov = scene["camera"]["fov"].get<double>() / 2 * M_PI / 180;
    const Bounds3 box = bounds(mesh);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y,
                           corner & 4 ? box.hi.z : box.lo.z);
        EXPECT_LT(std::acos(glm::dot(glm::normalize(p - eye), axis)), halfFov) << corner;
    }
    const nlohmann::json& floor = scene["surfaces"][0]["shape"];
    EXPECT_LT(vec(floor["corner"]).y, box.lo.y);
    EXPECT_EQ(vec(floor["edge0"]).y, 0);
    EXPECT_EQ(vec(floor["edge1"]).y, 0);
}

// A glass as a solid box with a cavity reaching through its top: the surfaces cross, and the
// error says how to model an open vessel.
TEST(Init, OpenVesselAsCavityGetsAHint) {
    try {
        tetrahedralize({box({0, 0, 0}, {2, 2, 2}), box({0.2, 0.2, 0.2}, {1.8, 2.5, 1.8})}, {"glass", "inside"},
                       noCache());
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("glass and inside cross"), std::string::npos) << what;
        EXPECT_NE(what.find("cup-shaped mesh"), std::string::npos) << what;
    }
}

// A floor inside an absorbing medium (a floor under water), camera and point light in the medium
// too: the pixel that sees the floor straight below the light has the closed form
// reflectance / pi * I cos / d^2 * exp(-sigma_a (d + camera distance)); the medium attenuates
// both legs, the floor reflects as in air.
TEST(SurfaceInsideAMedium, FloorUnderWaterMatchesTheClosedForm) {
    const RGB sigmaA(0.5, 1.0, 2.0);
    SceneDesc desc = sceneWith(sphereMedium(sigmaA, RGB(0), 0, 4), 1);
    desc.camera.position = {0, 0, 0.5};
    desc.camera.lookAt = {0, -0.4, 0};
    desc.camera.fov = 0.01;  // the pixel sees one point
    SurfaceDesc floor;
    floor.name = "floor";
    floor.mesh = quad({-0.4, -0.4, -0.4}, {0, 0, 0.8}, {0.8, 0, 0});
    floor.material.type = MaterialType::Diffuse;
    floor.material.reflectance = RGB(0.5);
    desc.surfaces.push_back(floor);
    LightDesc light;
    light.position = {0, 0.3, 0};
    light.intensity = RGB(2);
    desc.lights.push_back(light);
    const Scene scene(desc);
    ASSERT_TRUE(scene.volumeAt(desc.camera.position).inside());
    const auto integrator = makeIntegrator(scene, IntegratorDesc{});
    RenderOptions options;
    options.spp = 16;
    const Image image = render(scene, *integrator, options).image;
    const double toLight = 0.7, toCamera = std::sqrt(0.5 * 0.5 + 0.4 * 0.4);
    for (int c = 0; c < 3; ++c) {
        const double expected = 0.5 / M_PI * 2 / (toLight * toLight) * std::exp(-sigmaA[c] * (toLight + toCamera));
        EXPECT_NEAR(image.pixels[0][c], expected, 1e-3 * expected) << c;
    }
}

}  // namespace
}  // namespace tetglow::test
