// Adaptive sampling to a noise target (as in Cycles: a minimum of samples everywhere, then each
// region's own noise estimate decides how many more it takes), with the rule fixed after a pilot:
// every pixel takes the first kPilotPasses passes; then each tile of kBudgetTile x kBudgetTile
// pixels gets the passes the noise estimates from the two pilot half-images say bring it and its
// eight neighbours to the target, and takes exactly passes 0 .. budget - 1. A pixel's samples
// stay indices 0 .. n - 1 of its own sequence, and the budgets are a function of the pilot's
// exact sums alone, so any thread count, and any split of the passes into parts that each
// replay the pilot, give the same bits.
#pragma once
#include <cstdint>
#include <vector>

#include "render/Film.h"

namespace tetglow {

inline constexpr int kPilotPasses = 16;  // 8 a half: the fewest whose tile estimate is trusted
inline constexpr int kBudgetTile = 8;

class SampleBudget {
public:
    // None: every pixel takes every pass.
    SampleBudget() = default;
    // From the pilot's film and its first half-image (passes 0 .. pilotPasses - 1, the halves
    // independent: RenderOptions::independentHalves). The relative MSE falls as 1 / passes, so a
    // tile whose estimate is e after the pilot needs pilotPasses * e / target passes; e is the
    // mean of its pixels' estimates plus two standard errors (the pilot's estimate is noisy, and
    // the target bounds every tile). A tile takes the most that it or a neighbour needs, rounded
    // up to an even count (equal halves), at least the pilot, at most `cap`.
    static SampleBudget plan(const Film& pilot, const Film& pilotHalf, int pilotPasses, double target, int cap);

    bool planned() const { return !passes_.empty(); }
    bool takes(int x, int y, int pass) const {
        return passes_.empty() || uint32_t(pass) < passes_[size_t(y / kBudgetTile) * tilesX_ + x / kBudgetTile];
    }
    int passes(int x, int y) const { return int(passes_[size_t(y / kBudgetTile) * tilesX_ + x / kBudgetTile]); }
    int mostPasses() const { return most_; }         // the largest budget: no pass after it has a sample
    double neededPasses() const { return needed_; }  // the largest before the cap

private:
    int tilesX_ = 0, most_ = 0;
    double needed_ = 0;
    std::vector<uint32_t> passes_;  // per tile, row-major
};

}  // namespace tetglow
