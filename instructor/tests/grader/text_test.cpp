// What grade and grade-all print passes through terminal_text: a student's
// folder name, output or message can neither drive the instructor's terminal
// (title, clipboard, cleared screen, overwritten lines) nor hide that it tried.
#include "grader/class_grades.hpp"
#include "grader/class_progress.hpp"
#include "grader/text.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using namespace whitted::grade;

namespace {

// Whether the bytes hold anything a terminal acts on: a C0 control but newline and tab, DEL, a byte that is not part of
// a UTF-8 sequence (0x9b alone is CSI to an 8-bit terminal), or a C1 control in UTF-8 (0xc2 0x80-0x9f).
bool drives_a_terminal(const std::string& bytes) {
    for (std::size_t i = 0; i < bytes.size();) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c < 0x80) {
            if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) return true;
            ++i;
            continue;
        }
        const std::size_t length = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
        if (length == 0 || i + length > bytes.size()) return true;
        for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(bytes[i + k]) & 0xc0) != 0x80) return true;
        if (c == 0xc2 && static_cast<unsigned char>(bytes[i + 1]) < 0xa0) return true;
        i += length;
    }
    return false;
}

// What the stream got: ClassProgress and print_text write to a FILE*.
template <typename Write>
std::string written(Write write) {
    std::FILE* file = std::tmpfile();
    write(file);
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
    std::fclose(file);
    return text;
}

// The attacks of a hostile folder name: window title (OSC 0), clipboard (OSC 52), a cleared screen with a fake line,
// CSI as the C1 code point and as a lone byte, a carriage return over the line.
const std::string kHostile = "ana\x1b]0;pwned\x07\x1b]52;c;aGFja2Vk\x07\x1b[2J\x1b[Hfull marks: 100/100\xc2\x9b" "31m\x9b" "1m\rbob\x7f";

} // namespace

TEST(TerminalText, ControlSequencesAreShownAsEscapes) {
    EXPECT_EQ(terminal_text(kHostile), "ana\\x1b]0;pwned\\x07\\x1b]52;c;aGFja2Vk\\x07\\x1b[2J\\x1b[Hfull marks: 100/100\\u009b31m\\x9b1m\\x0dbob\\x7f");
    EXPECT_FALSE(drives_a_terminal(terminal_text(kHostile)));
    EXPECT_TRUE(drives_a_terminal(kHostile)) << "the check itself";
}

TEST(TerminalText, PrintableTextAndUtf8AreKept) {
    const std::string text = "Zoë Ñúñez – 学生 \xf0\x9f\x98\x80 tab\there \xc2\xa0nbsp, a\\x1b typed as text";
    EXPECT_EQ(terminal_text(text), text);
    EXPECT_EQ(terminal_text(terminal_text(kHostile)), terminal_text(kHostile)) << "a second pass changes nothing";
}

TEST(TerminalText, NewlinesAreEscapedInOneLineAndKeptInABlock) {
    EXPECT_EQ(terminal_text("ana\n  bob: 100/100"), "ana\\x0a  bob: 100/100");
    EXPECT_EQ(terminal_text("line 1\nline 2\n", Newlines::kept), "line 1\nline 2\n");
    EXPECT_EQ(terminal_text(std::string("nul\0here", 8)), "nul\\x00here");
}

// Bytes that are not UTF-8 are escaped one by one: overlong forms (of ESC and CSI), surrogates, past U+10FFFF,
// cut-off sequences, stray continuation bytes.
TEST(TerminalText, InvalidUtf8IsEscapedByteByByte) {
    EXPECT_EQ(terminal_text("\xc0\x9b"), "\\xc0\\x9b");
    EXPECT_EQ(terminal_text("\xe0\x80\x9b"), "\\xe0\\x80\\x9b");
    EXPECT_EQ(terminal_text("\xed\xa0\x80"), "\\xed\\xa0\\x80");
    EXPECT_EQ(terminal_text("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(terminal_text("cut \xe2\x82"), "cut \\xe2\\x82");
    EXPECT_EQ(terminal_text("\x9d" "52;c;x\x9c"), "\\x9d52;c;x\\x9c");
    EXPECT_EQ(terminal_text("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(terminal_text("\xe2\x82\xac\xf4\x8f\xbf\xbf"), "\xe2\x82\xac\xf4\x8f\xbf\xbf") << "the euro sign and U+10FFFF";
}

// Every byte pair, alone and around text: nothing a terminal acts on comes out.
TEST(TerminalText, NoByteSequenceComesOutRaw) {
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b) {
            const std::string bytes = {'x', static_cast<char>(a), static_cast<char>(b), 'y'};
            const std::string shown = terminal_text(bytes);
            ASSERT_FALSE(drives_a_terminal(shown)) << a << " " << b << ": " << shown;
            ASSERT_EQ(shown.find('\n'), std::string::npos) << a << " " << b;
        }
}

TEST(TerminalText, PrintLineAndPrintTextWriteWhatTerminalTextShows) {
    EXPECT_EQ(written([](std::FILE* f) { print_line(f, "a\x1b[2Jb\nc"); }), "a\\x1b[2Jb\\x0ac\n");
    EXPECT_EQ(written([](std::FILE* f) { print_text(f, "a\x1b[2Jb\nc\n"); }), "a\\x1b[2Jb\nc\n");
}

// grade-all's progress and summary name the student and the reason as the terminal may show them; on a terminal its
// own control sequences (erasing and redrawing the line) are the only ones.
TEST(TerminalText, GradeAllShowsStudentsAndReasonsEscaped) {
    const StudentGrade refused{kHostile, GradeStatus::not_graded, ResultsPoints{}, "x is a link\x1b]0;t\x07"};
    const std::string log = written([&](std::FILE* f) { ClassProgress(f, 2, 1, false, false).finished(refused, 1.0); });
    EXPECT_FALSE(drives_a_terminal(log)) << log;
    EXPECT_NE(log.find("[1/2] ana\\x1b]0;pwned\\x07"), std::string::npos) << log;
    // On a terminal: "\r\x1b[K", the failure's line, then the redrawn line "\r...\x1b[K"; nothing else drives it.
    const std::string screen = written([&](std::FILE* f) { ClassProgress(f, 2, 1, true, false).finished(refused, 1.0); });
    const std::size_t newline = screen.find('\n');
    ASSERT_TRUE(screen.starts_with("\r\x1b[K") && newline != std::string::npos && screen.ends_with("\x1b[K")) << screen;
    ASSERT_EQ(screen[newline + 1], '\r') << screen;
    const std::string own = screen.substr(4, newline + 1 - 4) + screen.substr(newline + 2, screen.size() - 3 - (newline + 2));
    EXPECT_FALSE(drives_a_terminal(own)) << screen;
    EXPECT_NE(screen.find("ana\\x1b]0;pwned"), std::string::npos) << screen;
    const std::string summary = class_summary({refused});
    EXPECT_FALSE(drives_a_terminal(summary)) << summary;
    EXPECT_NE(summary.find("not graded: x is a link\\x1b]0;t\\x07\n"), std::string::npos) << summary;
}
