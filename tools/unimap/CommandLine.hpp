#pragma once
// The command line as typed, for run.json ("command": where options given
// on the command line came from).
#include <string>

namespace unimap::cli {

// Stores argv joined by spaces (arguments holding spaces or quotes are single-quoted).
void SetCommandLine(int argc, const char* const* argv);
// The stored command line ("" before SetCommandLine).
const std::string& CommandLine();

}  // namespace unimap::cli
