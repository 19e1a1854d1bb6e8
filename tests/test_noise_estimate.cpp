// The noise estimate from two interleaved half-images: its closed form on a made-up film and its
// agreement with the error against a long reference (the noise target it plans adaptive sampling
// for: test_adaptive_sampling.cpp; the commands: test_render_cli.cpp).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "render/NoiseEstimate.h"
#include "render/Renderer.h"

namespace tetglow::test {
namespace {

// One pixel whose even passes all give a and odd ones b: the halves differ by a - b, and the
// full image's squared error is estimated as a quarter of that squared, relative to its mean,
// also where one half is many times the other (green: 1 and 20; blue: 0.5 and 0). The smaller
// half in its place made the photon-mapped fish's estimate 20 times its error.
TEST(NoiseEstimate, ClosedFormOnTwoValues) {
    Film all(1, 1), even(1, 1);
    EXPECT_TRUE(inFirstHalf(0) && !inFirstHalf(1) && inFirstHalf(2));
    const RGB a(1, 1, 0.5), b(3, 20, 0);
    const double converged[3] = {2, 10.5, 0.25};
    EXPECT_FALSE(estimateRelMse(all, even));
    for (int pass = 0; pass < 6; ++pass) {
        const RGB L = pass % 2 == 0 ? a : b;
        all.add(0, 0, L);
        if (pass % 2 == 0) even.add(0, 0, L);
    }
    double expected = 0;
    for (int c = 0; c < 3; ++c) {
        const double d = a[c] - b[c];
        expected += d * d / 4 / (converged[c] * converged[c] + kRelMseFloor) / 3;
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

// The estimate after 16 passes against the error measured against a render of 1024 passes
// (whose own error, a 64th of the render's, is part of what is measured), summed over six seeds.
// With independent halves the estimate has no bias: the sums agree. With one sequence over all
// passes the image is better than its halves predict (render/NoiseEstimate.cpp): the estimate is
// conservative.
TEST(NoiseEstimate, IndependentHalvesEstimateTheErrorWithoutBias) {
    const Scene scene(glowingSphereUnderQuad(24));
    for (const IntegratorType type : {IntegratorType::VolPath, IntegratorType::Single}) {
        SCOPED_TRACE(type == IntegratorType::VolPath ? "volpath" : "single");
        IntegratorDesc integ;
        integ.type = type;
        const auto integrator = makeIntegrator(scene, integ);
        RenderOptions options;
        options.spp = 1024;
        options.seed = 1;
        const Image reference = render(scene, *integrator, options).image;
        for (const bool independent : {true, false}) {
            double estimate = 0, truth = 0;
            options.spp = 16;
            options.independentHalves = independent;
            for (uint64_t seed = 2; seed < 8; ++seed) {
                options.seed = seed;
                const RenderResult result = render(scene, *integrator, options);
                ASSERT_TRUE(result.noise);
                estimate += *result.noise;
                truth += compare(result.image, reference).relMse;
            }
            std::printf("%s halves: estimate / error %.3f\n", independent ? "independent" : "stratified",
                        estimate / truth);
            if (independent)
                EXPECT_NEAR(estimate / truth, 1, 0.2);
            else
                EXPECT_GT(estimate / truth, 1.3);
        }
    }
}

}  // namespace
}  // namespace tetglow::test
