#include <iostream>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "TextTable.hpp"
#include "unimap/Errors.hpp"
#include "unimap/PluginLoader.hpp"

namespace unimap::cli {
namespace {

struct PluginsOptions {
  bool brief = false;  // names and paths only
};

void PrintDefaults(const PayloadPlugin& plugin) {
  TextTable table({"key", "symbol", "default", "meaning"});
  const ParameterSet defaults = plugin.Defaults();
  for (const ParameterSpec& spec : defaults.specs()) {
    table.AddRow({spec.key, spec.symbol, ToString(spec.default_value), spec.description});
  }
  table.Print(std::cout, "    ");
}

int RunPlugins(const PluginsOptions& options) {
  const PluginLoader loader;
  std::cout << "Plugin folders, in search order:\n";
  for (const auto& folder : loader.folders()) std::cout << "  " << folder.string() << '\n';
  const auto libraries = loader.Discover();
  std::cout << libraries.size() << " payload plugin(s) found\n";
  int failures = 0;
  for (const auto& path : libraries) {
    try {
      const LoadedPlugin loaded = loader.Load(path.string());
      std::cout << '\n'
                << loaded.plugin->Name() << "  (ABI " << loaded.abi_version << ")  " << loaded.library_path.string()
                << "\n  " << loaded.plugin->Description() << '\n';
      if (!options.brief) {
        std::cout << "  defaults:\n";
        PrintDefaults(*loaded.plugin);
      }
    } catch (const PluginError& e) {
      ++failures;
      std::cerr << "\nerror: " << path.string() << ": " << e.what() << '\n';
    }
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

void AddPluginsCommand(CLI::App* app) {
  auto options = std::make_shared<PluginsOptions>();
  CLI::App* cmd =
      app->add_subcommand("plugins", "List the payload plugins found (UNIMAP_PLUGIN_PATH, build and install folders)");
  cmd->add_flag("--brief", options->brief, "Names, versions and paths only, no defaults");
  cmd->callback([options]() {
    const int code = RunPlugins(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
