#include "eval/AtomicFile.hpp"

#include <system_error>

#include "io/PartialFile.hpp"

namespace unimap::eval {

void WriteFileAtomically(const std::filesystem::path& file, const std::string& bytes) {
  std::filesystem::path partial_path;
  try {
    io::PartialFile out(file);  // "<file>.partial", renamed into place by Commit()
    partial_path = out.partial_path();
    out.Write(bytes);
    out.Commit();
  } catch (...) {
    std::error_code ignored;
    if (!partial_path.empty()) std::filesystem::remove(partial_path, ignored);
    throw;
  }
}

}  // namespace unimap::eval
