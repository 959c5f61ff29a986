#pragma once

#include <cstdio>
#include <iostream>

namespace abalike::app
{

/// Plain text, no formatting: a pattern without values is not a format string (a '%' in it is printed as is).
inline void print(const char* text)
{
    std::cout << text;
}

/// printf-style formatting onto std::cout, so that every line of a command goes through the same stream (and a test
/// or the fuzzer capturing std::cout sees all of it). Lines longer than 511 bytes are cut.
template <class Value, class... Values>
void print(const char* pattern, Value value, Values... values)
{
    char line[512];
    std::snprintf(line, sizeof line, pattern, value, values...);
    std::cout << line;
}

} // namespace abalike::app
