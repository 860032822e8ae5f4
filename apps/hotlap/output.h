#pragma once
/// @file
/// Helpers the commands share for their outputs: JSON summaries and checks done before any work.

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

namespace hotlap::app {

/// Writes `json` (pretty-printed) to `path` atomically.
void WriteJsonFile(const std::filesystem::path& path, const nlohmann::json& json);

/// InputError unless the folder that will hold `path` exists, so that a run fails before doing
/// any work rather than after writing some of its outputs.
void CheckOutputFolder(const std::filesystem::path& path, const char* option);

/// Rounds to `digits` significant digits for JSON (keeps summaries readable, enough for checks).
double RoundSignificant(double x, int digits = 9);

/// The value rounded as RoundSignificant, or JSON null where there is none.
nlohmann::json JsonOrNull(const std::optional<double>& x, int digits = 9);

}  // namespace hotlap::app
