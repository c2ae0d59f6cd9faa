// Reading and writing numbers in text files: exact round trip (shortest representation that
// reads back to the same double), locale-independent.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace foldsketch {

// The number spelled by the whole of `token`, or nothing (NaN and Inf spellings parse; callers
// decide whether they are acceptable).
std::optional<double> parse_double(std::string_view token);
std::optional<long long> parse_integer(std::string_view token);

// Shortest decimal spelling of x that parses back to exactly x.
std::string format_double(double x);

// x with at most `decimals` digits after the point, trailing zeros dropped ("12.5", "-3", "0").
std::string format_fixed(double x, int decimals);

} // namespace foldsketch
