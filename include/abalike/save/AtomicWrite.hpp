#pragma once

#include <filesystem>
#include <string_view>

namespace abalike
{

/// Replaces path with contents so that a crash or a full disk leaves either the old file or the new one, never a
/// mix: writes a temporary file in the same folder, fsyncs it, renames it over path, then fsyncs the folder.
/// Throws SaveIoError naming the file and the reason; the old file and the folder are left as they were.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

} // namespace abalike
