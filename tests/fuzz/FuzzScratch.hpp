#pragma once
// Shared by the fuzz harnesses: the readers under test take file names, so
// each input is written to a scratch folder first (in /dev/shm when it
// exists: a RAM file system keeps executions fast).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace unimap::fuzz {

// One scratch folder per process, emptied and removed at exit.
class FuzzScratch {
 public:
  FuzzScratch() {
    std::error_code ec;
    const std::filesystem::path shm("/dev/shm");
    const std::filesystem::path base =
        std::filesystem::is_directory(shm, ec) ? shm : std::filesystem::temp_directory_path();
    folder_ = base / ("unimap-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder_, ec);
  }
  ~FuzzScratch() {
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
  }
  FuzzScratch(const FuzzScratch&) = delete;
  FuzzScratch& operator=(const FuzzScratch&) = delete;

  // Writes bytes to folder/name (replacing it) and returns its path.
  std::filesystem::path Write(const std::string& name, const std::uint8_t* data, std::size_t size) const {
    const std::filesystem::path file = folder_ / name;
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file;
  }
  std::filesystem::path Write(const std::string& name, const std::string& text) const {
    return Write(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }
  // Removes folder/name if present.
  void Remove(const std::string& name) const {
    std::error_code ec;
    std::filesystem::remove(folder_ / name, ec);
  }
  const std::filesystem::path& folder() const { return folder_; }

  // The process's scratch folder.
  static const FuzzScratch& Get() {
    static const FuzzScratch scratch;
    return scratch;
  }

 private:
  std::filesystem::path folder_;
};

}  // namespace unimap::fuzz
