#pragma once
/// @file
/// Closest-name suggestions for error messages ("did you mean ...?").

#include <string>
#include <string_view>
#include <vector>

namespace hotlap {

/// Levenshtein edit distance between two strings.
int EditDistance(std::string_view a, std::string_view b);

/// Up to `max_count` candidates closest to `name`, best first, among those within a distance
/// of max(2, name.size()/2). Empty when nothing is close.
std::vector<std::string> ClosestNames(std::string_view name,
                                      const std::vector<std::string>& candidates,
                                      int max_count = 3);

/// "'a', 'b' or 'c'" for messages; "(none)" when empty.
std::string QuotedList(const std::vector<std::string>& names);

}  // namespace hotlap
