// The render's progress on stderr, one line per pass: passes done, elapsed, time left and the
// noise estimate. Redrawn in place on a terminal; otherwise a line at every tenth of the way.
// A render that runs for a time or to a noise target also says where it will stop, warns when
// the noise estimate shows the pass cap comes first, and says which stop ended it.
#pragma once
#include <string>

#include "render/Renderer.h"

namespace tetglow::cli {

// Where the render stops: the first of these reached (0: no such limit).
struct RenderPlan {
    int passes = 0;
    std::string passesFrom;  // what set `passes`, for messages: "--spp", "the scene's spp", ...
    double timeLimit = 0, noiseTarget = 0;
    bool biased = false;  // the noise estimate leaves out a bias (photon integrator)
};

class Progress {
public:
    Progress(std::string label, RenderPlan plan);  // prints the stops of a timed or noise-driven render
    void pass(const PassReport& report);
    // Work counted otherwise than in passes (photons traced): `done` says how much, e.g.
    // "photons 1.68e+07 of 1.1e+12", `fraction` is the share of the way done.
    void work(const std::string& done, double fraction, double seconds);
    void finish();                            // ends the line on a terminal
    void finish(const RenderResult& result);  // ends the line on a terminal; says which stop ended it

private:
    bool openEnded() const { return plan_.timeLimit > 0 || plan_.noiseTarget > 0; }
    void line(const std::string& text);  // a line of its own, below a progress line redrawn in place

    std::string label_;
    RenderPlan plan_;
    bool terminal_;
    int lastTenth_ = -1;
    bool shown_ = false, warned_ = false;
};

// The passes the noisiest tile needs: `planned` once the pilot has planned them (PassReport::
// neededPasses), else the image's noise estimate of `noise` after `passes` passes scaled to the
// target (the relative MSE falls as 1 / passes), at least the pilot.
double passesForNoise(int passes, double noise, double target, double planned);
std::string passesInWords(double passes);

}  // namespace tetglow::cli
