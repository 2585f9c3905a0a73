// `whitted grade-all FOLDER --csv FILE`: grading a whole class (grade_all_command.cpp).
#pragma once

#include "commands.hpp"

namespace whitted {

/// `whitted grade-all FOLDER --csv FILE [--out GRADES_DIR] [--parallel N] [grade's options]`
Command add_grade_all_command(CLI::App& app);

} // namespace whitted
