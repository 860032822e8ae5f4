#pragma once
/// @file
/// The report page's embedded assets. Defined in a source file that CMake generates at configure
/// time (src/hotlap/report/embed_assets.cmake), so the library carries Chart.js and the page's own
/// script and style: a report never depends on files at run time.

#include <string_view>

namespace hotlap::report::internal {

/// Chart.js's UMD build, as read from Debian's libjs-chart.js package at build time.
std::string_view ChartJsSource();

/// Chart.js's version, e.g. "3.9.1".
std::string_view ChartJsVersion();

/// The file Chart.js was read from at build time.
std::string_view ChartJsPath();

/// Inline script for <head>: counts script errors before anything else runs (report_errors.js).
std::string_view ErrorHookScript();

/// The page's script that draws every chart from the embedded JSON (report_page.js).
std::string_view PageScript();

/// The page's style sheet (report_page.css).
std::string_view PageStyle();

}  // namespace hotlap::report::internal
