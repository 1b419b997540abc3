// Placeholder: registers nothing until `unimap simulate` is implemented
// (only implemented subcommands are listed).
#include "Commands.hpp"

namespace unimap::cli {

void AddSimulateCommand(CLI::App* /*app*/) {}

}  // namespace unimap::cli
