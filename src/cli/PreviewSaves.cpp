#include "cli/PreviewSaves.h"

#include <algorithm>
#include <cctype>

#include "base/Error.h"

namespace tetglow::cli {

namespace fs = std::filesystem;

PreviewSaves::PreviewSaves(fs::path dir, std::string stem, int limit)
    : dir_(std::move(dir)), stem_(std::move(stem)), limit_(limit) {}

// The largest n of the files named "<base><n>." or "<base><n>-..." (a save's files), 0 for none.
int PreviewSaves::largestTaken(const std::string& base) const {
    int largest = 0;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(dir_, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(base, 0) != 0) continue;
        size_t end = base.size();
        while (end < name.size() && end - base.size() < 9 && std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
        if (end > base.size() && end < name.size() && (name[end] == '.' || name[end] == '-'))
            largest = std::max(largest, std::stoi(name.substr(base.size(), end - base.size())));
    }
    return largest;
}

std::string PreviewSaves::next(const std::string& kind, const std::vector<std::string>& extensions) {
    std::lock_guard lock(mutex_);
    if (made_ >= limit_)
        throw InputError("not saved: this preview has saved " + std::to_string(limit_) +
                         " times, its limit (restart it to save more)");
    const std::string base = stem_ + "-" + kind + "-";
    auto found = last_.find(kind);
    if (found == last_.end()) found = last_.emplace(kind, largestTaken(base)).first;
    // Another program may have made a file since: a stat per extension, not a listing. Any
    // entry counts, a link to nothing too (a save would otherwise write where it leads).
    const auto taken = [&](const std::string& path) {
        return std::any_of(extensions.begin(), extensions.end(), [&](const std::string& ext) {
            std::error_code error;
            return fs::exists(fs::symlink_status(path + ext, error));
        });
    };
    std::string path;
    do path = (dir_ / (base + std::to_string(++found->second))).string();
    while (taken(path));
    ++made_;
    return path;
}

}  // namespace tetglow::cli
