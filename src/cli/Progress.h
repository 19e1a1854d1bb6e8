// Progress on stderr: a bar redrawn in place on a terminal, plain lines every 10% otherwise.
#pragma once
#include <chrono>
#include <string>

namespace tetglow::cli {

class Progress {
public:
    explicit Progress(std::string label);
    void update(double fraction);  // 0..1; cheap to call often
    void finish();                 // ends the bar's line

private:
    std::string label_;
    bool terminal_;
    int lastShown_ = -1;  // per mille on a terminal, tens of percent otherwise
    std::chrono::steady_clock::time_point start_;
};

}  // namespace tetglow::cli
