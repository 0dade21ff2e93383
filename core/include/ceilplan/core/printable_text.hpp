#pragma once
/// @file
/// Text from an input file or the command line, made safe to echo in a message: a corrupt or
/// hostile file must not write raw bytes or terminal escape sequences to the user's terminal.

#include <cstddef>
#include <string>
#include <string_view>

namespace ceilplan {

/// `text` with every byte that is not printable escaped as `\xHH`: ASCII control characters
/// (ESC, CR, NUL...), DEL, C1 controls (U+0080..U+009F, which some terminals obey as escapes)
/// and bytes that are not valid UTF-8. Printable ASCII and valid UTF-8 letters stay as they are,
/// and so does a backslash. Longer than `max_chars` characters, the rest becomes "...".
std::string printableText(std::string_view text, std::size_t max_chars = 64);

/// A report of several lines made safe to print: each line as printableText shows it, whole (no
/// "..."), the line breaks kept. Idempotent, so text already escaped can pass again.
std::string printableLines(std::string_view text);

}  // namespace ceilplan
