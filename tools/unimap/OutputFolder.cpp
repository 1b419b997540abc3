#include "OutputFolder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "unimap/Errors.hpp"

namespace unimap::cli {

void PrepareOutputFolder(const std::filesystem::path& folder, const std::string& option) {
  const std::string name = option + " " + folder.string();
  if (folder.empty()) throw InputError(option + ": no folder given");
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(folder, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_directory(status)) {
    throw InputError(name + ": exists and is not a folder");
  }
  if (!std::filesystem::exists(status)) {
    std::filesystem::create_directories(folder, ec);
    if (ec) throw InputError(name + ": cannot create the folder: " + ec.message());
  }
  // A file made and removed at once: access() would say yes to root in a
  // read-only folder, and knows nothing of full or read-only file systems.
  const std::filesystem::path probe = folder / (".unimap-write-test-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) throw InputError(name + ": cannot write into the folder: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace unimap::cli
