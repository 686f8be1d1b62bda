#pragma once

#include <string>
#include <vector>

namespace mechanist {

/// "a, b and 3 more": the first eight of `names`, in order, for a one-line message.
std::string FewNames(const std::vector<std::string>& names);

}  // namespace mechanist
