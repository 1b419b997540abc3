// Placeholder: registers nothing until `unimap bench` is implemented
// (only implemented subcommands are listed).
#include "Commands.hpp"

namespace unimap::cli {

void AddBenchCommand(CLI::App* /*app*/) {}

}  // namespace unimap::cli
