// The photon walk against the published slab (van de Hulst's tables, as MCML uses them).
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestMeshes.h"
#include "evidence/Slab.h"

namespace tetglow::test {
namespace {

TEST(Slab, MatchesPublishedReflectanceAndTransmittance) {
    SlabParams p;  // tau 2, albedo 0.9, g 0.75
    p.photons = 400000;
    const SlabResult r = simulateSlab(p);
    EXPECT_NEAR(r.reflectance.mean, 0.09739, 3 * r.reflectance.stdError);
    EXPECT_NEAR(r.transmittance.mean, 0.66096, 3 * r.transmittance.stdError);
    EXPECT_LT(r.transmittance.stdError, 0.0015);  // fine enough to see a 0.5% error in Tt
    EXPECT_EQ(r.lost.mean, 0);                    // nothing reaches the sides of the wide box
    // Energy balance: what enters is reflected, transmitted or absorbed.
    const double sum = r.reflectance.mean + r.transmittance.mean + r.absorbed.mean;
    const double se = std::sqrt(std::pow(r.reflectance.stdError, 2) + std::pow(r.transmittance.stdError, 2) +
                                std::pow(r.absorbed.stdError, 2));
    EXPECT_NEAR(sum, 1.0, 3 * se);
}

TEST(Slab, NoScatteringGivesBeerLambert) {
    SlabParams p;
    p.tau = 1.5;
    p.albedo = 0;
    p.photons = 1000;
    const SlabResult r = simulateSlab(p);
    EXPECT_NEAR(r.transmittance.mean, std::exp(-1.5), 4 * r.transmittance.stdError + 1e-12);
    EXPECT_EQ(r.reflectance.mean, 0);
}

TEST(Slab, SameResultAnyThreadCount) {
    SlabParams p;
    p.photons = 20000;
    p.threads = 1;
    const SlabResult one = simulateSlab(p);
    p.threads = 2;
    const SlabResult two = simulateSlab(p);
    EXPECT_EQ(one.reflectance.mean, two.reflectance.mean);
    EXPECT_EQ(one.transmittance.mean, two.transmittance.mean);
}

// The largest photon count used to allocate one sum per block of 4096 photons at once (17 GB
// for 2^40) and had no time bound; now its blocks are summed a few thousand at a time and
// --time ends it with an error naming how far it got.
TEST(Slab, LargestPhotonCountEndsAtItsTimeLimit) {
    const auto r = runTetglow("validate slab --photons 1099511627776 --time 0.3");
    expectOneLineError(r, 1, "photons traced in --time 0.3 s: ask for fewer photons or more time");
    EXPECT_NE(r.err.find(" of 1099511627776 photons"), std::string::npos) << r.err;
}

// A run of days says so at the start, as render does: the photons traced, the seconds so far
// and the seconds left, on stderr, before --time ends it.
TEST(Slab, LongRunPrintsProgressAndTimeLeft) {
    const auto r = runTetglow("validate slab --photons 1099511627776 --time 2");
    expectOneLineError(r, 1, "photons traced in --time 2 s");
    const size_t line = r.err.find("validate slab: ");
    ASSERT_NE(line, std::string::npos) << "no progress line: " << r.err;
    const std::string progress = r.err.substr(line, r.err.find('\n', line) - line);
    EXPECT_NE(progress.find(" of 1.1e+12 photons, "), std::string::npos) << progress;
    EXPECT_NE(progress.find(" s left"), std::string::npos) << progress;
}

// A slab so thick and forward-scattering that a photon neither leaves nor is absorbed within the
// event cap: its flux would be missing from every tally, so the run is refused, not reported.
TEST(Slab, PhotonAtTheEventCapIsAnError) {
    SlabParams p;
    p.tau = 1e6;
    p.albedo = 1;
    p.g = 0.999999;
    p.photons = 2;
    try {
        simulateSlab(p);
        FAIL() << "a photon at the event cap was counted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("a photon scattered 1048576 times without leaving or being absorbed"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Slab, CommandPrintsJsonAndRejectsBadParameters) {
    const auto r = runTetglow("validate slab --tau 2 --albedo 0.9 --g 0.75 --photons 20000 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["Rd"]["mean"].get<double>(), 0.09739, 4 * j["Rd"]["std_error"].get<double>());
    EXPECT_NEAR(j["Tt"]["mean"].get<double>(), 0.66096, 4 * j["Tt"]["std_error"].get<double>());
    EXPECT_EQ(runTetglow("validate slab --g 1").exitCode, 2);
    EXPECT_EQ(runTetglow("validate slab --tau nan").exitCode, 2);
    EXPECT_EQ(runTetglow("validate slab --albedo -0.1").exitCode, 2);
}

}  // namespace
}  // namespace tetglow::test
