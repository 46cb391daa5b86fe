// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numbers to and from text, exactly as std::from_chars and std::to_chars do it, in every edition:
// every reader and writer of numbers in lutkit calls these, so a .cube is the same bytes on Linux,
// Windows and in the browser. They are the standard library's where it has them for floating
// point (GCC's: the Linux and Windows builds); the browser edition's (Emscripten's libc++) has
// neither, and there
//   fromChars  is fast_float (Debian's libfast-float-dev: the algorithm GCC's own from_chars runs)
//              with the standard's out-of-range rule (the value overflows to infinity or underflows
//              to zero: result_out_of_range, the value left as it was);
//   toChars    is the shortest digits that read back as the value (Dragonbox, from Debian's
//              libfmt-dev, header-only) written in the standard's style: %f or %e, whichever is
//              shorter, %f on a tie; with a precision, as printf's %.Nf.
// tests/lutlib/test_number_text.cpp compares both against the standard library's on hostile and
// random values.
#include <charconv>
#include <system_error>

namespace lut {

std::from_chars_result fromChars(const char* first, const char* last, float& value);
std::from_chars_result fromChars(const char* first, const char* last, double& value);

// Shortest round-trip text (std::to_chars(first, last, value)).
std::to_chars_result toChars(char* first, char* last, float value);
std::to_chars_result toChars(char* first, char* last, double value);
// Fixed notation with `precision` digits after the point (std::to_chars(first, last, value,
// std::chars_format::fixed, precision)).
std::to_chars_result toCharsFixed(char* first, char* last, double value, int precision);

namespace detail {
// The browser edition's forms, compiled everywhere so the tests can compare them with the
// standard library's.
std::from_chars_result fromCharsPortable(const char* first, const char* last, float& value);
std::from_chars_result fromCharsPortable(const char* first, const char* last, double& value);
std::to_chars_result toCharsPortable(char* first, char* last, float value);
std::to_chars_result toCharsPortable(char* first, char* last, double value);
std::to_chars_result toCharsFixedPortable(char* first, char* last, double value, int precision);
} // namespace detail

} // namespace lut
