// The render's progress on stderr, one line per pass: passes done, elapsed, time left and the
// noise estimate. Redrawn in place on a terminal; otherwise a line at every tenth of the way.
#pragma once
#include <string>

#include "integrators/Renderer.h"

namespace tetglow::cli {

// Where the render stops: the first of these reached (0: no such limit).
struct RenderPlan {
    int passes = 0;
    double timeLimit = 0, noiseTarget = 0;
    bool biased = false;  // the noise estimate leaves out a bias (photon integrator)
};

class Progress {
public:
    Progress(std::string label, RenderPlan plan);
    void pass(const PassReport& report);
    // Work counted otherwise than in passes (photons traced): `done` says how much, e.g.
    // "photons 1.68e+07 of 1.1e+12", `fraction` is the share of the way done.
    void work(const std::string& done, double fraction, double seconds);
    void finish();  // ends the line on a terminal

private:
    // A line, unless it is not a terminal and the tenth of the way has not changed.
    void show(const std::string& done, double fraction, double seconds, const std::string& tail);

    std::string label_;
    RenderPlan plan_;
    bool terminal_;
    int lastTenth_ = -1;
    bool shown_ = false;
};

}  // namespace tetglow::cli
