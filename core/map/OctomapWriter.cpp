#include "map/OctomapWriter.hpp"

#include <streambuf>

#include <octomap/OcTree.h>

#include "io/PartialFile.hpp"
#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

// An output stream buffer that hands every byte to a PartialFile (which
// buffers and reports failures as InputError), so the tree is streamed to
// disk without a copy in memory.
class PartialFileBuffer : public std::streambuf {
 public:
  explicit PartialFileBuffer(io::PartialFile* out) : out_(out) {}

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char byte = traits_type::to_char_type(c);
    out_->Write(&byte, 1);
    return c;
  }
  std::streamsize xsputn(const char* data, std::streamsize size) override {
    out_->Write(data, static_cast<std::size_t>(size));
    return size;
  }

 private:
  io::PartialFile* out_;  // not owned
};

}  // namespace

void WriteOctomapBinary(const std::filesystem::path& file, const octomap::OcTree& tree) {
  io::WriteWholeFile(file, [&](io::PartialFile& out) {
    PartialFileBuffer buffer(&out);
    std::ostream stream(&buffer);
    // PartialFile throws InputError on a write failure; the stream must let
    // it through instead of turning it into badbit.
    stream.exceptions(std::ios::badbit);
    if (!tree.writeBinaryConst(stream) || !stream) {
      throw InputError(file.string() + ": OctoMap could not serialise the tree");
    }
  });
}

}  // namespace unimap::map
