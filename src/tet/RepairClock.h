// The clock of one mesh's repair (InteriorRepair.h): a line on stderr as each stage of a long
// repair ends, so that a large input shows where its time goes, and the bound on its time, after
// which the repair stops with the stage and its figures, and the mesh is approximated instead
// (approximateSurface), so that no input keeps the user waiting without an answer.
#pragma once
#include <chrono>
#include <string>

#include "base/Error.h"

namespace tetglow {

// The default bound: the repair of the largest inputs measured (a 67-part engine of 111k
// triangles, 62k crossing pairs) takes about a third of it on 2 cores.
inline constexpr double kRepairTimeLimit = 45;

// The repair reached its time limit; what() names the stage and its figures.
struct RepairTimeout : InputError {
    using InputError::InputError;
};

class RepairClock {
public:
    explicit RepairClock(double limit = kRepairTimeLimit) : limit_(limit) {}

    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    // Seconds left before the bound, 0 once it is reached.
    double left() const;
    bool expired() const { return left() <= 0; }
    // At the end of a stage: `figures` ("crossings: 62,166 pairs found") on stderr once the repair
    // has taken kQuiet seconds, then RepairTimeout if the bound is reached.
    void stage(const std::string& figures) const;
    // RepairTimeout: "the repair reached its time limit of L s at <figures> in S s".
    [[noreturn]] void stop(const std::string& figures) const;

    static constexpr double kQuiet = 2;

private:
    const double limit_;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// n with its thousands grouped, as the figures are printed: 62,166.
std::string grouped(size_t n);

}  // namespace tetglow
