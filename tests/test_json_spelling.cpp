// A misspelt key or name in a scene file is named with what it may have meant: "did you mean",
// by the edit distance, in the unknown-key, missing-key and one-of errors.
#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "base/Spelling.h"
#include "scene/SceneLoader.h"

namespace tetglow::test {
namespace {

std::string loadError(const std::string& text) {
    try {
        loadScene(writeTemp("scene.json", text));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Spelling, EditDistanceCountsSwapsAsOneAndIgnoresCase) {
    EXPECT_EQ(editDistance("intensty", "intensity"), 1u);
    EXPECT_EQ(editDistance("fov", "fvo"), 1u);  // two neighbours swapped
    EXPECT_EQ(editDistance("Sigma_S", "sigma_s"), 0u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(nearestName("intensty", {"position", "intensity", "radius"}), "intensity");
    EXPECT_EQ(nearestName("colour", {"position", "intensity", "radius"}), "") << "nothing near";
    EXPECT_EQ(nearestName("radius", {"radius", "radiance"}), "") << "a word that is one of them";
    EXPECT_EQ(didYouMean(std::string(100000, 'x'), {"x"}), "") << "a 100 kB key is compared with nothing";
}

// As a user wrote it: "intensty" was reported as "/lights/0/intensity: missing".
TEST(Spelling, AMisspeltRequiredKeyIsNamedWithTheKeyItMeant) {
    const std::string error = loadError(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "lights": [{"type": "point", "position": [0, 3, 0], "intensty": 5}]})");
    EXPECT_NE(error.find("/lights/0/intensity: missing; expected "), std::string::npos) << error;
    EXPECT_NE(error.find("did you mean \"intensity\" where the file says \"intensty\"?"), std::string::npos) << error;
}

TEST(Spelling, AnUnknownKeyAndAnUnknownNameGetTheNearest) {
    const std::string unknown = loadError(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fvo": 30},
        "lights": [{"type": "environment", "radiance": 1}]})");
    EXPECT_NE(unknown.find("/camera/fvo: unknown key (did you mean \"fov\"?); allowed here: "), std::string::npos)
        << unknown;
    const std::string type = loadError(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
        "lights": [{"type": "pont", "position": [0, 3, 0], "intensity": 5}]})");
    EXPECT_NE(type.find("/lights/0/type: expected one of \"point\""), std::string::npos) << type;
    EXPECT_NE(type.find(", got \"pont\" (did you mean \"point\"?)"), std::string::npos) << type;
}

}  // namespace
}  // namespace tetglow::test
