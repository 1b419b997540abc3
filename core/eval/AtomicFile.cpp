#include "eval/AtomicFile.hpp"

#include <fstream>
#include <system_error>

#include "unimap/Errors.hpp"

namespace unimap::eval {

void WriteFileAtomically(const std::filesystem::path& file, const std::string& bytes) {
  std::filesystem::path partial = file;
  partial += ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write " + partial.string());
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(partial, ignored);
      throw Error("cannot write " + partial.string() + " (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
    throw Error("cannot rename " + partial.string() + " to " + file.string() + ": " + ec.message());
  }
}

}  // namespace unimap::eval
