// Scene files: a full scene becomes the expected numbers and world-space meshes; each broken
// variant is one InputError line naming the file and the JSON path of the bad field.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "scene/SceneLoader.h"
#include "scene/Turntable.h"

namespace tetglow {
namespace {

// Every light, material, density and shape kind; the box mesh is scaled by 2, turned 90 degrees
// about z and moved by +1 in x; the sphere is mirrored, the last box mirrored by a matrix.
const std::string kFullScene = R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 35, "resolution": [320, 240]},
  "integrator": {"type": "single", "spp": 4, "max_depth": 8, "seed": 7, "boundary": "parity", "step": 0.01, "parity_rays": 3},
  "output": "out/fish.exr",
  "lights": [
    {"type": "point", "position": [1, 2, 3], "intensity": 2, "scale": 10},
    {"type": "spot", "position": [0, 5, 0], "look_at": [0, 0, 0], "cone_angle": 20, "cone_delta": 4, "intensity": [1, 2, 3], "radius": 0.1},
    {"type": "quad", "corner": [0, 3, 0], "edge0": [1, 0, 0], "edge1": [0, 0, 1], "radiance": [4, 4, 4], "two_sided": true},
    {"type": "environment", "radiance": 0.25, "scale": 2}
  ],
  "surfaces": [
    {"shape": {"type": "quad", "corner": [-5, -1, -5], "edge0": [0, 0, 10], "edge1": [10, 0, 0]}, "material": {"type": "diffuse", "reflectance": 0.8}},
    {"shape": {"type": "disk", "center": [0, 2, 0], "normal": [0, -1, 0], "radius": 0.5, "sides": 16}, "material": {"type": "dielectric", "ior": 1.4}}
  ],
  "media": [
    {"shape": {"type": "mesh", "file": "meshes/box.obj", "transform": [{"scale": 2}, {"rotate": [90, 0, 0, 1]}, {"translate": [1, 0, 0]}]},
     "sigma_a": [0.1, 0.2, 0.3], "sigma_s": [1, 1, 1], "scale": 2, "g": 0.5, "emission": [0, 0.5, 0],
     "density": {"type": "linear", "offset": 1, "gradient": [0, 0.1, 0]},
     "boundary": {"type": "dielectric", "ior": 1.33},
     "tetgen": {"quality": 1.5, "max_volume": 0.01}},
    {"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "subdivisions": 1, "transform": [{"scale": [-1, 1, 1]}]},
     "sigma_s": 3, "density": {"type": "noise", "offset": 2, "amplitude": 0.25, "frequency": 8, "seed": 3}},
    {"shape": {"type": "box", "min": [2, 0, 0], "max": [3, 1, 1], "transform": [{"matrix": [1, 0, 0, 5,  0, 1, 0, 0,  0, 0, -1, 0,  0, 0, 0, 1]}]}}
  ]
})";

const std::string kMinimalScene = R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"type": "point", "position": [0, 4, 0], "intensity": 1}]
})";

// The scene and the mesh it names, in this test's directory.
std::string writeScene(const std::string& text) {
    std::filesystem::create_directories(test::tempDir() + "/meshes");
    writeObj(box(), test::tempDir() + "/meshes/box.obj");
    return test::writeTemp("scene.json", text);
}

bool hasVertex(const TriangleMesh& mesh, const glm::dvec3& p) {
    for (const glm::dvec3& q : mesh.positions)
        if (glm::length(q - p) < 1e-6) return true;
    return false;
}

bool floatExact(const TriangleMesh& mesh) {
    for (const glm::dvec3& p : mesh.positions)
        if (p.x != roundToFloat(p.x) || p.y != roundToFloat(p.y) || p.z != roundToFloat(p.z)) return false;
    return true;
}

void expectRgb(const RGB& actual, const RGB& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-12) << "channel " << c;
}

TEST(SceneLoader, FullSceneGivesTheNumbersAndMeshes) {
    const std::string path = writeScene(kFullScene);
    const SceneDesc s = loadScene(path);
    EXPECT_EQ(s.path, path);
    EXPECT_EQ(s.output, test::tempDir() + "/out/fish.exr");

    EXPECT_EQ(s.camera.position, glm::dvec3(0, 0, 5));
    EXPECT_EQ(s.camera.fov, 35);
    EXPECT_EQ(s.camera.width, 320);
    EXPECT_EQ(s.camera.height, 240);

    EXPECT_EQ(s.integrator.type, IntegratorType::Single);
    EXPECT_EQ(s.integrator.spp, 4);
    EXPECT_EQ(s.integrator.maxDepth, 8);
    EXPECT_EQ(s.integrator.seed, 7u);
    EXPECT_EQ(s.integrator.boundary, BoundaryMode::Parity);
    EXPECT_EQ(s.integrator.stepSize, 0.01);
    EXPECT_EQ(s.integrator.parityRays, 3);

    ASSERT_EQ(s.lights.size(), 4u);
    expectRgb(s.lights[0].intensity, RGB(20));  // grey 2, scale 10
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
    expectRgb(s.lights[1].intensity, RGB(1, 2, 3));
    EXPECT_EQ(s.lights[1].coneAngle, 20);
    EXPECT_EQ(s.lights[1].coneDelta, 4);
    EXPECT_EQ(s.lights[1].radius, 0.1);
    EXPECT_EQ(s.lights[2].edge1, glm::dvec3(0, 0, 1));
    EXPECT_TRUE(s.lights[2].twoSided);
    expectRgb(s.lights[3].radiance, RGB(0.5));

    ASSERT_EQ(s.surfaces.size(), 2u);
    EXPECT_EQ(s.surfaces[0].name, "/surfaces/0");
    expectRgb(s.surfaces[0].material.reflectance, RGB(0.8));
    EXPECT_EQ(s.surfaces[1].mesh.triangles.size(), 16u);
    EXPECT_EQ(s.surfaces[1].material.type, MaterialType::Dielectric);
    EXPECT_EQ(s.surfaces[1].material.ior, 1.4);

    ASSERT_EQ(s.media.size(), 3u);
    const MediumDesc& m = s.media[0];
    EXPECT_EQ(m.name, "/media/0 (meshes/box.obj)");
    expectRgb(m.sigmaA, RGB(0.2, 0.4, 0.6));  // scale 2
    expectRgb(m.sigmaS, RGB(2));
    expectRgb(m.emission, RGB(0, 0.5, 0));  // not scaled
    EXPECT_EQ(m.g, 0.5);
    EXPECT_EQ(m.density.type, DensityDesc::Type::Linear);
    EXPECT_EQ(m.density.gradient, glm::dvec3(0, 0.1, 0));
    EXPECT_EQ(m.boundaryMaterial.type, MaterialType::Dielectric);
    EXPECT_EQ(m.boundaryMaterial.ior, 1.33);
    EXPECT_EQ(m.tetOptions.radiusEdgeRatio, 1.5);
    EXPECT_EQ(m.tetOptions.maxVolume, 0.01);
    // Corner (1, 0, 0) of the unit box: scaled to (2, 0, 0), turned to (0, 2, 0), moved to (1, 2, 0).
    EXPECT_TRUE(hasVertex(m.boundary, {1, 2, 0}));
    EXPECT_NEAR(signedVolume(m.boundary), 8, 1e-5);

    expectRgb(s.media[1].sigmaS, RGB(3));
    EXPECT_EQ(s.media[1].density.type, DensityDesc::Type::Noise);
    EXPECT_EQ(s.media[1].density.seed, 3u);
    EXPECT_GT(signedVolume(s.media[1].boundary), 0);  // mirrored, still outward
    const Bounds3 b = bounds(s.media[2].boundary);    // row-major: the translation is the last column
    EXPECT_EQ(b.lo, glm::dvec3(7, 0, -1));
    EXPECT_EQ(b.hi, glm::dvec3(8, 1, 0));
    EXPECT_NEAR(signedVolume(s.media[2].boundary), 1, 1e-12);
    for (const MediumDesc& medium : s.media) EXPECT_TRUE(floatExact(medium.boundary)) << medium.name;
}

TEST(SceneLoader, MinimalSceneGetsTheDefaults) {
    const SceneDesc s = loadScene(writeScene(kMinimalScene));
    EXPECT_EQ(s.output, "");
    EXPECT_EQ(s.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.camera.width, 400);
    EXPECT_EQ(s.integrator.type, IntegratorType::VolPath);
    EXPECT_EQ(s.integrator.spp, 16);
    EXPECT_TRUE(s.surfaces.empty());
    EXPECT_TRUE(s.media.empty());
}

TEST(SceneLoader, MissingSceneFile) {
    try {
        loadScene(test::tempDir() + "/nothere.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("nothere.json: no such file"), std::string::npos) << e.what();
    }
}

// A broken variant of a scene: `find` in `base` replaced by `replace` (all of `base` when `find`
// is empty), and what the error must name besides the file.
struct Broken {
    const char* what;
    std::string find, replace, expected;
    const std::string& base = kFullScene;
};

const Broken kBroken[] = {
    {"syntax error", R"("fov": 35, )", R"("fov": 35 )", "scene.json:2:97: /camera: syntax error"},
    {"number overflow", "[0.1, 0.2, 0.3]", "[0.1, 1e999, 0.3]",
     "scene.json:17:27: /media/0/sigma_a/1: number overflow"},
    {"duplicate key", R"("spp": 4,)", R"("spp": 4, "spp": 5,)", "/integrator/spp: duplicate key"},
    {"unknown key", R"("fov": 35)", R"("fovy": 35)",
     "/camera/fovy: unknown key (did you mean \"fov\"?); allowed here: position, look_at, up, fov"},
    {"unknown top-level key", R"("output")", R"("ouptut")", "/ouptut: unknown key"},
    {"wrong type", R"("spp": 4)", R"("spp": "many")",
     R"(/integrator/spp: expected an integer in 1..1048576, got "many")"},
    {"NaN as a string", R"("g": 0.5)", R"("g": "NaN")", R"(/media/0/g: expected a number in (-1, 1), got "NaN")"},
    {"negative sigma", R"("sigma_s": [1, 1, 1])", R"("sigma_s": [1, -1, 1])",
     "/media/0/sigma_s: expected an array of 3 numbers in [0, 3.40282e38]"},
    {"grey not a number", R"("sigma_s": 3)", R"("sigma_s": "abc")",
     R"(/media/1/sigma_s: expected an array of 3 numbers in [0, 3.40282e38] (or one for all 3), got "abc")"},
    {"g = 1", R"("g": 0.5)", R"("g": 1)", "/media/0/g"},
    {"spp = 0", R"("spp": 4)", R"("spp": 0)", "/integrator/spp"},
    {"even parity_rays", R"("parity_rays": 3)", R"("parity_rays": 2)",
     "/integrator/parity_rays: expected an odd integer"},
    {"resolution too large", "[320, 240]", "[320, 20000]", "/camera/resolution/1: expected an integer in 1..16384"},
    {"missing mesh file", "meshes/box.obj", "meshes/fish.obj", "/media/0/shape/file: "},  // in full: below
    {"quad as a medium", R"("type": "sphere")", R"("type": "quad")", "/media/1/shape/type: expected a closed shape"},
    {"camera looks at itself", R"("look_at": [0, 0, 0], "up")", R"("look_at": [0, 0, 5], "up")", "/camera/look_at"},
    {"up along the view", R"("up": [0, 1, 0])", R"("up": [0, 0, -2])", "/camera/up"},
    {"missing required key", R"("position": [1, 2, 3], )", "", "/lights/0/position: missing"},
    {"bad light type", R"("type": "environment")", R"("type": "sun")", R"(/lights/3/type: expected one of "point")"},
    {"cone_delta beyond cone_angle", R"("cone_delta": 4)", R"("cone_delta": 25)", "/lights/1/cone_delta"},
    {"reflectance above 1", R"("reflectance": 0.8)", R"("reflectance": [0.5, 1.5, 0.5])",
     "/surfaces/0/material/reflectance"},
    {"diffuse medium boundary", R"("boundary": {"type": "dielectric")", R"("boundary": {"type": "diffuse")",
     "/media/0/boundary/type"},
    {"key of another type", R"("type": "dielectric", "ior": 1.4)", R"("type": "interface", "ior": 1.4)",
     "/surfaces/1/material/ior: unknown key"},
    {"tetgen quality below 1", R"("quality": 1.5)", R"("quality": 0.5)", "/media/0/tetgen/quality"},
    {"singular transform", R"({"scale": [-1, 1, 1]})", R"({"scale": [0, 1, 1]})",
     "/media/1/shape/transform: the transform is singular"},
    {"unknown transform", R"({"translate": [1, 0, 0]})", R"({"shift": [1, 0, 0]})",
     "/media/0/shape/transform/2/shift: unknown key"},
    {"non-affine matrix", "0, 0, -1, 0,  0, 0, 0, 1]", "0, 0, -1, 0,  0, 0, 1, 1]",
     "/media/2/shape/transform/0/matrix"},
    {"empty box", R"("max": [3, 1, 1])", R"("max": [3, 0, 1])", "/media/2/shape/max"},
    {"no emitters", R"("intensity": 1)", R"("intensity": 0)", "/lights: nothing emits light", kMinimalScene},
    {"turntable without frames", R"("camera":)", R"("turntable": {"degrees": 90}, "camera":)",
     "/turntable/frames: missing"},
    {"turntable of 0 frames", R"("camera":)", R"("turntable": {"frames": 0}, "camera":)",
     "/turntable/frames: expected an integer in 1..1000000"},
    {"turntable about no axis", R"("camera":)", R"("turntable": {"frames": 4, "axis": [0, 0, 0]}, "camera":)",
     "/turntable/axis: expected a non-zero vector"},
    {"medium name not a string", R"("g": 0.5)", R"("g": 0.5, "name": 7)",
     "/media/0/name: expected a non-empty string, got 7"},
    {"medium name too long", R"("g": 0.5)", R"("g": 0.5, "name": ")" + std::string(65, 'x') + "\"",
     "/media/0/name: expected a name of 1 to 64 bytes without control characters, got \"xxxxxxxx"},
    {"medium name with a control character", R"("g": 0.5)", R"("g": 0.5, "name": "body\u0007")",
     R"(/media/0/name: expected a name of 1 to 64 bytes without control characters, got "body\u0007")"},
    {"medium name with a C1 control character", R"("g": 0.5)", R"("g": 0.5, "name": "body\u0085")",
     "/media/0/name: expected a name of 1 to 64 bytes without control characters"},
    {"medium name with a line break", R"("g": 0.5)", R"("g": 0.5, "name": "body\nlure")",
     "/media/0/name: expected a name of 1 to 64 bytes without control characters"},
    {"light switched by a number", R"("two_sided": true)", R"("two_sided": true, "on": 1)",
     "/lights/2/on: expected true or false, got 1"},
    {"no lights at all", "", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}})",
     "/lights: nothing emits light"},
    {"no camera", "", R"({"lights": [{"type": "environment", "radiance": 1}]})",
     "/camera: missing; expected an object"},
    {"top level not an object", "", "[1, 2]", "scene.json: expected an object, got [1,2]"},
};

TEST(SceneLoader, BrokenScenesNameTheFileAndField) {
    for (const Broken& b : kBroken) {
        SCOPED_TRACE(b.what);
        std::string text = b.base;
        if (b.find.empty()) {
            text = b.replace;
        } else {
            const size_t at = text.find(b.find);
            ASSERT_NE(at, std::string::npos) << "the variant's text is not in the scene";
            ASSERT_EQ(text.find(b.find, at + 1), std::string::npos) << "the variant's text is not unique";
            text.replace(at, b.find.size(), b.replace);
        }
        try {
            loadScene(writeScene(text));
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("scene.json"), std::string::npos) << message;
            EXPECT_NE(message.find(b.expected), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        }
    }
}

// A medium's "name" is what the preview shows; without one, its mesh's file name (a built-in
// shape: its place in the file). Up to 64 bytes of UTF-8, so a name in any script fits.
TEST(SceneLoader, MediaAreNamedByTheFileOrByTheirMesh) {
    const std::string longest(64, 'x');
    const SceneDesc s = loadScene(writeScene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"type": "point", "position": [0, 4, 0], "intensity": 1}],
  "media": [
    {"name": "Köder", "shape": {"type": "mesh", "file": "meshes/box.obj"}},
    {"shape": {"type": "mesh", "file": "meshes/box.obj", "transform": [{"translate": [3, 0, 0]}]}},
    {"shape": {"type": "sphere", "center": [-3, 0, 0], "radius": 0.5}, "name": ")" +
                                             longest + R"("}
  ],
  "cavities": [{"shape": {"type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 0.1}, "name": "bubble"}]
})"));
    ASSERT_EQ(s.media.size(), 4u);
    EXPECT_EQ(s.media[0].label, "Köder");
    EXPECT_EQ(s.media[1].label, "box.obj");
    EXPECT_EQ(s.media[2].label, longest);
    EXPECT_EQ(s.media[3].label, "bubble");
    EXPECT_EQ(s.media[0].name, "/media/0 (meshes/box.obj)") << "messages still name the file's place";
}

// A light that is off keeps its values (so that it can be turned on again) and emits nothing.
TEST(SceneLoader, ALightThatIsOffKeepsItsValues) {
    const std::string on = R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0], "intensity": [1, 2, 3], "scale": 10, "on": true},
             {"type": "environment", "radiance": 0.5, "on": false}]
})";
    const SceneDesc s = loadScene(writeScene(on));
    EXPECT_TRUE(s.lights[0].on);
    EXPECT_FALSE(s.lights[1].on);
    expectRgb(s.lights[1].radiance, RGB(0.5));
    EXPECT_TRUE(emitsLight(s));
    std::string off = on;
    off.replace(off.find(R"("on": true)"), 10, R"("on": false)");
    try {
        loadScene(writeScene(off));
        ADD_FAILURE() << "a scene with every light off loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/lights: nothing emits light"), std::string::npos) << e.what();
    }
}

// readMesh's message, behind the scene file and the JSON path.
TEST(SceneLoader, MeshFileErrorsCarryTheJsonPath) {
    const std::string meshes = test::tempDir() + "/meshes";
    std::filesystem::create_directories(meshes);
    const std::string scene = test::writeTemp("scene.json", kFullScene);
    const std::string prefix = scene + ": /media/0/shape/file: " + meshes;
    for (const auto& [obj, expected] : {std::pair<std::string, std::string>{"", "/box.obj: no such file"},
                                        {"v 0 0 0\nf 1 2 3\n", "/box.obj:2: face index 2 out of range"}}) {
        std::filesystem::remove(meshes + "/box.obj");
        if (!obj.empty()) test::writeTemp("meshes/box.obj", obj);
        try {
            loadScene(scene);
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(prefix + expected), std::string::npos) << e.what();
        }
    }
}

// The scenes in scenes/ load; those on ../shared/meshes only where that folder exists (the test
// skips, naming them, where it does not).
TEST(SceneLoader, ShippedScenesLoad) {
    const bool haveShared = !test::sharedMesh("blub").empty();
    std::string notLoaded;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(TETGLOW_SOURCE_DIR) + "/scenes")) {
        if (entry.path().extension() != ".json" && entry.path().extension() != ".pbrt") continue;
        std::stringstream text;
        text << std::ifstream(entry.path()).rdbuf();
        if (!haveShared && text.str().find("shared/meshes") != std::string::npos) {
            notLoaded += " " + entry.path().filename().string();
            continue;
        }
        try {
            loadScene(entry.path().string());
        } catch (const InputError& e) {
            ADD_FAILURE() << e.what();
        }
    }
    if (!notLoaded.empty()) GTEST_SKIP() << "../shared/meshes not found; not loaded:" << notLoaded;
}

// Frame k of n turns the camera by k / n of the turn, right-handed about the axis through the center.
TEST(Turntable, TurnsTheCameraAboutTheAxis) {
    SceneDesc scene;
    scene.camera.position = {0.3, 0.2, 4};
    scene.camera.lookAt = {1, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.turntable = {.frames = 4, .center = {1, 0, 0}, .axis = {0, 2, 0}, .degrees = 360};
    const CameraDesc still = cameraAtFrame(scene, 0);
    EXPECT_TRUE(still.position == scene.camera.position && still.lookAt == scene.camera.lookAt &&
                still.up == scene.camera.up);
    const CameraDesc quarter = cameraAtFrame(scene, 1);  // (x, z) - center -> (z, -x): a quarter turn about +y
    EXPECT_NEAR(glm::distance(quarter.position, glm::dvec3(1 + 4, 0.2, 0.7)), 0, 1e-12);
    EXPECT_NEAR(glm::distance(quarter.lookAt, glm::dvec3(1, 0, 0)), 0, 1e-12);
    EXPECT_NEAR(glm::distance(quarter.up, glm::dvec3(0, 1, 0)), 0, 1e-12);
    scene.turntable.axis = {1, 0, 0};  // about x, the up vector turns too
    const CameraDesc tilted = cameraAtFrame(scene, 1);
    EXPECT_NEAR(glm::distance(tilted.up, glm::dvec3(0, 0, 1)), 0, 1e-12);
}

}  // namespace
}  // namespace tetglow
