// Bad input: a scene, a script or an option that cannot be used as given. The message names the
// file, the field (a JSON path) and what is allowed; the command line exits with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace springlab {

/// Bad input: its message names the file, the field (a JSON path) and what is allowed, in one line.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The closest of `candidates` to `word` (edit distance), or "" when nothing is close.
std::string closest_match(const std::string& word, const std::string* candidates,
                          std::size_t count);

}  // namespace springlab
