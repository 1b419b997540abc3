#pragma once
// Internal to unimap_io: an output file that only appears under its final
// name once it is complete.
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace unimap::io {

// Writes "<final>.partial" through a large buffer; Commit() flushes, syncs
// and renames it to <final>. Destroying an uncommitted file (an error, a
// full disk) closes and removes the ".partial": an interrupted writer leaves
// neither a file that looks complete nor a half-written one. (Only a killed
// process, which runs no destructor, can leave a ".partial".) Every failure
// is an InputError naming the file.
class PartialFile {
 public:
  // Suffix of the file while it is being written.
  static constexpr const char* kSuffix = ".partial";

  // Creates (truncates) "<final_path>.partial".
  explicit PartialFile(std::filesystem::path final_path);
  ~PartialFile();
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Appends bytes; throws after Commit() or on a write error.
  void Write(const void* data, std::size_t size);
  void Write(std::string_view text) { Write(text.data(), text.size()); }
  // Flushes, fsyncs, closes and renames into place; throws on failure or
  // when called twice.
  void Commit();

  const std::filesystem::path& final_path() const { return final_path_; }
  const std::filesystem::path& partial_path() const { return partial_path_; }

 private:
  std::filesystem::path final_path_;    // name once complete
  std::filesystem::path partial_path_;  // name while written
  std::FILE* stream_ = nullptr;         // open while writing, null once committed
  std::vector<char> buffer_;            // stdio buffer (outlives stream_)
};

// Writes a whole file at once: write fills a PartialFile for file, which is
// then committed. On any exception the ".partial" file is removed (nothing
// half-written stays behind) and the exception is rethrown.
void WriteWholeFile(const std::filesystem::path& file, const std::function<void(PartialFile&)>& write);

}  // namespace unimap::io
