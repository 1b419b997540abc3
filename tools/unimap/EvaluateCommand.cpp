// Placeholder: registers nothing until `unimap evaluate` is implemented
// (only implemented subcommands are listed).
#include "Commands.hpp"

namespace unimap::cli {

void AddEvaluateCommand(CLI::App* /*app*/) {}

}  // namespace unimap::cli
