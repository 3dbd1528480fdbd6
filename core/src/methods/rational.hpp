// Exact rationals for tableaux (springlab/butcher.hpp): Boost.Multiprecision's cpp_rational,
// header-only, so that the browser build checks a tableau exactly as the desktop does.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <optional>
#include <string>

namespace springlab {

using Rational = boost::multiprecision::cpp_rational;

// "1/6", "-2", "0.25", "1.5e-3", " 3 / 8 ": a decimal, or a fraction of two decimals, exactly.
// nullopt when it is none of these or divides by zero.
std::optional<Rational> parse_rational(const std::string& text);

// "1/6", "-2", "0".
std::string rational_text(const Rational& r);

}  // namespace springlab
