// Which stage `whitted render` and `whitted trace` run: the labs' features they use.
#pragma once

#include "whitted/passes.hpp"

#include <optional>

namespace whitted {

/// The stage asked for, or the highest whose labs are all done; nothing (after
/// explaining on stderr which labs are missing) when the labs it needs, or the
/// labs `pass` calls, are not done yet.
std::optional<int> choose_stage(std::optional<int> asked, std::optional<Pass> pass = std::nullopt);

} // namespace whitted
