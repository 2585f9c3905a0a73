// Finding a submission's lab files and copying them where the grader builds them.
//
// Why: a submission is hostile input. A lab file may be a symbolic link (to
// the solution, or to a secret the grader would copy and show), a FIFO that
// blocks a reader for ever, a device without end, or huge. Only regular files
// of a bounded size are copied, opened without following links or blocking;
// anything else is refused with the reason, and the lab is graded as missing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted::grade {

/// The largest lab file the grader copies.
inline constexpr std::size_t kMaxLabFileBytes = 1 << 20;

/// Where a submission's lab files are.
struct LabFolder {
    std::filesystem::path folder; // absolute
    std::string shown;            // as the student knows it: "" (the top), "labs/", "my-project/labs/"
    int files = 0;                // how many lab files it holds (0: none anywhere)
};

/// The lab files are in more than one place; the message names each (shown to the student).
struct AmbiguousSubmission : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Finds the one folder holding the lab files, where students put them: the
/// top of the submission, its labs/, or one folder down (a zipped folder:
/// my-project/ or my-project/labs/). Folders that are links, hidden folders and
/// __MACOSX are not searched. Throws AmbiguousSubmission when lab files are in
/// two of these places; returns the top with `files` 0 when there are none.
LabFolder find_lab_folder(const std::filesystem::path& submission, const std::vector<std::string>& labs);

/// Why the submission, as given on the command line, is not graded: its last
/// component (after trailing slashes and `.`) is a symbolic link, which could
/// lead anywhere on the grading machine (the solution, say) and is not followed;
/// nothing when it is not one. The folders above it are the instructor's
/// choosing and may be links (a home or /tmp that is one).
std::optional<std::string> linked_submission(const std::filesystem::path& argument);

/// Copies <from.folder>/<lab>.cpp for every lab into `to` (emptied first); a lab
/// file that is missing or refused is replaced by the untouched stub from `stubs`.
/// Returns, for each such lab, why ("the submission has no labs/01_ray_casting.cpp").
std::map<std::string, std::string> copy_lab_files(const LabFolder& from, const std::filesystem::path& stubs,
                                                  const std::filesystem::path& to, const std::vector<std::string>& labs);

/// The content of a regular file that is not a link, at most `max_bytes` long,
/// read without blocking; throws std::runtime_error saying what it is instead.
std::string read_regular_file(const std::filesystem::path& file, std::size_t max_bytes);

/// The labs' stems ("01_ray_casting", ...), in order, from the lab table.
std::vector<std::string> lab_names();

} // namespace whitted::grade
