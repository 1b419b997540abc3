#include "unimap/Mapper.hpp"

namespace unimap {

bool MapperSettings::IsValid(std::string* why) const {
  if (platform_file.empty()) {
    *why = "platform_file is empty";
    return false;
  }
  if (threads < 1 || threads > 64) {
    *why = "threads " + std::to_string(threads) + " is outside 1-64";
    return false;
  }
  return true;
}

}  // namespace unimap
