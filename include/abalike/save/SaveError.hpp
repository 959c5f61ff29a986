#pragma once

#include <stdexcept>

namespace abalike
{

/// A save file whose content is not what abalike writes: bad JSON, wrong types, values out of range.
class SaveFormatError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/// A file that could not be read or written; the message names the file and the reason.
class SaveIoError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

} // namespace abalike
