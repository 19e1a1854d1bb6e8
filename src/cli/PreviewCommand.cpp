// tetglow preview SCENE: a local web page that shows the render refining pass after pass and
// tunes the media, lights, camera and integrator while it runs (cpp-httplib). The server answers only its
// own page (compiled in from web/), the current image, the settings and two saves whose file
// names it chooses itself; every other request gets 404. Who may ask: PreviewAccess.h.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <regex>
#include <thread>

#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <httplib.h>

#include "WebFiles.h"
#include "base/Hash.h"
#include "base/InputFile.h"
#include "cli/Commands.h"
#include "cli/LiveRender.h"
#include "cli/MediaReport.h"
#include "cli/PreviewAccess.h"
#include "cli/PreviewSaves.h"
#include "cli/PreviewSettings.h"
#include "render/ImageIO.h"
#include "scene/GltfScene.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

struct Options {
    std::string scene, camera, host = "127.0.0.1";
    int port = 8080, threads = 0;
    double noise = 0;
};

constexpr Range kExposure{.lo = -20, .hi = 20};
constexpr size_t kMaxRequestBytes = 64 * 1024;
constexpr int kMaxSaves = 100;  // scenes and images together, in one run
// One thread per connection up to this many: a few slow or idle clients cannot hold every
// thread (each waits at most kReadTimeoutSeconds for each byte, and the connection closes after
// one request, so no idle keep-alive connection holds one either).
constexpr size_t kConnectionThreads = 64;
constexpr time_t kReadTimeoutSeconds = 2;

std::atomic<bool> stopRequested{false};
void onStop(int) { stopRequested = true; }

std::string contentType(const std::string& file) {
    const std::string ext = fs::path(file).extension().string();
    if (ext == ".html") return "text/html; charset=utf-8";
    if (ext == ".js") return "text/javascript; charset=utf-8";
    if (ext == ".css") return "text/css; charset=utf-8";
    return "application/octet-stream";
}

void sendJson(httplib::Response& res, const Json& j, int status = 200) {
    res.status = status;
    res.set_content(j.dump(), "application/json");
}

void sendError(httplib::Response& res, const std::string& message, int status = 400) {
    sendJson(res, {{"error", message}}, status);
}

// The exposure a request asks for ("exposure" in the query or the JSON body), 0 when absent.
double exposureOf(const std::string& text) {
    if (text.empty()) return 0;
    const Json j = parseJson(text, "request");
    return JsonValue(&j, Json::json_pointer(), "request").readObject([](JsonObject& o) {
        const JsonValue e = o["exposure"];
        return e ? e.number(kExposure) : 0.0;
    });
}

// A true/false key of a request's JSON body ("" and absent: false).
bool flagOf(const std::string& text, const char* key) {
    if (text.empty()) return false;
    const Json j = parseJson(text, "request");
    return JsonValue(&j, Json::json_pointer(), "request").readObject([&](JsonObject& o) {
        const JsonValue v = o[key];
        return v && v.boolean();
    });
}

// The scene file's text as JSON, keys in their order, or null for a pbrt or glTF scene (saved as
// the scene writer's JSON beside it).
nlohmann::ordered_json jsonScene(const std::string& path, const std::string& text) {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(text, nullptr, false, true);
    const bool gltf = doc.is_object() && doc.contains("asset") && !doc.contains("camera");
    return doc.is_discarded() || gltf || looksLikeGltf(path, text) ? nlohmann::ordered_json() : doc;
}

// A file as the preview read it, to tell whether it changed on disk since: its time of last
// change and a hash of its bytes (a change within the clock's resolution keeps the time).
struct FileVersion {
    fs::file_time_type time;
    uint64_t hash = 0;
    bool operator==(const FileVersion& o) const { return time == o.time && hash == o.hash; }
};

FileVersion versionOf(const std::string& path, const std::string& text) {
    std::error_code error;
    return {fs::last_write_time(path, error), fnv1a(kFnvOffset, text.data(), text.size())};
}

// A glTF scene is never saved over, and a GLB may be larger than any scene file.
std::string readScene(const std::string& path) {
    return looksLikeGltf(path, "") ? "" : readInputFile(path, kMaxSceneFileBytes, "a scene file");
}

class PreviewServer {
public:
    PreviewServer(const std::string& scenePath, const SceneDesc& desc)
        : PreviewServer(scenePath, desc, readScene(scenePath)) {}

    PreviewServer(const std::string& scenePath, const SceneDesc& desc, const std::string& text)
        : scenePath_(fs::absolute(scenePath).string()),
          original_(jsonScene(scenePath, text)),
          read_(versionOf(scenePath_, text)),
          saves_(fs::absolute(scenePath).parent_path(), fs::path(scenePath).stem().string(), kMaxSaves),
          settings_(desc, original_),
          good_(settings_),
          before_(settings_) {
        routes();
    }

    // Before the scene is built, so that a taken port costs no tetrahedralization.
    int bind(const std::string& host, int port) {
        // SO_REUSEADDR alone: a restart may take a port whose old connections linger in
        // TIME_WAIT, but a port another server listens on is refused. (httplib's default adds
        // SO_REUSEPORT, with which a second preview binds the same port and takes half the requests.)
        server_.set_socket_options([](socket_t s) {
            const int yes = 1;
            setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
        });
        const int bound = port == 0 ? server_.bind_to_any_port(host) : (server_.bind_to_port(host, port) ? port : -1);
        if (bound < 0)
            throw InputError("cannot listen on " + host + ":" + std::to_string(port) +
                             " (in use, or not an address of this machine)");
        host_ = host;
        port_ = bound;
        return bound;
    }

    // Renders the scene and serves until SIGINT or SIGTERM.
    void serve(std::unique_ptr<Scene> scene, int threads, double noise, const std::string& url) {
        live_ = std::make_unique<LiveRender>(std::move(scene), threads, noise);
        {
            std::lock_guard lock(settingsMutex_);
            generation_ = live_->restart(settings_.scene());
        }
        std::printf("preview: %s (Ctrl-C stops)\n", url.c_str());
        std::fflush(stdout);
        std::atomic<bool> served{false};
        std::thread watcher([&] {
            while (!stopRequested) std::this_thread::sleep_for(std::chrono::milliseconds(100));
            // httplib stops only a server that is running: a signal that came between the URL
            // and the start of listening would be lost, and the server would serve on.
            while (!served && !server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
            if (!served) server_.stop();
        });
        server_.listen_after_bind();
        served = true;
        stopRequested = true;
        watcher.join();
    }

private:
    void routes() {
        server_.set_payload_max_length(kMaxRequestBytes);
        server_.new_task_queue = [] { return new httplib::ThreadPool(kConnectionThreads); };
        server_.set_keep_alive_max_count(1);
        server_.set_read_timeout(kReadTimeoutSeconds);
        // Before a byte of the body is read.
        server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
            Refusal refusal = accessRefusal(req, host_, port_);
            if (!refusal.status && req.has_header("Content-Length") &&
                req.get_header_value<uint64_t>("Content-Length") > kMaxRequestBytes)
                refusal = {413, tooLarge()};
            if (!refusal.status) return httplib::Server::HandlerResponse::Unhandled;
            sendError(res, refusal.message, refusal.status);
            return httplib::Server::HandlerResponse::Handled;
        });
        for (const web::File& file : web::kFiles) {
            const std::string name = file.name;
            const std::string body(reinterpret_cast<const char*>(file.bytes), file.size);
            const std::string type = contentType(name);
            // httplib's patterns are regular expressions: the name's dots must match dots only.
            const std::string pattern =
                name == "index.html" ? "/" : "/" + std::regex_replace(name, std::regex("\\."), "\\.");
            server_.Get(pattern,
                        [body, type](const httplib::Request&, httplib::Response& res) { res.set_content(body, type); });
        }
        server_.Get("/state", [this](const httplib::Request&, httplib::Response& res) { sendJson(res, state()); });
        server_.Get("/image.png", [this](const httplib::Request& req, httplib::Response& res) { image(req, res); });
        post("/settings", [this](const std::string& body, httplib::Response& res) { change(body, res); });
        post("/save/scene", [this](const std::string& body, httplib::Response& res) { saveScene(body, res); });
        post("/save/image", [this](const std::string& body, httplib::Response& res) { saveImage(body, res); });
        server_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
            if (!res.body.empty()) return;
            // httplib's own limits on the request line and on each header line (8 KiB).
            const std::string lineLimit = std::to_string(CPPHTTPLIB_HEADER_MAX_LENGTH) + " bytes";
            sendError(res,
                      res.status == 404   ? "not found"
                      : res.status == 413 ? tooLarge()
                      : res.status == 414
                          ? "request line too long: at most " + lineLimit
                          : "bad request: a malformed request line or header, or a header line over " + lineLimit,
                      res.status);
        });
        server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
            try {
                std::rethrow_exception(e);
            } catch (const InputError& error) {
                sendError(res, error.what());
            } catch (const std::exception& error) {
                sendError(res, error.what(), 500);
            }
        });
    }

    static std::string tooLarge() {
        return "request too large: at most " + std::to_string(kMaxRequestBytes) + " bytes";
    }

    // A POST route whose body is read here, kMaxRequestBytes at most, also when it comes in
    // chunks (httplib checks only a Content-Length against its limit): reading stops at the first
    // byte too many, and the connection closes.
    void post(const std::string& path, std::function<void(const std::string&, httplib::Response&)> handler) {
        server_.Post(path,
                     [handler](const httplib::Request&, httplib::Response& res, const httplib::ContentReader& read) {
                         std::string body;
                         bool over = false;
                         const bool complete = read([&](const char* data, size_t size) {
                             over = body.size() + size > kMaxRequestBytes;
                             if (!over) body.append(data, size);
                             return !over;
                         });
                         if (over) return sendError(res, tooLarge(), 413);
                         if (!complete) return sendError(res, "bad request: the body is incomplete", 400);
                         handler(body, res);
                     });
    }

    Json state() {
        Json j;
        const auto live = live_->latest();
        {
            std::lock_guard lock(settingsMutex_);
            followRender(live.get());
            j["settings"] = settings_.json();
            j["media_names"] = settings_.mediumNames();
            j["light_names"] = settings_.lightNames();
            j["generation"] = generation_;
            j["render_error"] = renderError_.empty() ? live_->error() : renderError_;
            j["warnings"] = live_->warnings();
        }
        j["image"] = nullptr;
        if (live)
            j["image"] = {{"version", live->version}, {"generation", live->generation}, {"passes", live->passes},
                          {"seconds", live->seconds}, {"width", live->image.width},     {"height", live->image.height}};
        return j;
    }

    // Settings whose first full-size pass rendered are good. Settings whose render failed (a
    // value that overflows the film, say) give way to those before the change that failed, so
    // an earlier change that had no pass yet is kept; they are rendered in turn, and if they
    // fail too, the last good ones follow. The error names the values undone. (settingsMutex_ held.)
    void followRender(const LiveImage* live) {
        if (live && live->generation == generation_ && live->passes > 0 && !atGood_) {
            good_ = settings_;
            atGood_ = true;
        }
        const std::string error = live_->error();
        if (error.empty() || atGood_) return;
        renderError_ = settings_.changesFrom(before_) + ": " + error + " (back to the values before)";
        settings_ = before_;
        atGood_ = beforeGood_;
        before_ = good_;
        beforeGood_ = true;
        generation_ = live_->restart(settings_.scene());
    }

    void image(const httplib::Request& req, httplib::Response& res) {
        double exposure = 0;
        if (req.has_param("exposure")) {
            // Checked as JSON: a number in range, or the loader's one-line error.
            exposure = exposureOf("{\"exposure\": " + req.get_param_value("exposure") + "}");
        }
        const auto live = live_->latest();
        if (!live) return sendError(res, "no image yet", 503);
        const std::vector<uint8_t> png = encodePng(live->image, exposure);
        res.set_header("Cache-Control", "no-store");
        res.set_content(std::string(png.begin(), png.end()), "image/png");
    }

    void change(const std::string& body, httplib::Response& res) {
        std::lock_guard lock(settingsMutex_);
        PreviewSettings changed = settings_;
        changed.apply(body);  // InputError: 400 with the message, settings unchanged
        before_ = std::move(settings_);
        beforeGood_ = atGood_;
        settings_ = std::move(changed);
        generation_ = live_->restart(settings_.scene());
        atGood_ = false;
        renderError_.clear();
        sendJson(res, {{"generation", generation_}, {"settings", settings_.json()}});
    }

    // A JSON scene: the user's file with only the values changed ({"overwrite": true}: over it,
    // else as <scene>-tuned-<n>.json beside it, so its mesh references hold). A pbrt or glTF scene: the
    // scene writer's JSON, its meshes beside it.
    void saveScene(const std::string& body, httplib::Response& res) {
        const bool overwrite = flagOf(body, "overwrite");
        std::lock_guard lock(saveMutex_);
        std::lock_guard settingsLock(settingsMutex_);
        if (overwrite && original_.is_null())
            return sendError(res, "not saved: a pbrt or glTF scene is saved as JSON beside it, never over it");
        if (overwrite) checkOverwrite();
        const std::string path = overwrite ? scenePath_ : saves_.next("tuned", {".json"}) + ".json";
        if (original_.is_null()) {
            writeScene(settings_.scene(), path);
        } else {
            const std::string text = sceneJsonText(settings_.editedScene(original_));
            // The loader's checks on the very text, so that no save leaves a scene it refuses
            // (a coefficient over the float range once divided by the medium's "scale", say).
            try {
                loadJsonSceneText(text, path);
            } catch (const InputError& e) {
                throw InputError(std::string("not saved: the scene would not load: ") + e.what());
            }
            writeStream(
                path, [&](std::ostream& out) { out << text; }, overwrite);  // a numbered name: no link
            if (overwrite) read_ = versionOf(scenePath_, text);
        }
        sendJson(res, {{"scene", path}});
    }

    // "Save over the original" keeps what is on disk unless the preview read it: an edit made to
    // the file while the preview ran, and a file made read-only, are refused, not overwritten.
    void checkOverwrite() const {
        std::string text;
        try {
            text = readScene(scenePath_);
        } catch (const InputError& e) {
            throw InputError(std::string("not saved: cannot read the scene again: ") + e.what());
        }
        if (!(versionOf(scenePath_, text) == read_))
            throw InputError("not saved: " + scenePath_ +
                             " changed on disk since the preview read it; save a copy, or restart the preview to "
                             "tune the file as it is now");
        struct stat st {};
        if (::access(scenePath_.c_str(), W_OK) != 0 || (::stat(scenePath_.c_str(), &st) == 0 && !(st.st_mode & 0222)))
            throw InputError("not saved: " + scenePath_ + " is read-only; save a copy instead");
    }

    void saveImage(const std::string& body, httplib::Response& res) {
        const double exposure = exposureOf(body);
        const auto live = live_->latest();
        if (!live) return sendError(res, "no image yet", 503);
        std::lock_guard lock(saveMutex_);
        const std::string exr = saves_.next("image", {".exr", ".png"}) + ".exr";
        writeExrAndPng(exr, live->image, exposure);
        sendJson(res,
                 {{"exr", exr}, {"png", previewPath(exr)}, {"passes", live->passes}, {"generation", live->generation}});
    }

    const std::string scenePath_;
    const nlohmann::ordered_json original_;  // the JSON scene file as read; null for pbrt and glTF
    FileVersion read_;                       // the scene file as read, or as last saved over
    PreviewSaves saves_;
    std::string host_;  // what the server is bound to, from bind() on
    int port_ = 0;
    std::mutex settingsMutex_, saveMutex_;
    PreviewSettings settings_, good_;  // good_: the last that rendered
    PreviewSettings before_;           // settings_ before the last change
    bool atGood_ = true;               // settings_ are good_ (the loaded scene counts as good)
    bool beforeGood_ = true;           // before_ are good_
    std::string renderError_;          // why the settings went back, until the next change
    uint64_t generation_ = 0;
    std::unique_ptr<LiveRender> live_;  // from serve() on, before any request is read
    httplib::Server server_;
};

void run(const Options& o) {
    const SceneDesc desc = loadScene(o.scene, o.camera);
    PreviewServer server(o.scene, desc);
    const int port = server.bind(o.host, o.port);
    auto scene = std::make_unique<Scene>(desc);
    printVolumes(*scene);
    std::signal(SIGINT, onStop);
    std::signal(SIGTERM, onStop);
    server.serve(std::move(scene), o.threads, o.noise, "http://" + o.host + ":" + std::to_string(port) + "/");
}

}  // namespace

void addPreviewCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "preview",
        "Serve a local web page that renders the scene live while its media, lights, camera and integrator are tuned");
    cmd->add_option("scene", o->scene, "Scene file: JSON, pbrt-v3 (.pbrt) or glTF 2.0 (.gltf, .glb)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--camera", o->camera, "glTF scene: the camera node to look through (default: the first)")
        ->check(kNonEmpty);
    cmd->add_option("--port", o->port, "TCP port (0: any free one; the URL printed says which)")
        ->check(CLI::Range(0, 65535));
    cmd->add_option("--host", o->host, "Address to listen on (default 127.0.0.1: this machine only)");
    cmd->add_option("--threads", o->threads, "Render threads (default: all cores)")->check(CLI::Range(1, 1024));
    cmd->add_option("--noise", o->noise,
                    "Adaptive sampling as in `render --noise`: each 8x8 tile takes the passes that bring it to this "
                    "estimated relative MSE")
        ->check(inRange(kPositive));
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
