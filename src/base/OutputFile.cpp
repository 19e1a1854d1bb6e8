#include "base/OutputFile.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include "base/Error.h"

namespace tetglow {
namespace fs = std::filesystem;
namespace {

// The temporaries being written, where a signal handler can read them: a slot is claimed
// (kWriting) while its path is copied in and published (kReady) only when complete.
enum SlotState { kFree, kWriting, kReady };
struct TemporarySlot {
    std::atomic<int> state{kFree};
    char path[4096];
};
TemporarySlot slots[16];

// The temporary of `path`, registered for removeTemporaries while it lives.
class Temporary {
public:
    explicit Temporary(const std::string& path) : path_(path + "." + std::to_string(::getpid()) + ".tmp") {
        if (path_.size() >= sizeof(slots[0].path)) return;
        for (auto& s : slots) {
            int expected = kFree;
            if (!s.state.compare_exchange_strong(expected, kWriting)) continue;
            std::memcpy(s.path, path_.c_str(), path_.size() + 1);
            s.state = kReady;
            slot_ = &s;
            return;
        }
    }
    ~Temporary() {
        std::error_code ec;
        fs::remove(path_, ec);  // gone already when renamed
        if (slot_) slot_->state = kFree;
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    TemporarySlot* slot_ = nullptr;
};

}  // namespace

void removeTemporaries() noexcept {
    for (auto& s : slots)
        if (s.state.load() == kReady) ::unlink(s.path);
}

void prepareOutput(const std::string& path, const std::vector<std::string>& inputs) {
    const fs::path target(path);
    std::error_code ec;
    if (path.empty() || !target.has_filename() || fs::is_directory(target, ec))
        throw InputError("'" + path + "': the output must name a file, not a folder");
    for (const auto& input : inputs)
        if (fs::equivalent(input, target, ec))
            throw InputError(path + ": the output is an input (" + input + "): refusing to overwrite it");
    const fs::path dir = target.parent_path();
    if (!dir.empty() && !fs::is_directory(dir, ec)) {
        fs::create_directories(dir, ec);
        if (ec) throw InputError(path + ": cannot create the folder " + dir.string() + ": " + ec.message());
    }
    // Found now, not after the work: the output is written as a new file in this folder.
    const std::string folder = dir.empty() ? "." : dir.string();
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(path + ": cannot write in the folder " + folder + ": " + std::strerror(errno));
}

void writeTogether(const std::vector<OutputWrite>& files) {
    for (const auto& file : files) {
        const fs::path dir = fs::path(file.path).parent_path();
        std::error_code ec;
        if (!dir.empty() && !fs::is_directory(dir, ec))
            throw InputError(file.path + ": the folder " + dir.string() + " does not exist");
    }
    std::vector<std::unique_ptr<Temporary>> temporaries;
    const std::string* current = nullptr;
    try {
        for (const auto& file : files) {
            current = &file.path;
            temporaries.push_back(std::make_unique<Temporary>(file.path));
            file.write(temporaries.back()->path());
        }
        for (size_t i = 0; i < files.size(); ++i) {
            current = &files[i].path;
            fs::rename(temporaries[i]->path(), files[i].path);
        }
    } catch (const fs::filesystem_error& e) {
        throw InputError(*current + ": cannot write: " + e.code().message());
    } catch (const std::exception& e) {
        throw InputError(*current + ": cannot write: " + oneLine(e.what()));
    }
}

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write) {
    writeTogether({{path, write}});
}

void writeStream(const std::string& path, const std::function<void(std::ostream& out)>& write) {
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throw std::runtime_error(std::strerror(errno));
        write(out);
        out.flush();
        if (!out) throw std::runtime_error("the write failed (is the disk full?)");
    });
}

}  // namespace tetglow
