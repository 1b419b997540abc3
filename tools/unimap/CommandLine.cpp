#include "CommandLine.hpp"

namespace unimap::cli {
namespace {

std::string& Stored() {
  static std::string line;
  return line;
}

std::string Quoted(const std::string& arg) {
  if (!arg.empty() && arg.find_first_of(" \t'\"\\$") == std::string::npos) return arg;
  std::string out = "'";
  for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void SetCommandLine(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i > 0 ? " " : "") + Quoted(argv[i]);
  Stored() = line;
}

const std::string& CommandLine() { return Stored(); }

}  // namespace unimap::cli
