// What the preview's page may change, checked as the loader checks a scene file: a cavity's
// coefficients stay zero (it holds no medium); the camera's view within the loader's ranges;
// the lights' emission in the file's own units, each light on or off. A save writes back only
// what changed.
#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "cli/PreviewSettings.h"
#include "scene/SceneLoader.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

TEST(PreviewSettings, ACavityHasNoCoefficientsToTune) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.1), RGB(1)), 8);
    MediumDesc bubble = desc.media[0];
    bubble.name = "/cavities/0";
    bubble.boundary = icosphere(1, 0.3);
    bubble.cavity = true;
    bubble.sigmaA = bubble.sigmaS = RGB(0);
    desc.media.push_back(bubble);
    desc.lights.push_back(environment(1));
    cli::PreviewSettings settings(desc);
    settings.apply(R"({"media": [{"sigma_s": 2}, {"g": 0.5}]})");  // the medium tunes; a cavity's phase is moot
    EXPECT_EQ(settings.scene().media[0].sigmaS, RGB(2));
    try {
        settings.apply(R"({"media": [{}, {"sigma_s": 1}]})");
        ADD_FAILURE() << "a cavity took a scattering coefficient";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/cavities/0 is a cavity: it holds no medium to tune"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(settings.scene().media[1].sigmaS, RGB(0));
}

// A sphere of medium under a spot light whose intensity is in units of its "scale", and a sky.
const std::string kScene = R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "resolution": [16, 16]},
  "lights": [{"type": "spot", "position": [0, 4, 0], "look_at": [0, 0, 0], "intensity": [1, 0.97, 0.9], "scale": 30},
             {"type": "environment", "radiance": 0.5}],
  "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_a": 0.5, "sigma_s": 1}]
})";

struct Loaded {
    SceneDesc desc;
    nlohmann::ordered_json file;
};
Loaded load(const std::string& text) {
    return {loadScene(test::writeTemp("scene.json", text)), nlohmann::ordered_json::parse(text)};
}

// The error a patch gets ("accepted" when none), checking that a refused one changes nothing.
std::string refusal(cli::PreviewSettings& settings, const std::string& patch) {
    const nlohmann::json before = settings.json();
    try {
        settings.apply(patch);
    } catch (const InputError& e) {
        EXPECT_EQ(settings.json(), before) << "a refused patch changed the settings: " << patch;
        return e.what();
    }
    return "accepted";
}

TEST(PreviewSettings, TheCameraMovesWithinTheLoadersRanges) {
    const Loaded scene = load(kScene);
    cli::PreviewSettings settings(scene.desc, scene.file);
    EXPECT_EQ(settings.json()["camera"],
              nlohmann::json::parse(R"({"position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40})"));
    settings.apply(R"({"camera": {"position": [1, 2, 3], "look_at": [0, 0.5, 0], "fov": 60}})");
    const CameraDesc& c = settings.scene().camera;
    EXPECT_EQ(c.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(c.lookAt, glm::dvec3(0, 0.5, 0));
    EXPECT_EQ(c.fov, 60);
    EXPECT_EQ(c.width, 16) << "the view changed the resolution";
    EXPECT_EQ(refusal(settings, R"({"camera": {"fov": 180}})"),
              "request: /camera/fov: expected a number in (0, 180), got 180");
    EXPECT_EQ(refusal(settings, R"({"camera": {"fov": "wide"}})"),
              R"(request: /camera/fov: expected a number in (0, 180), got "wide")");
    EXPECT_EQ(
        refusal(settings, R"({"camera": {"position": [1, 2, 3e12]}})").rfind("request: /camera/position: expected ", 0),
        0u);
    EXPECT_EQ(refusal(settings, R"({"camera": {"look_at": [1, 2, 3]}})"),
              R"(request: /camera/look_at: expected a point at least 1e-12 from "position", got [1,2,3])");
    EXPECT_EQ(refusal(settings, R"({"camera": {"position": [0, 5, 0], "look_at": [0, 0, 0]}})"),
              "request: /camera/up: the up direction must not be zero or parallel to the view direction (look_at - "
              "position)");
    EXPECT_EQ(refusal(settings, R"({"camera": {"resolution": [8, 8]}})"),
              "request: /camera/resolution: unknown key; allowed here: position, look_at, up, fov");
    EXPECT_EQ(refusal(settings, R"({"camera": null})"), "request: /camera: expected an object, got null");
    EXPECT_EQ(settings.scene().camera.fov, 60);
}

TEST(PreviewSettings, LightsKeepTheFilesUnits) {
    const Loaded scene = load(kScene);
    cli::PreviewSettings settings(scene.desc, scene.file);
    EXPECT_EQ(settings.lightNames(), (std::vector<std::string>{"spot", "environment"}));
    EXPECT_EQ(settings.json()["lights"],
              nlohmann::json::parse(R"([{"intensity": [1, 0.97, 0.9], "scale": 30, "on": true},
                                                                     {"radiance": [0.5, 0.5, 0.5], "scale": 1, "on": true}])"));
    settings.apply(R"({"lights": [{"intensity": [2, 1, 0.5]}, {"on": false}]})");
    EXPECT_EQ(settings.scene().lights[0].intensity, 30.0 * RGB(2, 1, 0.5)) << "not the loader's product";
    EXPECT_FALSE(settings.scene().lights[1].on);
    EXPECT_EQ(settings.scene().lights[1].radiance, RGB(0.5)) << "an off light lost its value";
    EXPECT_EQ(
        refusal(settings, R"({"lights": [{"intensity": -1}]})").rfind("request: /lights/0/intensity: expected ", 0),
        0u);
    EXPECT_EQ(refusal(settings, R"({"lights": [{"scale": 1e39}]})"),
              "request: /lights/0/scale: expected a number in [0, 3.40282e38], got 1e+39");
    EXPECT_EQ(refusal(settings, R"({"lights": [{"on": "yes"}]})"),
              R"(request: /lights/0/on: expected true or false, got "yes")");
    EXPECT_EQ(refusal(settings, R"({"lights": [{"position": [0, 9, 0]}]})"),
              "request: /lights/0/position: unknown key; allowed here: scale, intensity, on");
    EXPECT_EQ(refusal(settings, R"({"lights": [{}, {}, {}]})"),
              "request: /lights: expected an array of at most 2 lights, one per light of the scene, got [{},{},{}]");
    EXPECT_EQ(refusal(settings, R"({"lights": [{"on": false}]})"),
              "request: nothing emits light: turn a light on, or give it or a medium an emission");

    // Saved: only the keys changed, in the file's terms (the spot's scale stays its scale).
    nlohmann::ordered_json expected = scene.file;
    expected["lights"][0]["intensity"] = {2.0, 1.0, 0.5};
    expected["lights"][1]["on"] = false;
    EXPECT_EQ(settings.editedScene(scene.file), expected);
    // The sky's single number stays one; turned on again, "on" is as loaded and not written.
    settings.apply(R"({"lights": [{}, {"radiance": [0.25, 0.25, 0.25], "on": true}]})");
    expected["lights"][1] = {{"type", "environment"}, {"radiance", 0.25}};
    EXPECT_EQ(settings.editedScene(scene.file), expected);

    // A scene without a JSON file (pbrt): the loaded values, in units of 1.
    cli::PreviewSettings loaded(scene.desc);
    EXPECT_EQ(loaded.json()["lights"][0]["scale"], 1);
    EXPECT_EQ(loaded.json()["lights"][0]["intensity"], nlohmann::json::array({30.0, 30 * 0.97, 30 * 0.9}));
}

TEST(PreviewSettings, ASavedViewWritesOnlyTheKeysChanged) {
    const Loaded scene = load(kScene);
    cli::PreviewSettings settings(scene.desc, scene.file);
    settings.apply(R"({"camera": {"position": [0.5, 1, 4]}})");
    nlohmann::ordered_json expected = scene.file;
    expected["camera"]["position"] = {0.5, 1.0, 4.0};  // no "up": the file has none and it did not change
    EXPECT_EQ(settings.editedScene(scene.file), expected);
    settings.apply(R"({"camera": {"fov": 25.5}})");
    expected["camera"]["fov"] = 25.5;
    EXPECT_EQ(settings.editedScene(scene.file), expected);
}

// A medium's single numbers stay single numbers where the value saved is grey, as a light's do;
// a colour, or a key the file left out, is written as three.
TEST(PreviewSettings, AMediumsSingleNumbersStaySingle) {
    const Loaded scene = load(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40, "resolution": [16, 16]},
  "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_a": 0.5, "sigma_s": 2,
             "emission": 0.25, "scale": 2},
            {"shape": {"type": "sphere", "center": [3, 0, 0], "radius": 1}, "sigma_a": [0.1, 0.1, 0.1], "sigma_s": 1}]
})");
    cli::PreviewSettings settings(scene.desc, scene.file);
    // What the page sends: three channels, sigma_a and sigma_s with the file's scale applied.
    settings.apply(R"({"media": [{"sigma_a": [3, 3, 3], "sigma_s": [2, 4, 6], "emission": [0.5, 0.5, 0.5]},
                                 {"sigma_a": [0.2, 0.2, 0.2], "sigma_s": [3, 3, 3], "emission": [1, 1, 1]}]})");
    nlohmann::ordered_json expected = scene.file;
    expected["media"][0]["sigma_a"] = 1.5;  // in units of the scale, 2
    expected["media"][0]["sigma_s"] = {1.0, 2.0, 3.0};
    expected["media"][0]["emission"] = 0.5;
    expected["media"][1]["sigma_a"] = {0.2, 0.2, 0.2};  // three in the file: three
    expected["media"][1]["sigma_s"] = 3.0;
    expected["media"][1]["emission"] = {1.0, 1.0, 1.0};  // not in the file
    EXPECT_EQ(settings.editedScene(scene.file), expected);
    // A colour where the file had one number: three.
    settings.apply(R"({"media": [{"emission": [0.5, 0.25, 0.5]}]})");
    expected["media"][0]["emission"] = {0.5, 0.25, 0.5};
    EXPECT_EQ(settings.editedScene(scene.file), expected);
}

}  // namespace
}  // namespace tetglow::test
