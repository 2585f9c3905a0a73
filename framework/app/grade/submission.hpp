// Finding a submission's lab files and copying them where the grader builds them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace whitted::grade {

/// The folder holding the lab files: SUBMISSION/labs when it has any of them, else SUBMISSION.
std::filesystem::path find_lab_folder(const std::filesystem::path& submission, const std::vector<std::string>& labs);

/// Copies <from>/<lab>.cpp for every lab into `to` (emptied first); a lab file
/// that is not there is replaced by the untouched stub from `stubs`. Returns
/// the labs that were missing.
std::vector<std::string> copy_lab_files(const std::filesystem::path& from, const std::filesystem::path& stubs,
                                        const std::filesystem::path& to, const std::vector<std::string>& labs);

/// The lab names of a tree: the NN_name.cpp files in its labs/ folder, sorted.
std::vector<std::string> lab_names(const std::filesystem::path& instructor_tree);

} // namespace whitted::grade
