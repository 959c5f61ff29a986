#pragma once

#include <stdexcept>

namespace abalike::app
{

/// Bad command-line input: reported as one line on stderr, exit code 2.
class UsageError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/// Exit code for wrong arguments, unreadable files and invalid numbers.
inline constexpr int kUsageExitCode = 2;

} // namespace abalike::app
