#pragma once
// The output folder of a command, checked before any work is done.
#include <filesystem>
#include <string>

namespace unimap::cli {

// Creates `folder` (and its parents) if needed and checks that files can be
// created in it; throws InputError "<option> <folder>: <reason>" when it
// exists but is not a folder (a file, /dev/null), cannot be created, or is
// not writable (a read-only folder or file system).
void PrepareOutputFolder(const std::filesystem::path& folder, const std::string& option);

}  // namespace unimap::cli
