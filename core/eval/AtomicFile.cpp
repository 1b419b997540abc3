#include "eval/AtomicFile.hpp"

#include "io/PartialFile.hpp"

namespace unimap::eval {

void WriteFileAtomically(const std::filesystem::path& file, const std::string& bytes) {
  io::WriteWholeFile(file, [&bytes](io::PartialFile& out) { out.Write(bytes); });
}

}  // namespace unimap::eval
