// The symbols of compiled objects: what a lab's object calls, what the kit defines.
//
// Why: the link fence (lab_fences.hpp) must know which of the framework's
// functions a student's lab file calls. The object is the student's (its
// symbol table is whatever their source made the compiler write), so it is
// read here, bound by bound, rather than by a tool whose output the student's
// code could shape: every offset and size is checked against the file, and a
// file that is not a plain 64-bit little-endian ELF object is refused.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::grade {

/// A file that is not an object (or archive of objects) this reader understands.
struct ObjectFormatError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The global and weak symbols of an ELF object, by their (mangled) names.
struct ObjectSymbols {
    std::vector<std::string> defined;
    std::vector<std::string> undefined; // what the object calls or uses from elsewhere
};

/// The symbols of a 64-bit little-endian ELF relocatable object (every symbol table it has).
ObjectSymbols elf_object_symbols(std::string_view bytes);

/// The symbols defined by the members of an ar archive of such objects (a static library).
std::vector<std::string> archive_defined_symbols(std::string_view bytes);

} // namespace whitted::grade
