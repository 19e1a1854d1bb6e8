#include "base/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <random>

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

// Twelve letters and digits (71 bits) from the system's random source: a name another user
// cannot guess to plant a link at.
std::string unguessable() {
    static constexpr char kSymbols[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::random_device random;
    std::string name;
    for (int i = 0; i < 12; ++i) name += kSymbols[random() % (sizeof kSymbols - 1)];
    return name;
}

[[noreturn]] void fail(const char* what, const std::string& path) {
    throw fs::filesystem_error(what, path, std::error_code(errno, std::generic_category()));
}

// The temporary of a file: created new (O_EXCL: never through a link, never over a file that
// is there) beside it, and registered for removeTemporaries while it lives.
class Temporary {
public:
    explicit Temporary(const fs::path& target) {
        int fd = -1;
        for (int attempt = 0; fd < 0; ++attempt) {
            path_ = target.string() + "." + unguessable() + ".tmp";
            fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
            if (fd < 0 && (errno != EEXIST || attempt == 100)) fail("cannot create a temporary", path_);
        }
        ::close(fd);
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
        if (!renamed_) ::unlink(path_.c_str());
        if (slot_) slot_->state = kFree;
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;
    const std::string& path() const { return path_; }

    // Once written: the permissions of the file it replaces (set by name, not on a descriptor
    // kept from the creation: a writer may itself replace the temporary with one of its own).
    void keepPermissions(const fs::path& target) const {
        struct stat old {
        }, now{};
        if (::stat(target.c_str(), &old) == 0 && S_ISREG(old.st_mode) && ::lstat(path_.c_str(), &now) == 0 &&
            S_ISREG(now.st_mode) && ::chmod(path_.c_str(), old.st_mode & 07777) != 0)
            fail("cannot set the permissions of", path_);
    }
    void rename(const fs::path& target) {
        fs::rename(path_, target);
        renamed_ = true;
    }

private:
    std::string path_;
    bool renamed_ = false;
    TemporarySlot* slot_ = nullptr;
};

// What a link at `path` leads to; nullopt where `path` is no link. InputError for a link that
// leads to no file.
std::optional<fs::path> linkTarget(const std::string& path) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(path, ec))) return std::nullopt;
    fs::path target = fs::canonical(path, ec);
    if (ec) {
        const std::string why = ec.message();
        throw InputError(path + ": is a link to " + fs::read_symlink(path, ec).string() + ", which leads to no file (" +
                         why + "): refusing to write through it");
    }
    return target;
}

// Where `file` is written: its path, or the file a link there leads to (OutputWrite).
fs::path destination(const OutputWrite& file) {
    std::error_code ec;
    if (!file.named && fs::is_symlink(fs::symlink_status(file.path, ec)))
        throw InputError(file.path + ": is a link, and tetglow chose this name: refusing to write through it");
    const std::optional<fs::path> target = linkTarget(file.path);
    return target ? *target : fs::path(file.path);
}

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
    const std::optional<fs::path> linked = linkTarget(path);
    const fs::path dir = (linked ? *linked : target).parent_path();
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
    std::vector<fs::path> destinations;
    for (const auto& file : files) {
        destinations.push_back(destination(file));
        const fs::path dir = destinations.back().parent_path();
        std::error_code ec;
        if (!dir.empty() && !fs::is_directory(dir, ec))
            throw InputError(file.path + ": the folder " + dir.string() + " does not exist");
    }
    std::vector<std::unique_ptr<Temporary>> temporaries;
    const std::string* current = nullptr;
    try {
        for (size_t i = 0; i < files.size(); ++i) {
            current = &files[i].path;
            temporaries.push_back(std::make_unique<Temporary>(destinations[i]));
            files[i].write(temporaries.back()->path());
            temporaries.back()->keepPermissions(destinations[i]);
        }
        for (size_t i = 0; i < files.size(); ++i) {
            current = &files[i].path;
            temporaries[i]->rename(destinations[i]);
        }
    } catch (const fs::filesystem_error& e) {
        throw InputError(*current + ": cannot write: " + e.code().message());
    } catch (const std::exception& e) {
        throw InputError(*current + ": cannot write: " + oneLine(e.what()));
    }
}

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write,
                     bool named) {
    writeTogether({{path, write, named}});
}

OutputWrite streamWrite(const std::string& path, std::function<void(std::ostream& out)> write, bool named) {
    return {path,
            [write = std::move(write)](const std::string& temporary) {
                std::ofstream out(temporary, std::ios::binary);
                if (!out) throw std::runtime_error(std::strerror(errno));
                write(out);
                out.flush();
                if (!out) throw std::runtime_error("the write failed (is the disk full?)");
            },
            named};
}

void writeStream(const std::string& path, const std::function<void(std::ostream& out)>& write, bool named) {
    writeTogether({streamWrite(path, write, named)});
}

}  // namespace tetglow
