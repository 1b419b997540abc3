#include "PayloadConformanceTest.hpp"

#include <exception>
#include <sstream>

namespace unimap::conformance {

void PayloadConformanceTest::SetUp() {
  try {
    loaded_ = PluginLoader().Load(GetParam());
  } catch (const std::exception& e) {
    FAIL() << "cannot load payload plugin '" << GetParam() << "': " << e.what();
  }
  ASSERT_NE(loaded_.plugin, nullptr) << "PluginLoader::Load('" << GetParam() << "') returned no plugin";
  try {
    loaded_.plugin->Configure(DefaultMap());
  } catch (const std::exception& e) {
    FAIL() << Label() << ": Configure(Defaults().DefaultMap()) threw: " << e.what();
  }
}

ParameterMap PayloadConformanceTest::DefaultMap() const { return plugin().Defaults().DefaultMap(); }

std::string PayloadConformanceTest::Label() const {
  return "payload '" + plugin().Name() + "' (" + loaded_.library_path.string() + ")";
}

bool PayloadConformanceTest::Identical(const BodyScan& a, const BodyScan& b, std::string* why) {
  std::ostringstream out;
  out.precision(17);
  if (a.reference_time_s != b.reference_time_s) {
    out << "reference time " << a.reference_time_s << " vs " << b.reference_time_s;
  } else if (a.dropped_out_of_range != b.dropped_out_of_range) {
    out << "dropped " << a.dropped_out_of_range << " vs " << b.dropped_out_of_range;
  } else if (a.points.size() != b.points.size()) {
    out << a.points.size() << " points vs " << b.points.size();
  } else {
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const Point& p = a.points[i];
      const Point& q = b.points[i];
      if (p.position_m != q.position_m || p.time_s != q.time_s || p.intensity != q.intensity || p.ring != q.ring) {
        out << "point " << i << ": (" << p.position_m.transpose() << ") t=" << p.time_s << " vs ("
            << q.position_m.transpose() << ") t=" << q.time_s;
        break;
      }
    }
  }
  *why = out.str();
  return why->empty();
}

}  // namespace unimap::conformance
