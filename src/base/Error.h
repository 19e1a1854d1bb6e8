// Errors in what the user gave (files, values) and the one-line messages that report them.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace tetglow {

// Input that cannot be used: broken meshes, bad files. The message is one line naming the problem.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Library messages can span lines; ours are one line.
inline std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

// An input echoed in a message, cut in the middle when longer than `max` characters, so that a
// 100 kB key or value still gives a readable line.
inline std::string shorten(const std::string& s, size_t max = 80) {
    if (s.size() <= max) return s;
    return s.substr(0, max / 2) + "...(" + std::to_string(s.size()) + " characters)..." + s.substr(s.size() - max / 4);
}

// Adds a warning for the user, shortened like an error; a machine-made file can repeat one mistake
// a million times, so after the first kMaxWarnings only one line says that more were dropped.
inline constexpr size_t kMaxWarnings = 100;
inline void addWarning(std::vector<std::string>& warnings, const std::string& message) {
    if (warnings.size() < kMaxWarnings)
        warnings.push_back(shorten(oneLine(message), 400));
    else if (warnings.size() == kMaxWarnings)
        warnings.push_back("tetglow: warning: more than 100 warnings; the rest are not shown");
}

}  // namespace tetglow
