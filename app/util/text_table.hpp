// Rows printed as a table for the terminal: each column as wide as its longest entry, counted in
// characters (a UTF-8 title's "ω" is one), two spaces between columns, the last left as it is.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace springlab::app {

// Characters in UTF-8 text (bytes that do not continue a character).
std::size_t utf8_length(std::string_view text);

// The rows, one line each ("\n"-ended), in columns.
std::string text_table(const std::vector<std::vector<std::string>>& rows);

}  // namespace springlab::app
