// glTF 2.0 scenes: the camera, KHR_lights_punctual in photometric units, the material extensions
// and extras, node transforms, instancing and nesting, `convert`, and malformed files, each against
// the JSON scene that says the same thing.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "GltfBuilder.h"
#include "PreviewProcess.h"
#include "SceneCompare.h"
#include "TestMeshes.h"
#include "render/ImageIO.h"
#include "scene/MediaNesting.h"
#include "scene/SceneLoader.h"

namespace tetglow {
namespace {

using nlohmann::json;
using test::GltfBuilder;

constexpr double kPi = glm::pi<double>();

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance, const std::string& what) {
    EXPECT_LE(glm::length(a - b), tolerance)
        << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

std::string errorOf(const std::string& path, const std::string& camera = "") {
    try {
        loadScene(path, camera);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// A camera node, a diffuse floor under it and a point light over it: the base of every scene here.
GltfBuilder withCamera(double yfov = 0.6, double aspect = 1.5) {
    GltfBuilder b;
    b.addNode({{"name", "Eye"}, {"camera", b.addCamera(yfov, aspect)}, {"translation", {0, 0.5, 4}}});
    return b;
}

const TriangleMesh& floorMesh() {
    static const TriangleMesh m = quad({-3, -1, 3}, {6, 0, 0}, {0, 0, -6});  // facing +y
    return m;
}

int addFloor(GltfBuilder& b) {
    const int grey =
        b.addMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.5, 0.4, 1}}, {"metallicFactor", 0}}}});
    return b.addNode({{"name", "Floor"}, {"mesh", b.addMesh(floorMesh(), grey)}});
}

// The renders compared here use one seed, so images of the same scene are equal up to the last
// bits of positions computed two ways; a framing or brightness error moves whole pixels.
double relativeDifference(const std::string& a, const std::string& b) {
    const Image x = readExr(a), y = readExr(b);
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    double diff = 0, sum = 0;
    for (size_t i = 0; i < x.pixels.size() && i < y.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            diff += std::abs(x.pixels[i][k] - y.pixels[i][k]);
            sum += x.pixels[i][k];
        }
    EXPECT_GT(sum, 0) << a << " is black";
    return diff / sum;
}

std::string render(const std::string& scene, const std::string& exr, const std::string& extra = "") {
    const auto r = test::runTetglow("render " + scene + " --seed 3 --spp 4 --threads 2 -o " + exr + " " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return exr;
}

TEST(GltfScene, CameraFramingMatchesTheJsonCamera) {
    const std::string dir = test::tempDir();
    // The camera two nodes down: turned 90 degrees about +y by its parent, 4 along its own +z.
    GltfBuilder b;
    const int eye = b.addNode({{"name", "Eye"}, {"camera", b.addCamera(0.5, 1.5)}, {"translation", {0, 0, 4}}}, false);
    b.addNode({{"name", "Rig"}, {"rotation", {0, std::sin(kPi / 4), 0, std::cos(kPi / 4)}}, {"children", {eye}}});
    addFloor(b);
    b.addLight({{"type", "point"}, {"intensity", 683 * 20}});
    b.addNode({{"light", 0}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {1, 3, 0}}});
    const std::string gltf = b.writeGltf(dir + "/turned.gltf");
    const SceneDesc s = loadScene(gltf);
    expectNear(s.camera.position, {4, 0, 0}, 1e-12, "position");
    expectNear(s.camera.lookAt, {3, 0, 0}, 1e-12, "look_at");
    expectNear(s.camera.up, {0, 1, 0}, 1e-12, "up");
    EXPECT_EQ(s.camera.width, 600);
    EXPECT_EQ(s.camera.height, 400);
    EXPECT_DOUBLE_EQ(s.camera.fov, 0.5 * 180 / kPi);  // wide: the shorter axis is the vertical one
    EXPECT_EQ(s.camera.handedness, Handedness::Right);

    // The same view written as a tetglow JSON scene renders the same image.
    writeObj(floorMesh(), dir + "/floor.obj");
    const std::string jsonScene = test::writeTemp("turned.json", R"({
  "camera": {"position": [4, 0, 0], "look_at": [3, 0, 0], "fov": )" + std::to_string(0.5 * 180 / kPi) +
                                                                     R"(, "resolution": [600, 400]},
  "lights": [{"type": "point", "position": [1, 3, 0], "intensity": 20}],
  "surfaces": [{"shape": {"type": "mesh", "file": "floor.obj"}, "material": {"type": "diffuse", "reflectance": [0.6, 0.5, 0.4]}}]
})");
    const std::string res = "--resolution 30x20";
    EXPECT_LT(relativeDifference(render(gltf, dir + "/g.exr", res), render(jsonScene, dir + "/j.exr", res)), 1e-4);

    // Tall: yfov spans the longer axis, so tetglow's fov (across the shorter) is narrower.
    b.json["cameras"][0]["perspective"]["aspectRatio"] = 0.5;
    const SceneDesc tall = loadScene(b.writeGltf(dir + "/tall.gltf"));
    EXPECT_EQ(tall.camera.width, 400);
    EXPECT_EQ(tall.camera.height, 800);
    EXPECT_NEAR(tall.camera.fov, 2 * std::atan(std::tan(0.25) * 0.5) * 180 / kPi, 1e-12);
    // A mirroring parent makes the camera's image x run along cross(up, view).
    b.json["nodes"][1]["scale"] = {-1, 1, 1};
    EXPECT_EQ(loadScene(b.writeGltf(dir + "/mirrored.gltf")).camera.handedness, Handedness::Left);
}

TEST(GltfScene, CameraIsTheFirstOrTheNamedOne) {
    GltfBuilder b = withCamera();
    b.addNode({{"name", "Side"}, {"camera", b.addCamera(0.3, 1)}, {"translation", {5, 0, 0}}});
    addFloor(b);
    b.addLight({{"type", "directional"}, {"intensity", 683}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"rotation", {-0.5, 0, 0, 0.8660254}}});
    const std::string path = b.writeGltf(test::tempDir() + "/two.gltf");
    expectNear(loadScene(path).camera.position, {0, 0.5, 4}, 0, "first camera");
    expectNear(loadScene(path, "Side").camera.position, {5, 0, 0}, 0, "named camera");
    EXPECT_EQ(loadScene(path, "Side").camera.width, 400);
    EXPECT_EQ(errorOf(path, "Top"), path + ": /scenes/0: no camera node named 'Top' (camera nodes: 'Eye', 'Side')");
    const std::string json = test::writeTemp("plain.json", R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
        "lights": [{"type": "environment", "radiance": 1}]})");
    EXPECT_EQ(errorOf(json, "Side"),
              "--camera Side: " + json + " is not a glTF scene; only glTF scenes name their cameras");
}

// Each light of KHR_lights_punctual (cd, lux) against the JSON light of intensity / 683 (W/sr, W/m^2).
TEST(GltfScene, LightsMatchJsonLightsAt683LumensPerWatt) {
    const std::string dir = test::tempDir();
    writeObj(floorMesh(), dir + "/floor.obj");
    const std::string camera =
        R"("camera": {"position": [0, 0.5, 4], "look_at": [0, 0.5, 3], "fov": 34.377467707849392, "resolution": [30, 20]})";
    const std::string floor =
        R"("surfaces": [{"shape": {"type": "mesh", "file": "floor.obj"}, "material": {"type": "diffuse", "reflectance": [0.6, 0.5, 0.4]}}])";
    // Turned -60 degrees about x: the node's -z (the light's axis) points down and away.
    const json turned = {-0.5, 0, 0, 0.8660254037844386};
    const glm::dvec3 axis(0, -0.8660254037844386, -0.5);
    struct Case {
        json light;
        std::string jsonLight;
    };
    const Case cases[] = {
        {{{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 683 * 8}},
         R"({"type": "point", "position": [0.5, 1, 0], "intensity": [8, 4, 2]})"},
        {{{"type", "spot"}, {"intensity", 683 * 30}, {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.5}}}},
         R"({"type": "spot", "position": [0.5, 1, 0], "look_at": [0.5, 0.1339745962155614, -0.5], "cone_angle": 28.64788975654116, "cone_delta": 11.459155902616464, "intensity": 30})"},
        {{{"type", "directional"}, {"color", {0.5, 1, 1}}, {"intensity", 683 * 2}},
         R"({"type": "distant", "direction": [0, -0.8660254037844386, -0.5], "irradiance": [1, 2, 2]})"},
    };
    for (const Case& c : cases) {
        const std::string type = c.light["type"];
        GltfBuilder b = withCamera(0.6, 1.5);
        addFloor(b);
        b.addLight(c.light);
        b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
                   {"translation", {0.5, 1, 0}},
                   {"rotation", turned}});
        const std::string gltf = b.writeGltf(dir + "/" + type + ".gltf");
        const std::string jsonScene =
            test::writeTemp(type + ".json", "{" + camera + ", " + floor + ", \"lights\": [" + c.jsonLight + "]}");
        const SceneDesc g = loadScene(gltf), j = loadScene(jsonScene);
        ASSERT_EQ(g.lights.size(), 1u);
        const LightDesc &l = g.lights[0], &m = j.lights[0];
        EXPECT_EQ(l.type, m.type) << type;
        expectNear(emissionOf(l), emissionOf(m), 1e-12, type + " emission");
        if (l.type == LightType::Distant) expectNear(l.direction, axis, 1e-9, type + " direction");
        if (l.type != LightType::Distant) expectNear(l.position, m.position, 1e-12, type + " position");
        if (l.type == LightType::Spot) {
            expectNear(glm::normalize(l.lookAt - l.position), axis, 1e-9, "spot axis");
            EXPECT_NEAR(l.coneAngle, m.coneAngle, 1e-9);
            EXPECT_NEAR(l.coneDelta, m.coneDelta, 1e-9);
        }
        EXPECT_NEAR(g.camera.fov, j.camera.fov, 1e-12);
        EXPECT_LT(relativeDifference(render(gltf, dir + "/" + type + "-g.exr", "--resolution 30x20"),
                                     render(jsonScene, dir + "/" + type + "-j.exr")),
                  1e-4)
            << type;
    }
}

// A glTF with one sphere of material `material` (and a point light, so something emits).
SceneDesc sphereScene(const json& material, const std::string& name) {
    GltfBuilder b = withCamera();
    b.addLight({{"type", "point"}, {"intensity", 683}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 3, 0}}});
    const int m = material.is_null() ? -1 : b.addMaterial(material);
    b.addNode({{"name", "Ball"}, {"mesh", b.addMesh(icosphere(2, 0.5), m)}});
    return loadScene(b.writeGltf(test::tempDir() + "/" + name + ".gltf"));
}

TEST(GltfScene, VolumeAttenuationBecomesSigmaA) {
    const SceneDesc s = sphereScene(
        {{"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
           {"KHR_materials_ior", {{"ior", 1.33}}},
           {"KHR_materials_volume",
            {{"thicknessFactor", 0.1}, {"attenuationColor", {0.5, 0.25, 1}}, {"attenuationDistance", 2}}}}}},
        "volume");
    ASSERT_EQ(s.media.size(), 1u);
    const MediumDesc& m = s.media[0];
    expectNear(m.sigmaA, {std::log(2.0) / 2, std::log(4.0) / 2, 0}, 1e-15, "sigma_a = -ln(colour) / distance");
    EXPECT_EQ(m.sigmaS, RGB(0));
    EXPECT_EQ(m.boundaryMaterial.type, MaterialType::Dielectric);
    EXPECT_EQ(m.boundaryMaterial.ior, 1.33);
    EXPECT_EQ(m.label, "Ball");
    EXPECT_EQ(m.name, "/nodes/2 (Ball)");
}

TEST(GltfScene, TransmissionAndIorMakeADielectricBoundary) {
    const SceneDesc glass = sphereScene(
        {{"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_ior", {{"ior", 1.7}}}}}},
        "glass");
    ASSERT_EQ(glass.media.size(), 1u);
    EXPECT_EQ(glass.media[0].boundaryMaterial.type, MaterialType::Dielectric);
    EXPECT_EQ(glass.media[0].boundaryMaterial.ior, 1.7);
    EXPECT_EQ(glass.media[0].sigmaA + glass.media[0].sigmaS, RGB(0));  // clear glass: a solid with nothing inside
    const SceneDesc plain =
        sphereScene({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}}, "ior15");
    EXPECT_EQ(plain.media[0].boundaryMaterial.ior, 1.5);  // KHR_materials_ior's default
    // A volume without transmission is index-matched: its surface does not refract.
    const SceneDesc fog =
        sphereScene({{"extensions", {{"KHR_materials_volume", {{"attenuationDistance", 1}}}}}}, "fog");
    EXPECT_EQ(fog.media[0].boundaryMaterial.type, MaterialType::Interface);
}

TEST(GltfScene, EmissiveStrengthMakesAnAreaLight) {
    const SceneDesc s = sphereScene({{"emissiveFactor", {1, 0.5, 0.25}},
                                     {"doubleSided", true},
                                     {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}},
                                    "glow");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[1].type, LightType::Mesh);
    EXPECT_EQ(s.lights[1].radiance, RGB(4, 2, 1));
    EXPECT_TRUE(s.lights[1].twoSided);
    EXPECT_EQ(s.lights[1].mesh.triangles.size(), 320u);
}

TEST(GltfScene, SurfacesByBaseColourAndTransparency) {
    const SceneDesc diffuse = sphereScene(
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}, {"metallicFactor", 0}}}}, "diffuse");
    ASSERT_EQ(diffuse.surfaces.size(), 1u);
    EXPECT_EQ(diffuse.surfaces[0].material.type, MaterialType::Diffuse);
    EXPECT_EQ(diffuse.surfaces[0].material.reflectance, RGB(0.2, 0.4, 0.6));
    const SceneDesc none = sphereScene(json(), "none");
    EXPECT_EQ(none.surfaces[0].material.type, MaterialType::Interface);
    const SceneDesc blend =
        sphereScene({{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.3}}}}}, "blend");
    EXPECT_EQ(blend.surfaces[0].material.type, MaterialType::Interface);
}

TEST(GltfScene, ExtrasSetWhatGltfCannotSay) {
    const json material = {
        {"extensions",
         {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
          {"KHR_materials_volume", {{"attenuationColor", {0.5, 0.5, 0.5}}, {"attenuationDistance", 1}}}}},
        {"extras",
         {{"tetglow", {{"sigma_s", {1, 2, 3}}, {"scale", 2}, {"g", 0.3}, {"emission", 0.5}}}, {"blender", "kept"}}}};
    const SceneDesc s = sphereScene(material, "extras");
    const MediumDesc& m = s.media[0];
    expectNear(m.sigmaA, glm::dvec3(2 * std::log(2.0)), 1e-15, "scale multiplies the extension's sigma_a");
    EXPECT_EQ(m.sigmaS, RGB(2, 4, 6));
    EXPECT_EQ(m.g, 0.3);
    EXPECT_EQ(m.emission, RGB(0.5));
    // Extras alone make a glowing, index-matched medium.
    const SceneDesc glow = sphereScene({{"extras", {{"tetglow", {{"sigma_a", 1}, {"emission", {1, 0, 0}}}}}}}, "glow2");
    EXPECT_EQ(glow.media[0].boundaryMaterial.type, MaterialType::Interface);
    EXPECT_EQ(glow.media[0].emission, RGB(1, 0, 0));

    GltfBuilder b = withCamera();
    const int bad = b.addMaterial({{"extras", {{"tetglow", {{"sigma_t", 1}}}}}});
    b.addNode({{"mesh", b.addMesh(icosphere(1), bad)}});
    const std::string path = b.writeGltf(test::tempDir() + "/typo.gltf");
    EXPECT_EQ(errorOf(path).rfind(path + ": /materials/0/extras/tetglow/sigma_t: unknown key", 0), 0u) << errorOf(path);

    // The scene's extras: resolution, integrator, environment.
    GltfBuilder c = withCamera();
    c.json["scenes"][0]["extras"] = {
        {"tetglow", {{"resolution", {32, 24}}, {"integrator", {{"spp", 7}, {"max_depth", 5}}}, {"environment", 0.25}}}};
    const SceneDesc x = loadScene(c.writeGltf(test::tempDir() + "/settings.gltf"));
    EXPECT_EQ(x.camera.width, 32);
    EXPECT_EQ(x.camera.height, 24);
    EXPECT_EQ(x.integrator.spp, 7);
    EXPECT_EQ(x.integrator.maxDepth, 5);
    ASSERT_EQ(x.lights.size(), 1u);
    EXPECT_EQ(x.lights[0].radiance, RGB(0.25));
}

// A glass body holding a glowing core (a child node, so placed by both transforms), and one mesh
// instanced at two nodes, one of them mirrored.
TEST(GltfScene, HierarchyInstancesAndNesting) {
    GltfBuilder b = withCamera();
    const int glass = b.addMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}});
    const int core = b.addMaterial({{"extras", {{"tetglow", {{"sigma_s", 0}, {"emission", 2}}}}}});
    const int ball = b.addMesh(icosphere(2), glass);
    const int inner =
        b.addNode({{"name", "Core"}, {"mesh", b.addMesh(icosphere(2), core)}, {"scale", {0.4, 0.4, 0.4}}}, false);
    b.addNode({{"name", "Body"}, {"mesh", ball}, {"translation", {-2, 0, 0}}, {"children", {inner}}});
    b.addNode({{"name", "Twin"}, {"mesh", ball}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1}}});
    const SceneDesc s = loadScene(b.writeGltf(test::tempDir() + "/nested.gltf"));
    ASSERT_EQ(s.media.size(), 3u);
    EXPECT_EQ(s.media[0].label, "Body");
    EXPECT_EQ(s.media[1].label, "Core");
    EXPECT_EQ(s.media[2].label, "Twin");
    // Placed: the body at x = -2, the core at -2 scaled by 0.4, the twin at +2.
    const auto centre = [](const TriangleMesh& m) {
        glm::dvec3 c(0);
        for (const auto& p : m.positions) c += p;
        return c / double(m.positions.size());
    };
    expectNear(centre(s.media[0].boundary), {-2, 0, 0}, 1e-6, "body");
    expectNear(centre(s.media[1].boundary), {-2, 0, 0}, 1e-6, "core");
    expectNear(centre(s.media[2].boundary), {2, 0, 0}, 1e-6, "twin");
    EXPECT_EQ(s.media[0].boundary.triangles.size(), 320u);
    // The core nests in the body; the mirrored twin is still wound outward, so it nests in nothing.
    const MediaNesting nesting = nestMedia(s.media);
    EXPECT_EQ(nesting.parent, (std::vector<int32_t>{-1, 0, -1}));
}

TEST(GltfScene, ConvertedToJsonRendersTheSameImage) {
    const std::string dir = test::tempDir();
    GltfBuilder b = withCamera(0.6, 1.5);
    addFloor(b);
    b.addLight({{"type", "spot"}, {"intensity", 683 * 40}, {"spot", {{"outerConeAngle", 0.6}}}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}},
               {"translation", {0, 3, 0}},
               {"rotation", {-0.7071067811865476, 0, 0, 0.7071067811865476}}});
    const int absorbing = b.addMaterial(
        {{"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
           {"KHR_materials_volume", {{"attenuationColor", {0.9, 0.5, 0.2}}, {"attenuationDistance", 0.5}}}}},
         {"extras", {{"tetglow", {{"sigma_s", 1}, {"g", 0.2}}}}}});
    b.addNode({{"name", "Drop"}, {"mesh", b.addMesh(icosphere(2, 0.6), absorbing)}, {"translation", {0, -0.2, 0}}});
    const std::string glb = b.writeGlb(dir + "/drop.glb"), jsonPath = dir + "/out/drop.json";
    std::filesystem::create_directories(dir + "/out");
    const auto converted = test::runTetglow("convert " + glb + " -o " + jsonPath);
    ASSERT_EQ(converted.exitCode, 0) << converted.err;
    EXPECT_NE(converted.out.find("1 lights, 1 surfaces, 1 media"), std::string::npos) << converted.out;
    test::expectSameScene(loadScene(glb), loadScene(jsonPath));
    const std::string res = " --resolution 24x16";
    render(glb, dir + "/glb.exr", res);
    render(jsonPath, dir + "/json.exr", res);
    EXPECT_EQ(test::readFile(dir + "/glb.exr"), test::readFile(dir + "/json.exr"));
    EXPECT_EQ(relativeDifference(dir + "/glb.exr", dir + "/json.exr"), 0);  // and not black
}

// A .gltf is JSON, but not a tetglow scene: the preview saves it as the scene writer's JSON beside
// it, as a pbrt scene, and never edits the glTF itself.
TEST(GltfScene, PreviewSavesTheSceneAsJsonBesideIt) {
    const std::string dir = test::tempDir();
    GltfBuilder b = withCamera();
    addFloor(b);
    b.addLight({{"type", "point"}, {"intensity", 683}});
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 2, 0}}});
    const std::string gltf = b.writeGltf(dir + "/room.gltf"), before = test::readFile(gltf);
    test::PreviewProcess preview(gltf + " --port 0 --threads 1");
    const auto post = [&](const std::string& path, const std::string& body) {
        return test::rawHttp(preview.port(), test::httpRequest("POST", path, preview.port(),
                                                               {{"Content-Type", "application/json"}}, body));
    };
    const test::HttpReply saved = post("/save/scene", "{}");
    ASSERT_EQ(saved.status, 200) << saved.body;
    EXPECT_EQ(json::parse(saved.body)["scene"], dir + "/room-tuned-1.json");
    test::expectSameScene(loadScene(gltf), loadScene(dir + "/room-tuned-1.json"));
    EXPECT_NE(post("/save/scene", R"({"overwrite": true})").status, 200);
    EXPECT_EQ(test::readFile(gltf), before);
}

// Every malformed file is one line naming the file and the JSON pointer (or the GLB part).
TEST(GltfScene, MalformedFilesAreOneLineErrors) {
    const std::string dir = test::tempDir();
    GltfBuilder good = withCamera();
    addFloor(good);
    good.addLight({{"type", "point"}, {"intensity", 683}});
    good.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    ASSERT_NO_THROW(loadScene(good.writeGltf(dir + "/good.gltf")));
    struct Case {
        std::string name, expected;
        std::function<void(GltfBuilder&)> edit;
    };
    const std::vector<Case> cases = {
        {"count", "/accessors/0: the accessor's 9999 elements run past the end of its buffer view",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["accessors"][0]["count"] = 9999;
         }},
        {"index", "/meshes/0/primitives/0/indices: index 99 (element 0) is past the 4 vertices of POSITION",
         [](GltfBuilder& b) {
             const uint32_t past = 99;
             std::memcpy(&b.bin[b.json["bufferViews"][1]["byteOffset"].get<size_t>()], &past, 4);
         }},
        {"escape", "/buffers/0/uri: '../secret.bin' lies outside the model's folder: refusing to read it",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["buffers"][0]["uri"] = "../secret.bin";
         }},
        {"absolute", "/buffers/0/uri: '/etc/passwd' lies outside the model's folder: refusing to read it",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["buffers"][0]["uri"] = "/etc/passwd";
         }},
        // A link in the folder to a file elsewhere: read through it before, as if it were the buffer.
        {"link", "/buffers/0/uri: 'outside link.bin' lies outside the model's folder: refusing to read it",
         [&dir](GltfBuilder& b) {
             std::filesystem::remove(dir + "/outside link.bin");
             std::filesystem::create_symlink("/etc/hostname", dir + "/outside link.bin");
             b.json["buffers"][0]["uri"] = "outside%20link.bin";
         }},
        {"percent", "/buffers/0/uri: a '%' not followed by two hex digits",
         [](GltfBuilder& b) { b.json["buffers"][0]["uri"] = "mesh%2.bin"; }},
        {"scheme", "/buffers/0/uri: 'https://example.org/x.bin' is not a file in the glTF's folder",
         [](GltfBuilder& b) { b.json["buffers"][0]["uri"] = "https://example.org/x.bin"; }},
        {"length", "/buffers/0: byteLength is 100000, but the buffer holds",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["buffers"][0]["byteLength"] = 100000;
         }},
        {"huge", "/accessors/0/count: expected an integer in 1..402653184, got 1000000000",
         [](GltfBuilder& b) { b.json["accessors"][0]["count"] = 1000000000; }},
        {"flat", "/nodes/0: the camera's transform is singular (scale 0)",
         [](GltfBuilder& b) {
             b.json["nodes"][0]["scale"] = {1, 0, 1};
         }},
        {"cycle", "/nodes/0/children/0: node 0 is reached twice",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["nodes"][0]["children"] = {0};
         }},
        {"meshopt", "/extensionsRequired/0: the extension EXT_meshopt_compression is required but not read",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["extensionsRequired"] = {"EXT_meshopt_compression"};
         }},
        {"nocamera", "/scenes/0: the scene has no camera node",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["nodes"][0].erase("camera");
         }},
        {"version", "/asset/version: expected \"2.x\" (glTF 2.0), got \"1.0\"",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["asset"]["version"] = "1.0";
         }},
        {"material", "/meshes/0/primitives/0/material: expected an integer",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["meshes"][0]["primitives"][0]["material"] = "grey";
         }},
        {"attenuation", "/materials/0/extensions/KHR_materials_volume/attenuationColor: expected",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["materials"][0]["extensions"]["KHR_materials_volume"] = {{"attenuationColor", {0, 1, 1}}};
         }},
        {"spot", "/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle: expected a number in [0, 0.5]",
         [](GltfBuilder& b) {
             json& j = b.json;
             j["extensions"]["KHR_lights_punctual"]["lights"][0] = {
                 {"type", "spot"}, {"spot", {{"innerConeAngle", 0.7}, {"outerConeAngle", 0.5}}}};
         }},
    };
    for (const Case& c : cases) {
        GltfBuilder b = good;
        c.edit(b);
        const std::string path = b.writeGltf(dir + "/" + c.name + ".gltf");
        const std::string e = errorOf(path);
        EXPECT_EQ(e.rfind(path + ": " + c.expected, 0), 0u) << c.name << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << c.name;
    }
    // JSON past a scene file's 64 MiB is refused before it is parsed (parsed, it would take many times that).
    GltfBuilder big = good;
    big.json["extras"] = std::string(65 << 20, 'x');
    const std::string bigPath = big.writeGltf(dir + "/big.gltf");
    EXPECT_EQ(errorOf(bigPath).rfind(bigPath + ": its JSON is 65 MiB, larger than the 64 MiB limit for a scene", 0), 0u)
        << errorOf(bigPath);
    // A cut GLB, through the command line: one line, exit code 1.
    const std::string glb = good.writeGlb(dir + "/cut.glb");
    std::string bytes = test::readFile(glb);
    bytes.resize(bytes.size() - 9);
    const std::string cut = test::writeTemp("cut2.glb", bytes);
    const auto r = test::runTetglow("render " + cut + " -o " + dir + "/cut.exr");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "tetglow: error: " + cut + ": GLB container: the header gives a length of " +
                         std::to_string(bytes.size() + 9) + " bytes, the file has " + std::to_string(bytes.size()) +
                         "\n");
}

}  // namespace
}  // namespace tetglow
