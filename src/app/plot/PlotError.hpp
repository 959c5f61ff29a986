#pragma once

#include <stdexcept>

namespace abalike::app
{

/// A plot could not be drawn or written (no font, unwritable file); the message says which and why.
class PlotError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

} // namespace abalike::app
