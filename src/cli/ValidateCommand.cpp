// tetglow validate slab: the photon walk against published slab values.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "cli/Progress.h"
#include "evidence/Slab.h"

namespace tetglow::cli {
namespace {

struct Options {
    SlabParams slab;
    bool json = false;
};

void run(const Options& o) {
    SlabParams params = o.slab;
    Progress progress("validate slab", {});
    params.progress = [&](uint64_t traced, double seconds) {
        char done[64];
        std::snprintf(done, sizeof done, "%.3g of %.3g photons", double(traced), double(params.photons));
        progress.work(done, double(traced) / double(params.photons), seconds);
    };
    const SlabResult r = simulateSlab(params);
    progress.finish();
    if (o.json) {
        auto t = [](const Tally& x) { return nlohmann::json{{"mean", x.mean}, {"std_error", x.stdError}}; };
        const nlohmann::json j = {{"tau", o.slab.tau},
                                  {"albedo", o.slab.albedo},
                                  {"g", o.slab.g},
                                  {"photons", o.slab.photons},
                                  {"seed", o.slab.seed},
                                  {"Rd", t(r.reflectance)},
                                  {"Tt", t(r.transmittance)},
                                  {"absorbed", t(r.absorbed)},
                                  {"lost_sideways", t(r.lost)},
                                  {"tets", r.tets},
                                  {"seconds", r.seconds}};
        std::printf("%s\n", j.dump(2).c_str());
        return;
    }
    std::printf("slab tau %g, albedo %g, g %g: %llu photons through %llu tets in %.2f s\n", o.slab.tau, o.slab.albedo,
                o.slab.g, (unsigned long long)o.slab.photons, (unsigned long long)r.tets, r.seconds);
    std::printf("  diffuse reflectance Rd  = %.5f +- %.5f\n", r.reflectance.mean, r.reflectance.stdError);
    std::printf("  total transmittance Tt  = %.5f +- %.5f\n", r.transmittance.mean, r.transmittance.stdError);
    std::printf("  absorbed                = %.5f +- %.5f\n", r.absorbed.mean, r.absorbed.stdError);
    std::printf("  lost through the sides  = %.5f +- %.5f\n", r.lost.mean, r.lost.stdError);
    if (o.slab.tau == 2 && o.slab.albedo == 0.9 && o.slab.g == 0.75)
        std::printf(
            "  published (van de Hulst; MCML): Rd = 0.09739, Tt = 0.66096: off by %.1f and %.1f standard errors\n",
            (r.reflectance.mean - 0.09739) / r.reflectance.stdError,
            (r.transmittance.mean - 0.66096) / r.transmittance.stdError);
}

}  // namespace

void addValidateCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand("validate", "Check the light transport against published values");
    cmd->require_subcommand(1);
    auto* slab =
        cmd->add_subcommand("slab", "Slab with matched boundaries under collimated normal incidence: Rd and Tt");
    slab->add_option("--tau", o->slab.tau, "Optical thickness")->check(inRange(kPositive));
    slab->add_option("--albedo", o->slab.albedo, "Single-scattering albedo")->check(inRange({.lo = 0, .hi = 1}));
    slab->add_option("--g", o->slab.g, "Henyey-Greenstein asymmetry, in (-1, 1)")
        ->check(inRange({.lo = -0.999999, .hi = 0.999999}));
    slab->add_option("--photons", o->slab.photons, "Photons traced")->check(CLI::Range(uint64_t(2), uint64_t(1) << 40));
    slab->add_option("--seed", o->slab.seed, "Random seed")->check(inIntegers(0, INT64_MAX));
    slab->add_option("--time", o->slab.timeLimit,
                     "An error when the photons are not all traced within this many seconds")
        ->check(inRange(kPositive));
    slab->add_option("--threads", o->slab.threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
    slab->add_flag("--json", o->json, "Print one JSON object");
    slab->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
