#pragma once
// Numbers as text, in the two forms Lucerna writes: the shortest form that reads back to the same
// double (scene files, and values quoted in error messages), and printf's %g with a number of
// significant digits (EXR header attributes, diagnostics, the command line's figures).

#include <string>

namespace lucerna {

// The shortest decimal that reads back as exactly x (std::to_chars): "0.1", "1e+39", "inf".
std::string shortestNumber(double x);

// %.Ng: "0.0123457" for N = 6.
std::string formatNumber(double v, int significantDigits = 9);

// %.Nf: a figure to a fixed number of decimal places, "512" for N = 0, "0.62" for N = 2; a
// negative zero reads "0".
std::string fixedNumber(double v, int decimals);

}  // namespace lucerna
