// Placeholder: registers nothing until `unimap convert` is implemented
// (only implemented subcommands are listed).
#include "Commands.hpp"

namespace unimap::cli {

void AddConvertCommand(CLI::App* /*app*/) {}

}  // namespace unimap::cli
