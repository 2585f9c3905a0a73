// Which stage `whitted render`, `trace` and `explore` run: the labs' features they use.
#pragma once

#include "whitted/passes.hpp"

#include <CLI/CLI.hpp>

#include <optional>

namespace whitted {

/// The stage asked for, or the highest whose labs are all done; nothing (after
/// explaining on stderr which labs are missing) when the labs it needs, or the
/// labs `pass` calls, are not done yet.
std::optional<int> choose_stage(std::optional<int> asked, std::optional<Pass> pass = std::nullopt);

/// The command's `--stage K` option (1 to the last lab), the same in every command that renders.
void add_stage_option(CLI::App& command, std::optional<int>& stage);

} // namespace whitted
