#include "WorldLoader.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "BoxPrimitive.hpp"
#include "CylinderPrimitive.hpp"
#include "HeightfieldPrimitive.hpp"
#include "PlanePrimitive.hpp"
#include "SpherePrimitive.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Extrinsic.hpp"

namespace unimap::sim {
namespace {

constexpr long long kMaxRepeatCount = 100000;

// 1-based line of a node; 0 when it has no position (or does not exist).
int LineOf(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

// How a node is called in messages.
std::string Describe(const YAML::Node& node) {
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list of " + std::to_string(node.size());
  if (node.IsNull()) return "nothing";
  return "'" + node.Scalar() + "'";
}

// The keys each primitive type accepts (besides `type`); the first group is required.
struct TypeKeys {
  std::vector<std::string> required;  // must be present
  std::vector<std::string> optional;  // may be present
};

const std::map<std::string, TypeKeys>& KeysByType() {
  static const std::map<std::string, TypeKeys> keys = {
      {"box", {{"center", "size"}, {"rpy_deg", "repeat"}}},
      {"plane", {{"center", "size"}, {"rpy_deg", "repeat"}}},
      {"cylinder", {{"base", "axis", "radius", "height"}, {"repeat"}}},
      {"sphere", {{"center", "radius"}, {"repeat"}}},
      {"heightfield", {{"center", "size"}, {"z0", "waves", "repeat"}}},
  };
  return keys;
}

// Comma-separated words.
std::string Join(const std::vector<std::string>& words) {
  std::string joined;
  for (const std::string& w : words) joined += (joined.empty() ? "" : ", ") + w;
  return joined;
}

// The keys of one map node (an entry or its `repeat`), with typed accessors
// that throw ConfigError naming the file, line, key and entry.
class EntryReader {
 public:
  // Collects the keys of map; prefix ("" or "repeat.") is prepended to key names in errors.
  EntryReader(const YAML::Node& map, std::string file, std::string context, std::string prefix)
      : file_(std::move(file)), context_(std::move(context)), prefix_(std::move(prefix)), line_(LineOf(map)) {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node key = it->first;
      if (!key.IsScalar()) Fail("", LineOf(key), "a key must be a plain word, got " + Describe(key));
      if (values_.count(key.Scalar()) > 0) {
        Fail(key.Scalar(), LineOf(key),
             "set twice (first on line " + std::to_string(LineOf(key_nodes_.at(key.Scalar()))) + ")");
      }
      values_.emplace(key.Scalar(), it->second);
      key_nodes_.emplace(key.Scalar(), key);
    }
  }

  [[noreturn]] void Fail(const std::string& key, int line, const std::string& reason) const {
    throw ConfigError(file_, line > 0 ? line : line_, key.empty() ? prefix_ : prefix_ + key, context_ + reason);
  }
  bool Has(const std::string& key) const { return values_.count(key) > 0; }
  // Rejects keys outside allowed.
  void CheckKeys(const std::vector<std::string>& allowed) const {
    const std::set<std::string> known(allowed.begin(), allowed.end());
    for (const auto& [key, node] : key_nodes_) {
      if (known.count(key) == 0) {
        Fail(key, LineOf(node), "unknown key; expected one of: " + Join(allowed));
      }
    }
  }
  const YAML::Node& Get(const std::string& key) const {
    const auto it = values_.find(key);
    if (it == values_.end()) Fail(key, line_, "missing key '" + prefix_ + key + "'");
    return it->second;
  }
  // A finite number.
  double Number(const std::string& key) const { return NumberOf(Get(key), key, "a number"); }
  // A number > 0.
  double Positive(const std::string& key) const {
    const double value = Number(key);
    if (!(value > 0.0)) Fail(key, LineOf(Get(key)), "must be > 0, got " + Get(key).Scalar());
    return value;
  }
  // A whole number.
  long long Integer(const std::string& key) const {
    const YAML::Node& node = Get(key);
    long long value = 0;
    if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value)) {
      Fail(key, LineOf(node), "expected a whole number, got " + Describe(node));
    }
    return value;
  }
  // A list of exactly n finite numbers.
  Eigen::VectorXd Numbers(const std::string& key, int n) const { return NumbersOf(Get(key), key, n); }
  // The same for a node below key (a list element).
  Eigen::VectorXd NumbersOf(const YAML::Node& node, const std::string& key, int n) const {
    const std::string expected = "a list of " + std::to_string(n) + " numbers";
    if (!node.IsSequence() || static_cast<int>(node.size()) != n) {
      Fail(key, LineOf(node), "expected " + expected + ", got " + Describe(node));
    }
    Eigen::VectorXd values(n);
    for (int i = 0; i < n; ++i) values[i] = NumberOf(node[static_cast<std::size_t>(i)], key, expected);
    return values;
  }
  // A list of all-positive numbers.
  Eigen::VectorXd Sizes(const std::string& key, int n) const {
    const Eigen::VectorXd values = Numbers(key, n);
    if ((values.array() <= 0.0).any()) Fail(key, LineOf(Get(key)), "every size must be > 0");
    return values;
  }
  int line() const { return line_; }

 private:
  double NumberOf(const YAML::Node& node, const std::string& key, const std::string& expected) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      Fail(key, LineOf(node), "expected " + expected + ", got " + Describe(node));
    }
    if (!std::isfinite(value)) Fail(key, LineOf(node), "must be finite, got " + node.Scalar());
    return value;
  }

  std::string file_;                             // file label for errors
  std::string context_;                          // "world entry <i> (<type>): "
  std::string prefix_;                           // key prefix in errors
  int line_;                                     // line of the map itself
  std::map<std::string, YAML::Node> values_;     // key -> value
  std::map<std::string, YAML::Node> key_nodes_;  // key -> key node (for its line)
};

// Rotation from roll/pitch/yaw in degrees, R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d RotationOf(const EntryReader& entry) {
  if (!entry.Has("rpy_deg")) return Eigen::Matrix3d::Identity();
  Extrinsic orientation;
  orientation.rpy_deg = entry.Numbers("rpy_deg", 3);
  return orientation.ToIsometry().linear();
}

using Factory = std::function<std::unique_ptr<Primitive>(const Eigen::Vector3d& offset)>;

// Reads one entry's shape keys; the result makes the primitive moved by an offset.
Factory ReadShape(const std::string& type, const EntryReader& entry) {
  if (type == "box") {
    const Eigen::Vector3d center = entry.Numbers("center", 3);
    const Eigen::Vector3d size = entry.Sizes("size", 3);
    const Eigen::Matrix3d R = RotationOf(entry);
    return [=](const Eigen::Vector3d& offset) { return std::make_unique<BoxPrimitive>(center + offset, size, R); };
  }
  if (type == "plane") {
    const Eigen::Vector3d center = entry.Numbers("center", 3);
    const Eigen::Vector2d size = entry.Sizes("size", 2);
    const Eigen::Matrix3d R = RotationOf(entry);
    return [=](const Eigen::Vector3d& offset) { return std::make_unique<PlanePrimitive>(center + offset, size, R); };
  }
  if (type == "cylinder") {
    const Eigen::Vector3d base = entry.Numbers("base", 3);
    const Eigen::Vector3d axis = entry.Numbers("axis", 3);
    if (!(axis.norm() > 0.0)) entry.Fail("axis", LineOf(entry.Get("axis")), "must not be zero");
    const double radius = entry.Positive("radius");
    const double height = entry.Positive("height");
    return [=](const Eigen::Vector3d& offset) {
      return std::make_unique<CylinderPrimitive>(base + offset, axis, radius, height);
    };
  }
  if (type == "sphere") {
    const Eigen::Vector3d center = entry.Numbers("center", 3);
    const double radius = entry.Positive("radius");
    return [=](const Eigen::Vector3d& offset) { return std::make_unique<SpherePrimitive>(center + offset, radius); };
  }
  // heightfield
  const Eigen::Vector3d center = entry.Numbers("center", 3);
  const Eigen::Vector2d size = entry.Sizes("size", 2);
  const double z0 = entry.Has("z0") ? entry.Number("z0") : 0.0;
  std::vector<HeightfieldPrimitive::Wave> waves;
  if (entry.Has("waves")) {
    const YAML::Node& list = entry.Get("waves");
    if (!list.IsSequence()) {
      entry.Fail("waves", LineOf(list),
                 "expected a list of [amplitude, kx, ky, phi, psi] lists, got " + Describe(list));
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Eigen::VectorXd w = entry.NumbersOf(list[i], "waves", 5);
      waves.push_back(HeightfieldPrimitive::Wave{w[0], w[1], w[2], w[3], w[4]});
    }
  }
  return [=](const Eigen::Vector3d& offset) {
    return std::make_unique<HeightfieldPrimitive>(center + offset, size, z0, waves);
  };
}

// Adds the primitives of one list entry (item is 1-based) to world.
void AddEntry(const YAML::Node& node, std::size_t item, const std::string& file, World* world) {
  const std::string where = "world entry " + std::to_string(item);
  if (!node.IsMap()) {
    throw ConfigError(file, LineOf(node), "type",
                      where + ": expected a map such as {type: box, ...}, got " + Describe(node));
  }
  const EntryReader untyped(node, file, where + ": ", "");
  const std::string expected_types = "box, plane, cylinder, sphere, heightfield";
  const YAML::Node& type_node = untyped.Get("type");
  const std::string type = type_node.IsScalar() ? type_node.Scalar() : std::string();
  const auto keys = KeysByType().find(type);
  if (keys == KeysByType().end()) {
    untyped.Fail("type", LineOf(type_node),
                 "unknown type " + Describe(type_node) + "; expected one of: " + expected_types);
  }
  const EntryReader entry(node, file, where + " (" + type + "): ", "");
  std::vector<std::string> allowed = {"type"};
  allowed.insert(allowed.end(), keys->second.required.begin(), keys->second.required.end());
  allowed.insert(allowed.end(), keys->second.optional.begin(), keys->second.optional.end());
  entry.CheckKeys(allowed);
  for (const std::string& key : keys->second.required) entry.Get(key);  // missing -> error
  const Factory make = ReadShape(type, entry);

  long long count = 1;
  Eigen::Vector3d step = Eigen::Vector3d::Zero();
  if (entry.Has("repeat")) {
    const YAML::Node& repeat_node = entry.Get("repeat");
    if (!repeat_node.IsMap()) {
      entry.Fail("repeat", LineOf(repeat_node),
                 "expected {count: n, step: [dx, dy, dz]}, got " + Describe(repeat_node));
    }
    const EntryReader repeat(repeat_node, file, where + " (" + type + "): ", "repeat.");
    repeat.CheckKeys({"count", "step"});
    count = repeat.Integer("count");
    if (count < 1 || count > kMaxRepeatCount) {
      repeat.Fail("count", LineOf(repeat.Get("count")),
                  "must be between 1 and " + std::to_string(kMaxRepeatCount) + ", got " + std::to_string(count));
    }
    step = repeat.Numbers("step", 3);
  }
  for (long long i = 0; i < count; ++i) {
    try {
      world->Add(make(static_cast<double>(i) * step));
    } catch (const std::invalid_argument& e) {  // e.g. a copy moved to non-finite coordinates
      throw ConfigError(file, entry.line(), "", where + " (" + type + "): " + e.what());
    }
  }
}

}  // namespace

World LoadWorld(const YAML::Node& primitives_list, const std::string& file_label) {
  if (!primitives_list.IsDefined() || !primitives_list.IsSequence()) {
    throw ConfigError(
        file_label, LineOf(primitives_list), "world",
        "expected a list of primitives, got " + (primitives_list.IsDefined() ? Describe(primitives_list) : "nothing"));
  }
  World world;
  for (std::size_t i = 0; i < primitives_list.size(); ++i) {
    AddEntry(primitives_list[i], i + 1, file_label, &world);
  }
  world.Build();
  return world;
}

std::string DescribeWorld(const World& world) {
  std::map<std::string, int> kinds;
  for (std::size_t i = 0; i < world.size(); ++i) ++kinds[world.primitive(i).Kind()];
  std::ostringstream out;
  out << world.size() << " primitives";
  if (!kinds.empty()) {
    out << " (";
    bool first = true;
    for (const auto& [kind, n] : kinds) {
      out << (first ? "" : ", ") << n << " " << kind;
      first = false;
    }
    out << ")";
  }
  const Eigen::AlignedBox3d bounds = world.Bounds();
  if (!bounds.isEmpty()) {
    const auto vec = [](const Eigen::Vector3d& v) {
      std::ostringstream text;
      text << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
      return text.str();
    };
    out << ", bounds " << vec(bounds.min()) << " .. " << vec(bounds.max()) << " m";
  }
  return out.str();
}

}  // namespace unimap::sim
