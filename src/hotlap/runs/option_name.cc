#include "hotlap/runs/option_name.h"

#include <algorithm>

namespace hotlap::runs {

std::string OptionName(NameStyle style, std::string_view name) {
  std::string out(name);
  if (style == NameStyle::kPython) return out;
  std::replace(out.begin(), out.end(), '_', '-');
  return "--" + out;
}

}  // namespace hotlap::runs
