#include "cli/LiveRender.h"
#include "render/IntegratorFactory.h"

#include <algorithm>
#include <chrono>

#include "render/Renderer.h"

namespace tetglow {

LiveRender::LiveRender(std::unique_ptr<Scene> scene, int threads, double noiseTarget)
    : scene_(std::move(scene)), threads_(threads), noiseTarget_(noiseTarget), worker_([this] { work(); }) {}

LiveRender::~LiveRender() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        cancel_ = true;
    }
    wake_.notify_one();
    worker_.join();
}

uint64_t LiveRender::restart(const SceneDesc& desc) {
    std::lock_guard lock(mutex_);
    pending_ = desc;  // a change not yet started is simply replaced
    cancel_ = true;
    error_.clear();  // the last settings' failure, not these
    wake_.notify_one();
    return ++generation_;
}

std::shared_ptr<const LiveImage> LiveRender::latest() const {
    std::lock_guard lock(mutex_);
    return latest_;
}

std::string LiveRender::error() const {
    std::lock_guard lock(mutex_);
    return error_;
}

std::vector<std::string> LiveRender::warnings() const {
    std::lock_guard lock(mutex_);
    return warnings_;
}

void LiveRender::work() {
    for (;;) {
        SceneDesc desc;
        uint64_t generation = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return pending_ || stop_; });
            if (stop_) return;
            desc = std::move(*pending_);
            pending_.reset();
            generation = generation_;
            cancel_ = false;
        }
        try {
            renderGeneration(desc, generation);
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            if (generation == generation_) error_ = e.what();  // else settings came that may not fail
        }
    }
}

void LiveRender::renderGeneration(const SceneDesc& desc, uint64_t generation) {
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    scene_->retuneMedia(desc.media);
    scene_->retuneLights(desc.lights);
    RenderOptions options;
    options.seed = desc.integrator.seed;
    options.threads = threads_;
    options.cancel = &cancel_;

    // The quick look: a sixteenth of the pixels (the photon pass costs what it always does).
    CameraDesc quick = desc.camera;
    quick.width = std::max(1, (quick.width + 2) / 4);
    quick.height = std::max(1, (quick.height + 2) / 4);
    scene_->setCamera(quick);
    options.spp = 1;
    RenderResult look = render(*scene_, *makeIntegrator(*scene_, desc.integrator), options);
    if (look.cancelled) return;
    publish(std::move(look.image), 0, generation, seconds());

    // A fresh integrator, so that pass p is what `tetglow render --passes` renders as pass p.
    scene_->setCamera(desc.camera);
    const auto integrator = makeIntegrator(*scene_, desc.integrator);
    {
        std::lock_guard lock(mutex_);
        if (generation == generation_) warnings_ = integrator->warnings();
    }
    options.spp = desc.integrator.spp;   // where `tetglow render` stops too
    options.noiseTarget = noiseTarget_;  // and the passes each tile takes
    options.passDone = [&](const PassReport& p) { publish(p.film.image(), p.passes, generation, seconds()); };
    render(*scene_, *integrator, options);
}

void LiveRender::publish(Image image, int passes, uint64_t generation, double seconds) {
    std::lock_guard lock(mutex_);
    if (generation != generation_) return;  // settings changed while this pass ran
    auto live = std::make_shared<LiveImage>();
    live->image = std::move(image);
    live->passes = passes;
    live->seconds = seconds;
    live->version = ++version_;
    live->generation = generation;
    latest_ = std::move(live);
    error_.clear();
}

}  // namespace tetglow
