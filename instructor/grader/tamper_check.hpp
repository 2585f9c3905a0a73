// A record of the files the grader relies on, to notice a test that changed them.
//
// Why: the fences (sandbox.hpp) make the instructor's files read-only to the
// tests wherever the machine allows it, but a grader run by an ordinary user
// without bubblewrap leaves them writable. A test that rewrites a reference
// image, the rubric or an imported library would change how every later
// submission is graded. The grader records these files' sizes and modification
// times before the tests and compares after each lab: any change stops the
// grading with a grader failure that names the file, so no wrong grade is given.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace whitted::grade {

class FileRecord {
public:
    /// Records the files given and every file under the folders given (those
    /// that exist); under folders only those whose extension is in
    /// `extensions` (".a") when it is not empty.
    static FileRecord of(const std::vector<std::filesystem::path>& paths, const std::vector<std::string>& extensions = {});

    /// Adds the other record's files to this one.
    void add(const FileRecord& other) { files_.insert(other.files_.begin(), other.files_.end()); }

    /// The first file added, removed or changed in `now`, with what happened; empty when none.
    std::optional<std::string> first_change(const FileRecord& now) const;

private:
    struct Stamp {
        std::uintmax_t size = 0;
        std::int64_t modified = 0; // nanoseconds of the file clock
        bool operator==(const Stamp&) const = default;
    };
    std::map<std::string, Stamp> files_;
};

} // namespace whitted::grade
