#include "report/LoopClosureLayer.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "report/Float32Table.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {

nlohmann::ordered_json LoopClosureLayer(const std::filesystem::path& file, std::size_t* count) {
  std::ifstream in(file);
  if (!in) throw InputError("loop closures " + file.string() + ": cannot be read");
  Float32Table table(6);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double v[7];
    bool ok = true;
    for (double& value : v) ok = ok && static_cast<bool>(fields >> value) && std::isfinite(value);
    std::string extra;
    if (!ok || fields >> extra) {
      throw InputError("loop closures " + file.string() + ":" + std::to_string(number) +
                       ": expected 7 finite numbers (time_s, scan x y z, submap x y z)");
    }
    table.AddRow({v[1], v[2], v[3], v[4], v[5], v[6]});
  }
  if (count != nullptr) *count = table.rows();
  return {{"count", table.rows()}, {"xyz", table.Base64()}};
}

}  // namespace unimap::report
