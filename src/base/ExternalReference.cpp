#include "base/ExternalReference.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

#include "base/Error.h"

namespace tetglow {

namespace fs = std::filesystem;

namespace {

// Whether `path` is `folder` or lies below it, both with ".." and links resolved, compared
// component by component (a prefix of the text would take /a/bc for a file in /a/b).
bool inside(const fs::path& path, const fs::path& folder) {
    std::error_code pathError, folderError;
    const fs::path p = fs::weakly_canonical(path, pathError), f = fs::weakly_canonical(folder, folderError);
    if (pathError || folderError) return false;
    auto pi = p.begin();
    for (auto fi = f.begin(); fi != f.end() && !fi->empty(); ++fi, ++pi)  // empty: a trailing separator
        if (pi == p.end() || *pi != *fi) return false;
    return true;
}

}  // namespace

std::optional<std::string> percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out.push_back(uri[i]);
            continue;
        }
        if (i + 2 >= uri.size() || !std::isxdigit(uint8_t(uri[i + 1])) || !std::isxdigit(uint8_t(uri[i + 2])))
            return std::nullopt;
        out.push_back(char(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
        i += 2;
    }
    return out;
}

bool outsideReferencesAllowed() {
    const char* allow = std::getenv("TETGLOW_ALLOW_OUTSIDE_REFS");
    return allow && std::strcmp(allow, "1") == 0;
}

void checkReference(const fs::path& path, const std::string& reference, const fs::path& folder) {
    const fs::path base = folder.empty() ? fs::path(".") : folder;
    if (!outsideReferencesAllowed() && !inside(path, base))
        throw InputError(
            "'" + shorten(oneLine(reference), 200) +
            "' lies outside the model's folder: refusing to read it (TETGLOW_ALLOW_OUTSIDE_REFS=1 allows it)");
}

fs::path resolveReference(const fs::path& folder, const std::string& reference) {
    const fs::path path =
        fs::path(reference).is_absolute() || folder.empty() ? fs::path(reference) : folder / reference;
    checkReference(path, reference, folder);
    return path;
}

}  // namespace tetglow
