#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "TextTable.hpp"
#include "pipeline/MapperSettings.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

struct ConfigOptions {
  std::string platform_file;  // the platform YAML
};

int RunConfig(const ConfigOptions& options) {
  try {
    const Platform platform = LoadPlatform(options.platform_file);
    // Checked before anything is printed: a bad mapper setting is an error, not half a listing.
    const std::vector<pipeline::MapperSettingRow> mapper_rows = pipeline::ListMapperSettings(platform);
    std::cout << "platform: " << platform.file << '\n'
              << "plugin:   " << platform.plugin.plugin->Name() << "  (ABI " << platform.plugin.abi_version << ")  "
              << platform.plugin.library_path.string() << '\n'
              << "          " << platform.plugin.plugin->Description() << "\n\n";
    TextTable table({"key", "symbol", "value", "source", "meaning"});
    for (const EffectiveParameter& p : platform.effective) {
      const std::string source =
          p.source == ParameterSource::kPlatformFile ? platform.file + ":" + std::to_string(p.line) : "plugin default";
      table.AddRow({p.spec.key, p.spec.symbol, ToString(p.value), source, p.spec.description});
    }
    table.Print(std::cout);
    // The mapper's settings: every key a `mapper:` section may set.
    std::cout << "\nmapper settings (a `mapper:` section sets them; "
              << "sources: file:line, derived = follows a "
              << "value the file sets, platform = the mapper's value for this platform's parameters, default)\n";
    TextTable settings({"key", "value", "unit", "source"});
    for (const pipeline::MapperSettingRow& row : mapper_rows) {
      settings.AddRow({row.key, row.value, row.unit, row.source});
    }
    settings.Print(std::cout);
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddConfigCommand(CLI::App* app) {
  auto options = std::make_shared<ConfigOptions>();
  CLI::App* cmd = app->add_subcommand("config", "Print a platform's effective parameters and where each came from");
  cmd->add_option("--platform", options->platform_file, "Platform YAML (configs/platforms/*.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->callback([options]() {
    const int code = RunConfig(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
