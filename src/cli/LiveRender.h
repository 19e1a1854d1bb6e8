// A render that starts again whenever its settings change (tetglow preview). A worker thread
// renders one pass at a quarter of the width and height first, for a quick look, then
// full-size progressive passes, up to the integrator's spp or the next change, publishing the
// image after each.
#pragma once
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render/Image.h"
#include "scene/Scene.h"

namespace tetglow {

struct LiveImage {
    Image image;
    int passes = 0;           // full-size passes in `image`; 0: the quarter-size quick look
    double seconds = 0;       // since the change
    uint64_t version = 0;     // rises with every image published
    uint64_t generation = 0;  // the settings shown: restart()'s count
};

class LiveRender {
public:
    // Renders nothing until the first restart(). threads: 0 for all cores. noiseTarget > 0:
    // adaptive sampling to it, the rule of `tetglow render --noise` (RenderOptions::noiseTarget).
    LiveRender(std::unique_ptr<Scene> scene, int threads, double noiseTarget = 0);
    ~LiveRender();
    LiveRender(const LiveRender&) = delete;
    LiveRender& operator=(const LiveRender&) = delete;

    // Renders `desc` from its first pass: the scene's geometry (the tets are kept) with desc's
    // media coefficients, light emission, camera and integrator. Returns the generation that shows it.
    uint64_t restart(const SceneDesc& desc);
    std::shared_ptr<const LiveImage> latest() const;  // null before the first image
    std::string error() const;  // why the render of the last restart() failed ("" when it did not)
    // The light its integrator cannot carry (Integrator::warnings), as of the last render started.
    std::vector<std::string> warnings() const;

private:
    void work();
    void renderGeneration(const SceneDesc& desc, uint64_t generation);
    void publish(Image image, int passes, uint64_t generation, double seconds);

    std::unique_ptr<Scene> scene_;  // the worker's alone
    const int threads_;
    const double noiseTarget_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<SceneDesc> pending_;
    uint64_t generation_ = 0, version_ = 0;
    bool stop_ = false;
    std::atomic<bool> cancel_{false};
    std::shared_ptr<const LiveImage> latest_;
    std::string error_;
    std::vector<std::string> warnings_;
    std::thread worker_;  // last: starts when everything else is ready
};

}  // namespace tetglow
