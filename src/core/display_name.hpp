#pragma once
// Names (file paths, scene names) as messages print them: in single
// quotes, with control characters escaped, so that a newline or a terminal
// escape sequence in a file name cannot break the one-line error or reach
// the terminal.
#include <string>
#include <string_view>

namespace penumbra {

// "'name'", with \n, \r, \t and other control bytes written as \n, \r, \t
// and \xHH.
std::string display_name(std::string_view name);

// The same escaping without the quotes.
std::string escape_control(std::string_view text);

}  // namespace penumbra
