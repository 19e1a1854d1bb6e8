// The nearest of a list of names to a word that matches none of them, for "did you mean" in
// errors: the optimal-string-alignment distance (insertions, deletions, substitutions and
// swaps of two neighbours, case ignored), within about a third of the word.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace tetglow {

size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest `word` ("" when none is near enough or the word is one of them). Ties go
// to the first.
std::string nearestName(std::string_view word, const std::vector<std::string_view>& candidates);

// " (did you mean \"NAME\"?)" for nearestName, "" when there is none.
std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace tetglow
