#include "base/Spelling.h"

#include <algorithm>
#include <cctype>

namespace tetglow {

size_t editDistance(std::string_view a, std::string_view b) {
    auto same = [](char x, char y) { return std::tolower((unsigned char)x) == std::tolower((unsigned char)y); };
    // Three rows of the table: a swap looks two rows back.
    std::vector<size_t> back(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + !same(a[i - 1], b[j - 1])});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                current[j] = std::min(current[j], back[j - 2] + 1);
        }
        std::swap(back, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string nearestName(std::string_view word, const std::vector<std::string_view>& candidates) {
    // Long words (a 100 kB key) are compared with nothing: no name is that long.
    constexpr size_t kLongest = 64;
    if (word.size() > kLongest) return "";
    const size_t allowed = std::max<size_t>(1, word.size() / 3);
    std::string_view best;
    size_t bestDistance = allowed + 1;
    for (std::string_view c : candidates) {
        if (c == word) return "";
        if (c.size() > kLongest) continue;
        const size_t d = editDistance(word, c);
        if (d < bestDistance) {
            best = c;
            bestDistance = d;
        }
    }
    return std::string(best);
}

std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates) {
    const std::string name = nearestName(word, candidates);
    return name.empty() ? "" : " (did you mean \"" + name + "\"?)";
}

}  // namespace tetglow
