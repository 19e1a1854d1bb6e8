#include "render/AdaptiveSampling.h"

#include <algorithm>
#include <cmath>

#include "render/NoiseEstimate.h"

namespace tetglow {

namespace {

// The passes one tile needs by its own pilot: its estimate's upper bound, the mean of its pixels'
// estimates plus two standard errors of that mean, scaled from the pilot's passes to the target.
// The pilot's estimate is itself noisy (8 samples a half), and planning by the mean alone left
// half the tiles above the target; a tile of a few heavy-tailed pixels gets the wider margin it
// needs. A serial sum in a fixed order: the same double on any thread count.
double tileNeeds(const Film& pilot, const Film& pilotHalf, int tx, int ty, int pilotPasses, double target) {
    double sum = 0, sumSquares = 0;
    int pixels = 0;
    for (int y = ty * kBudgetTile; y < std::min(pilot.height(), (ty + 1) * kBudgetTile); ++y)
        for (int x = tx * kBudgetTile; x < std::min(pilot.width(), (tx + 1) * kBudgetTile); ++x) {
            RelMseSum pixel;
            pixel.addPixel(pilot, pilotHalf, size_t(y) * pilot.width() + x);
            const double e = pixel.mean().value_or(0);
            sum += e;
            sumSquares += e * e;
            ++pixels;
        }
    const double mean = sum / pixels;
    const double variance = pixels > 1 ? std::max(0.0, sumSquares - sum * mean) / (pixels - 1) : 0;
    return std::max(double(pilotPasses), pilotPasses * (mean + 2 * std::sqrt(variance / pixels)) / target);
}

}  // namespace

SampleBudget SampleBudget::plan(const Film& pilot, const Film& pilotHalf, int pilotPasses, double target, int cap) {
    SampleBudget b;
    b.tilesX_ = (pilot.width() + kBudgetTile - 1) / kBudgetTile;
    const int tilesX = b.tilesX_, tilesY = (pilot.height() + kBudgetTile - 1) / kBudgetTile;
    std::vector<double> own(size_t(tilesX) * tilesY);
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx)
            own[size_t(ty) * tilesX + tx] = tileNeeds(pilot, pilotHalf, tx, ty, pilotPasses, target);
    b.passes_.resize(own.size());
    b.most_ = pilotPasses;
    b.needed_ = pilotPasses;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            // A tile takes what its noisiest neighbour needs (Cycles widens its unconverged
            // pixels the same way): rare bright paths that one tile's pilot missed are seldom
            // missed by all nine, and noisy regions are wider than a tile.
            double needed = 0;
            for (int ny = std::max(0, ty - 1); ny <= std::min(tilesY - 1, ty + 1); ++ny)
                for (int nx = std::max(0, tx - 1); nx <= std::min(tilesX - 1, tx + 1); ++nx)
                    needed = std::max(needed, own[size_t(ny) * tilesX + nx]);
            const double even = 2 * std::ceil(std::min(needed, double(cap)) / 2);
            const int passes = std::clamp(int(even), pilotPasses, std::max(cap, pilotPasses));
            b.passes_[size_t(ty) * tilesX + tx] = uint32_t(passes);
            b.most_ = std::max(b.most_, passes);
            b.needed_ = std::max(b.needed_, needed);
        }
    return b;
}

}  // namespace tetglow
