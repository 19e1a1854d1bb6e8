// The noise estimate from two interleaved half-images: its closed form on a made-up film, its
// agreement with the error against a long reference, and `noiseTarget` stopping at the same pass
// on any thread count (the commands: test_render_cli.cpp).
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "integrators/Renderer.h"
#include "render/NoiseEstimate.h"

namespace tetglow::test {
namespace {

// One pixel whose even passes all give a and odd ones b: the halves differ by a - b, and the
// full image's squared error is estimated as a quarter of that squared, relative to its mean.
TEST(NoiseEstimate, ClosedFormOnTwoValues) {
    Film all(1, 1), even(1, 1);
    EXPECT_TRUE(inFirstHalf(0) && !inFirstHalf(1) && inFirstHalf(2));
    const RGB a(1, 2, 0.5), b(3, 2, 0);
    EXPECT_FALSE(estimateRelMse(all, even));
    for (int pass = 0; pass < 6; ++pass) {
        const RGB L = pass % 2 == 0 ? a : b;
        all.add(0, 0, L);
        if (pass % 2 == 0) even.add(0, 0, L);
    }
    double expected = 0;
    for (int c = 0; c < 3; ++c) {
        const double d = a[c] - b[c], mean = (a[c] + b[c]) / 2;
        expected += d * d / 4 / (mean * mean + kRelMseFloor) / 3;
    }
    ASSERT_TRUE(estimateRelMse(all, even));
    EXPECT_NEAR(*estimateRelMse(all, even), expected, 1e-12);
    // Equal halves: no noise seen.
    Film flat(1, 1), flatEven(1, 1);
    for (int pass = 0; pass < 4; ++pass) {
        flat.add(0, 0, a);
        if (pass % 2 == 0) flatEven.add(0, 0, a);
    }
    EXPECT_EQ(*estimateRelMse(flat, flatEven), 0);
}

// The estimate after n passes against the error measured against a render of 256 passes with
// another seed (whose own error is part of what is measured). The passes' stratification makes
// the true error smaller than independent samples would (render/NoiseEstimate.cpp): the estimate
// is at least the error and at most four times it.
TEST(NoiseEstimate, AgreesWithTheErrorAgainstALongReference) {
    const Scene scene(glowingSphereUnderQuad(24));
    for (const IntegratorType type : {IntegratorType::VolPath, IntegratorType::Single}) {
        SCOPED_TRACE(type == IntegratorType::VolPath ? "volpath" : "single");
        IntegratorDesc integ;
        integ.type = type;
        const auto integrator = makeIntegrator(scene, integ);
        RenderOptions options;
        options.spp = 256;
        options.seed = 1;
        const Image reference = render(scene, *integrator, options).image;
        for (const int passes : {4, 16}) {
            options.spp = passes;
            options.seed = 2;
            const RenderResult result = render(scene, *integrator, options);
            ASSERT_TRUE(result.noise);
            const double truth = compare(result.image, reference).relMse;
            EXPECT_GT(*result.noise, truth) << passes << " passes";
            EXPECT_LT(*result.noise, truth * 4) << passes << " passes";
        }
    }
}

TEST(NoiseEstimate, NoiseTargetStopsAtTheSamePassOnAnyThreadCount) {
    const Scene scene(glowingSphereUnderQuad(24));
    const auto integrator = makeIntegrator(scene, IntegratorDesc{});
    RenderOptions options;
    options.spp = 1000;
    options.seed = 5;
    options.noiseTarget = 0.01;
    options.threads = 1;
    const RenderResult one = render(scene, *integrator, options);
    options.threads = 2;
    const RenderResult two = render(scene, *integrator, options);
    EXPECT_GE(one.passes, 4);
    EXPECT_LT(one.passes, 1000);
    EXPECT_LE(*one.noise, 0.01);
    EXPECT_EQ(one.passes, two.passes);
    EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(),
                             one.image.pixels.size() * sizeof(one.image.pixels[0])));
}

}  // namespace
}  // namespace tetglow::test
