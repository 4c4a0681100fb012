#pragma once
// Numbers as text, in the forms Lucerna writes: the shortest form that reads back to the same
// double (scene files, and values quoted in error messages), printf's %g with a number of
// significant digits (EXR header attributes, diagnostics, the command line's figures), a fixed
// number of decimals, and a duration.

#include <string>

namespace lucerna {

// The shortest decimal that reads back as exactly x (std::to_chars): "0.1", "1e+39", "inf".
std::string shortestNumber(double x);

// %.Ng: "0.0123457" for N = 6.
std::string formatNumber(double v, int significantDigits = 9);

// %.Nf: a figure to a fixed number of decimal places, "512" for N = 0, "0.62" for N = 2; a
// negative zero reads "0".
std::string fixedNumber(double v, int decimals);

// A duration as every part of Lucerna writes it (the command line, the report, the dock): to a
// tenth of a second under a minute ("12.3 s"), else to the nearest second ("4 min 05 s"; 119.7 s
// is "2 min 00 s").
std::string formatDuration(double seconds);

}  // namespace lucerna
