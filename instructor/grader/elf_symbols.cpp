#include "grader/elf_symbols.hpp"

#include <cstdint>
#include <cstring>

namespace whitted::grade {
namespace {

constexpr std::uint32_t kElfSymbolTable = 2;  // SHT_SYMTAB
constexpr std::uint32_t kElfDynamicSymbols = 11; // SHT_DYNSYM
constexpr std::size_t kElfSectionHeaderSize = 64;
constexpr std::size_t kElfSymbolSize = 24;

/// A little-endian unsigned integer of `size` bytes at `offset`, checked against the file.
std::uint64_t elf_read_le(std::string_view bytes, std::uint64_t offset, std::size_t size) {
    if (offset > bytes.size() || size > bytes.size() - offset) throw ObjectFormatError("a field past the end of the object");
    std::uint64_t value = 0;
    for (std::size_t i = size; i-- > 0;) value = (value << 8) | static_cast<unsigned char>(bytes[offset + i]);
    return value;
}

/// The part [offset, offset + size) of the file, checked.
std::string_view elf_slice(std::string_view bytes, std::uint64_t offset, std::uint64_t size) {
    if (offset > bytes.size() || size > bytes.size() - offset) throw ObjectFormatError("a section past the end of the object");
    return bytes.substr(offset, size);
}

/// The NUL-terminated name at `offset` of a string table.
std::string elf_name_at(std::string_view strings, std::uint64_t offset) {
    if (offset >= strings.size()) throw ObjectFormatError("a symbol name outside its string table");
    const std::string_view rest = strings.substr(offset);
    const std::size_t end = rest.find('\0');
    if (end == std::string_view::npos) throw ObjectFormatError("a symbol name without its end");
    return std::string(rest.substr(0, end));
}

struct ElfSection {
    std::uint32_t type = 0;
    std::uint64_t offset = 0, size = 0;
    std::uint32_t link = 0;
};

std::vector<ElfSection> elf_sections(std::string_view bytes) {
    if (bytes.size() < 64 || std::memcmp(bytes.data(), "\x7f" "ELF", 4) != 0) throw ObjectFormatError("not an ELF object");
    if (bytes[4] != 2 || bytes[5] != 1) throw ObjectFormatError("not a 64-bit little-endian ELF object");
    const std::uint64_t table = elf_read_le(bytes, 0x28, 8);
    const std::uint64_t entry_size = elf_read_le(bytes, 0x3a, 2);
    const std::uint64_t count = elf_read_le(bytes, 0x3c, 2);
    if (count == 0 && table != 0) throw ObjectFormatError("an ELF object with more sections than its header counts");
    if (count > 0 && entry_size != kElfSectionHeaderSize) throw ObjectFormatError("ELF section headers of an unknown size");
    std::vector<ElfSection> sections;
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::uint64_t at = table + i * kElfSectionHeaderSize;
        sections.push_back({static_cast<std::uint32_t>(elf_read_le(bytes, at + 4, 4)), elf_read_le(bytes, at + 0x18, 8),
                            elf_read_le(bytes, at + 0x20, 8), static_cast<std::uint32_t>(elf_read_le(bytes, at + 0x28, 4))});
    }
    return sections;
}

} // namespace

ObjectSymbols elf_object_symbols(std::string_view bytes) {
    const std::vector<ElfSection> sections = elf_sections(bytes);
    ObjectSymbols symbols;
    for (const ElfSection& table : sections) {
        if (table.type != kElfSymbolTable && table.type != kElfDynamicSymbols) continue;
        if (table.link >= sections.size()) throw ObjectFormatError("a symbol table without its string table");
        const std::string_view entries = elf_slice(bytes, table.offset, table.size);
        const ElfSection& names = sections[table.link];
        const std::string_view strings = elf_slice(bytes, names.offset, names.size);
        for (std::size_t at = kElfSymbolSize; at + kElfSymbolSize <= entries.size(); at += kElfSymbolSize) { // entry 0 is null
            const auto binding = static_cast<unsigned>(static_cast<unsigned char>(entries[at + 4]) >> 4);
            if (binding != 1 && binding != 2) continue; // local symbols name nothing outside the object
            const std::uint64_t name = elf_read_le(entries, at, 4);
            const std::uint64_t section = elf_read_le(entries, at + 6, 2);
            std::string text = elf_name_at(strings, name);
            if (text.empty()) continue;
            (section == 0 ? symbols.undefined : symbols.defined).push_back(std::move(text));
        }
    }
    return symbols;
}

std::vector<std::string> archive_defined_symbols(std::string_view bytes) {
    constexpr std::string_view kMagic = "!<arch>\n";
    if (bytes.substr(0, kMagic.size()) != kMagic) throw ObjectFormatError("not an ar archive");
    std::vector<std::string> defined;
    std::uint64_t at = kMagic.size();
    while (at + 60 <= bytes.size()) {
        const std::string_view header = bytes.substr(at, 60);
        const std::string_view name = header.substr(0, 16);
        std::uint64_t size = 0;
        for (const char c : header.substr(48, 10)) {
            if (c == ' ') break;
            if (c < '0' || c > '9') throw ObjectFormatError("an archive member of unreadable size");
            size = size * 10 + static_cast<std::uint64_t>(c - '0');
        }
        const std::string_view member = elf_slice(bytes, at + 60, size);
        // "/" and "/SYM64/" are the archive's own symbol index and "//" its long names; every other member is an object.
        const std::string_view trimmed = name.substr(0, name.find_last_not_of(' ') + 1);
        if (trimmed != "/" && trimmed != "//" && trimmed != "/SYM64/") {
            ObjectSymbols symbols = elf_object_symbols(member);
            defined.insert(defined.end(), symbols.defined.begin(), symbols.defined.end());
        }
        at += 60 + size + (size % 2); // members start at even offsets
    }
    return defined;
}

} // namespace whitted::grade
