// What the preview's page may change: a cavity's coefficients stay zero (it holds no medium).
#include <gtest/gtest.h>

#include "TestScenes.h"
#include "cli/PreviewSettings.h"
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
        EXPECT_NE(std::string(e.what()).find("/cavities/0 is a cavity: it holds no medium to tune"), std::string::npos) << e.what();
    }
    EXPECT_EQ(settings.scene().media[1].sigmaS, RGB(0));
}

}  // namespace
}  // namespace tetglow::test
