#pragma once
/// @file
/// JSON summaries (docs/json-output.md): numbers rounded for reading, null where there is no
/// value, and the file written atomically.

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

namespace hotlap {

/// Writes `json` (pretty-printed, two spaces, a final newline) to `path` atomically.
void WriteJsonFile(const std::filesystem::path& path, const nlohmann::json& json);

/// WriteJsonFile, then `wrote PATH` on standard output (the commands' `--json`).
void WriteJsonFileAndSay(const std::filesystem::path& path, const nlohmann::json& json);

/// Rounds to `digits` significant digits for JSON (keeps summaries readable, enough for checks);
/// zero, infinities and NaN as they are.
double RoundSignificant(double x, int digits = 9);

/// The value rounded as RoundSignificant, or JSON null where there is none.
nlohmann::json JsonOrNull(const std::optional<double>& x, int digits = 9);

}  // namespace hotlap
