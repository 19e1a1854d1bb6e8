// Names for the files `tetglow preview` saves: "<stem>-<kind>-<n>" beside the scene, n one more
// than the largest the folder held when the kind was first saved (the folder is listed once,
// not at every save), never a name already taken, and at most a fixed number of saves in one
// run of the preview, so that no page, however often it asks, fills the disk.
#pragma once
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace tetglow::cli {

class PreviewSaves {
public:
    PreviewSaves(std::filesystem::path dir, std::string stem, int limit);
    // A free "<dir>/<stem>-<kind>-<n>": no "<that><ext>" exists for any of `extensions`.
    // Throws InputError after `limit` names.
    std::string next(const std::string& kind, const std::vector<std::string>& extensions);
    int limit() const { return limit_; }

private:
    int largestTaken(const std::string& base) const;

    const std::filesystem::path dir_;
    const std::string stem_;
    const int limit_;
    int made_ = 0;
    std::map<std::string, int> last_;  // kind -> the n last given (or found)
    std::mutex mutex_;
};

}  // namespace tetglow::cli
