// The square root of a real number as a complex one, exact on both axes: sqrt(-w^2) = i w. Not
// std::sqrt of a complex: libc++ (the browser build's) takes it through polar form, which leaves
// a real part of about 1e-16 w on the imaginary axis, and an undamped mode with a positive real
// part grows: every explicit method's limit would read 0.
#pragma once

#include <cmath>
#include <complex>

namespace springlab {

inline std::complex<double> sqrt_of_real(double x) {
  return x >= 0.0 ? std::complex<double>(std::sqrt(x), 0.0)
                  : std::complex<double>(0.0, std::sqrt(-x));
}

}  // namespace springlab
