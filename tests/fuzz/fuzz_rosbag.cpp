// libFuzzer harness: a ROS 1 bag through RosbagReader (every stream on auto).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <system_error>

#include "FuzzScratch.hpp"
#include "io/RosbagReader.hpp"
#include "unimap/Errors.hpp"

namespace {

// librosbag loads its encryptor plugin (a shared library, through
// class_loader) for every bag it opens and unloads it when the last bag
// closes. The first bag that opens is therefore kept open for the whole
// process, so the plugin stays loaded and each execution measures the
// reader, not a dlopen / dlclose pair (and no leak scan is triggered by the
// loader's bookkeeping): about 60 executions/s before, see
// docs/reliability.md.
// A function-local static: made on first use, after class_loader's own
// statics, so it is destroyed before them at exit (a namespace-scope one
// outlived them and corrupted the heap on exit).
std::unique_ptr<unimap::io::RosbagReader>& KeptOpen() {
  static std::unique_ptr<unimap::io::RosbagReader> kept;
  return kept;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = unimap::fuzz::FuzzScratch::Get();
  try {
    const std::filesystem::path bag = scratch.Write("data.bag", data, size);
    unimap::io::RosbagReader reader(bag);
    if (!KeptOpen()) {
      std::error_code ec;
      const std::filesystem::path kept = scratch.folder() / "kept.bag";
      std::filesystem::copy_file(bag, kept, std::filesystem::copy_options::overwrite_existing, ec);
      if (!ec) KeptOpen() = std::make_unique<unimap::io::RosbagReader>(kept);
    }
    while (reader.Next()) {
    }
  } catch (const unimap::Error&) {
  }
  return 0;
}
