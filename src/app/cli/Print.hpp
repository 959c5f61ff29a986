#pragma once

#include <cstdio>
#include <iostream>

namespace abalike::app
{

/// printf-style formatting onto std::cout, so that every line of a command goes through the same stream (and a test
/// or the fuzzer capturing std::cout sees all of it). Lines longer than 511 bytes are cut.
template <class... Values>
void print(const char* pattern, Values... values)
{
    char line[512];
    std::snprintf(line, sizeof line, pattern, values...);
    std::cout << line;
}

} // namespace abalike::app
