// The link fence: the framework's functions a lab's code may not call.
//
// Why: a worker links the student's lab with the whole framework, and the
// framework holds answers: its own BVH builder and walks, the scene's queries
// (which walk that BVH), its box primitive's slab test, the yardsticks that
// measure lab 10's trees. The grader never hands one over to the lab it
// answers: before a worker is linked, the lab's object is read (its symbol
// table, elf_symbols.hpp) and a call of a fenced function refuses the lab,
// naming the function and why. The list is per lab; the kit's own files say
// which symbols the names stand for, so an overload or a new signature of a
// fenced function is fenced too. What the student writes themselves (or
// copies) is theirs: the fence is that the grader never gives it.
#pragma once

#include "grader/kit.hpp"

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::grade {

/// One call of a fenced function by a lab's object.
struct FencedCall {
    std::string function; // demangled, as the student wrote it
    std::string why;
};

class LabFences {
  public:
    /// Reads the symbols the kit's libraries and remote objects define (the
    /// instructor's files) and fences those the rules name. Throws
    /// ObjectFormatError for a kit file it cannot read.
    explicit LabFences(const WorkerKit& kit);

    /// The fenced functions the compiled object of `lab` ("10_bvh") calls; none: it may be linked.
    std::vector<FencedCall> refused(const std::string& lab, std::string_view object) const;

    /// The message for a lab refused by its calls, for the student.
    static std::string describe(const std::string& lab, const std::vector<FencedCall>& calls);

  private:
    struct Fenced {
        int lab = 0; // 0: fenced for every lab
        std::string function;
        std::string why;
    };
    std::map<std::string, std::vector<Fenced>> fenced_; // mangled symbol -> its fences
};

} // namespace whitted::grade
