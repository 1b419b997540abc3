#pragma once
// Whole-file writes that never leave a half-written file behind.
#include <filesystem>
#include <string>

namespace unimap::eval {

// Writes bytes to "<file>.partial" in the same folder, then renames it onto
// file (atomic on POSIX file systems). Throws unimap::Error naming the file
// when it cannot be written or renamed; the partial file is removed then.
void WriteFileAtomically(const std::filesystem::path& file, const std::string& bytes);

}  // namespace unimap::eval
