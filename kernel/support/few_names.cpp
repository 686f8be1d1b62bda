#include "kernel/support/few_names.h"

#include <fmt/format.h>

#include <iterator>

namespace mechanist {

std::string FewNames(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 8;
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) {
    text += (i ? ", " : "") + names[i];
  }
  if (names.size() > kShown) {
    fmt::format_to(std::back_inserter(text), " and {} more", names.size() - kShown);
  }
  return text;
}

}  // namespace mechanist
