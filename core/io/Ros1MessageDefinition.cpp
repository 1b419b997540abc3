#include "io/Ros1MessageDefinition.hpp"

#include <cstring>
#include <functional>
#include <set>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Fixed sizes of the primitives (string: variable, 0 here).
const std::map<std::string, std::size_t>& Primitives() {
  static const std::map<std::string, std::size_t> sizes = {
      {"bool", 1},    {"int8", 1},  {"uint8", 1},    {"byte", 1},  {"char", 1},   {"int16", 2},
      {"uint16", 2},  {"int32", 4}, {"uint32", 4},   {"int64", 8}, {"uint64", 8}, {"float32", 4},
      {"float64", 8}, {"time", 8},  {"duration", 8}, {"string", 0}};
  return sizes;
}

bool IsPrimitive(const std::string& type) { return Primitives().count(type) > 0; }

std::string Trim(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string Package(const std::string& type) {
  const std::size_t slash = type.find('/');
  return slash == std::string::npos ? "" : type.substr(0, slash);
}

// Resolves a field's type name as ROS 1 does: primitives as they are,
// "Header" as std_msgs/Header, a bare name in the enclosing package.
std::string Resolve(const std::string& name, const std::string& enclosing) {
  if (IsPrimitive(name) || name.find('/') != std::string::npos) return name;
  if (name == "Header") return "std_msgs/Header";
  return Package(enclosing) + "/" + name;
}

constexpr int kMaxDepth = 32;  // nesting deeper than this is a definition error
// A type whose fields, expanded through its nested (non-array) types, number
// more than this is refused: a small text can name a type holding two of
// the next, 30 deep (2^30 fields).
constexpr std::size_t kMaxExpandedFields = 100000;

}  // namespace

Ros1MessageDefinition::Ros1MessageDefinition(const std::string& type, const std::string& definition) : type_(type) {
  std::istringstream in(definition);
  std::string line;
  std::string current = type;
  int line_number = 0;
  auto fail = [&](const std::string& reason) {
    throw InputError("message definition of " + type + ", line " + std::to_string(line_number) + ": " + reason);
  };
  types_[current];
  while (std::getline(in, line)) {
    ++line_number;
    const std::string text = Trim(line.substr(0, line.find('#')));
    if (text.empty()) continue;
    if (text.find_first_not_of('=') == std::string::npos) continue;  // separator
    if (text.rfind("MSG:", 0) == 0) {
      current = Trim(text.substr(4));
      if (current.empty()) fail("MSG: without a type");
      types_[current];
      continue;
    }
    std::istringstream words(text);
    std::string field_type, name;
    if (!(words >> field_type >> name)) fail("expected 'type name': '" + text + "'");
    if (name.find('=') != std::string::npos || text.find('=') != std::string::npos) continue;  // a constant
    Field f;
    f.name = name;
    const std::size_t bracket = field_type.find('[');
    if (bracket != std::string::npos) {
      const std::size_t close = field_type.find(']', bracket);
      if (close == std::string::npos) fail("unclosed '[' in '" + field_type + "'");
      f.is_array = true;
      const std::string count = field_type.substr(bracket + 1, close - bracket - 1);
      if (!count.empty()) {
        if (count.find_first_not_of("0123456789") != std::string::npos || count.size() > 9) {
          fail("bad array size '" + count + "'");
        }
        f.fixed_count = std::stoll(count);
      }
      field_type = field_type.substr(0, bracket);
    }
    f.type = Resolve(field_type, current);
    types_[current].push_back(f);
  }
  // Every nested type must be defined.
  for (const auto& [name, fields] : types_) {
    for (const Field& f : fields) {
      if (!IsPrimitive(f.type) && types_.count(f.type) == 0) {
        throw InputError("message definition of " + type + ": " + name + "." + f.name + " has type " + f.type +
                         ", which the definition does not define");
      }
    }
  }
  // No type may hold itself outside an array (it could not be serialized),
  // and none may expand into too many fields.
  std::map<std::string, std::size_t> expanded;  // type -> its fields expanded (done)
  std::set<std::string> open;                   // types being expanded
  const std::function<std::size_t(const std::string&, int)> expand = [&](const std::string& t, int depth) {
    if (const auto done = expanded.find(t); done != expanded.end()) return done->second;
    if (open.count(t) > 0) throw InputError("message definition of " + type + ": " + t + " contains itself");
    if (depth > kMaxDepth) throw InputError("message definition of " + type + ": types nest too deeply");
    open.insert(t);
    std::size_t count = 0;
    for (const Field& f : types_.at(t)) {
      count += 1 + (IsPrimitive(f.type) || f.is_array ? 0 : expand(f.type, depth + 1));
      if (count > kMaxExpandedFields) {
        throw InputError("message definition of " + type + ": " + t + " expands to more than " +
                         std::to_string(kMaxExpandedFields) + " fields");
      }
    }
    open.erase(t);
    expanded[t] = count;
    return count;
  };
  for (const auto& entry : types_) expand(entry.first, 0);
}

std::size_t Ros1MessageDefinition::SizeOf(const std::string& type, const std::uint8_t* data, std::size_t size,
                                          std::size_t offset, int depth) const {
  if (depth > kMaxDepth) throw InputError("message definition of " + type_ + ": " + type + " nests too deeply");
  auto need = [&](std::size_t bytes) {
    if (offset > size || size - offset < bytes) {
      throw InputError(type_ + " message of " + std::to_string(size) + " bytes is shorter than its definition");
    }
  };
  const auto primitive = Primitives().find(type);
  if (primitive != Primitives().end()) {
    if (type != "string") {
      need(primitive->second);
      return primitive->second;
    }
    need(4);
    std::uint32_t length = 0;
    std::memcpy(&length, data + offset, 4);
    need(4 + static_cast<std::size_t>(length));
    return 4 + static_cast<std::size_t>(length);
  }
  std::size_t total = 0;
  for (const Field& f : types_.at(type)) total += SizeOfField(f, data, size, offset + total, depth + 1);
  return total;
}

std::size_t Ros1MessageDefinition::SizeOfField(const Field& f, const std::uint8_t* data, std::size_t size,
                                               std::size_t offset, int depth) const {
  if (!f.is_array) return SizeOf(f.type, data, size, offset, depth);
  std::size_t total = 0;
  std::uint64_t count = static_cast<std::uint64_t>(f.fixed_count);
  if (f.fixed_count < 0) {
    if (offset > size || size - offset < 4) {
      throw InputError(type_ + " message of " + std::to_string(size) + " bytes is shorter than its definition");
    }
    std::uint32_t n = 0;
    std::memcpy(&n, data + offset, 4);
    count = n;
    total = 4;
  }
  const auto primitive = Primitives().find(f.type);
  if (primitive != Primitives().end() && f.type != "string") {
    const std::uint64_t bytes = count * primitive->second;
    if (offset + total > size || size - offset - total < bytes) {
      throw InputError(type_ + " message of " + std::to_string(size) + " bytes is shorter than its definition");
    }
    return total + static_cast<std::size_t>(bytes);
  }
  // Each element takes a byte at least (an array of empty types is no
  // exception worth reading): more elements than bytes left is a truncation.
  if (offset + total > size || count > size - offset - total) {
    throw InputError(type_ + " message of " + std::to_string(size) + " bytes is shorter than its definition");
  }
  for (std::uint64_t i = 0; i < count; ++i) total += SizeOf(f.type, data, size, offset + total, depth);
  return total;
}

std::vector<std::string> Ros1MessageDefinition::FieldsOfType(const std::string& type) const {
  std::vector<std::string> found;
  // Breadth-first over non-array fields, so the outermost come first.
  std::vector<std::pair<std::string, std::string>> level = {{"", type_}};  // (path, its type)
  for (int depth = 0; depth < kMaxDepth && !level.empty(); ++depth) {
    std::vector<std::pair<std::string, std::string>> next;
    for (const auto& [path, t] : level) {
      const auto fields = types_.find(t);
      if (fields == types_.end()) continue;
      for (const Field& f : fields->second) {
        if (f.is_array) continue;
        const std::string child = path.empty() ? f.name : path + "." + f.name;
        if (f.type == type) found.push_back(child);
        if (!IsPrimitive(f.type)) next.emplace_back(child, f.type);
      }
    }
    level = std::move(next);
  }
  return found;
}

std::string Ros1MessageDefinition::TypeOf(const std::string& path) const {
  std::string t = type_;
  std::istringstream parts(path);
  std::string part;
  while (std::getline(parts, part, '.')) {
    const auto fields = types_.find(t);
    if (fields == types_.end()) return "";
    const Field* match = nullptr;
    for (const Field& f : fields->second) {
      if (f.name == part) match = &f;
    }
    if (match == nullptr) return "";
    if (match->is_array) return parts.peek() == EOF ? match->type + "[]" : "";
    t = match->type;
  }
  return t;
}

Ros1MessageDefinition::Span Ros1MessageDefinition::Locate(const std::uint8_t* data, std::size_t size,
                                                          const std::string& path) const {
  std::string t = type_;
  std::size_t offset = 0;
  std::istringstream parts(path);
  std::string part;
  bool any = false;
  while (std::getline(parts, part, '.')) {
    any = true;
    const auto fields = types_.find(t);
    if (fields == types_.end()) throw InputError(type_ + " has no field " + path);
    const Field* match = nullptr;
    for (const Field& f : fields->second) {
      if (f.name == part) {
        match = &f;
        break;
      }
      offset += SizeOfField(f, data, size, offset, 1);
    }
    if (match == nullptr || (match->is_array && parts.peek() != EOF)) throw InputError(type_ + " has no field " + path);
    if (parts.peek() == EOF) return Span{offset, SizeOfField(*match, data, size, offset, 1)};
    t = match->type;
  }
  if (!any) return Span{0, SizeOf(type_, data, size, 0, 0)};
  throw InputError(type_ + " has no field " + path);
}

double Ros1MessageDefinition::ReadNumber(const std::uint8_t* data, std::size_t size, const std::string& path) const {
  const std::string t = TypeOf(path);
  const Span span = Locate(data, size, path);
  const std::uint8_t* p = data + span.offset;
  auto as = [p](auto value) {
    std::memcpy(&value, p, sizeof(value));
    return static_cast<double>(value);
  };
  if (t == "float64") return as(double{});
  if (t == "float32") return as(float{});
  if (t == "int8") return as(std::int8_t{});
  if (t == "uint8" || t == "byte" || t == "char" || t == "bool") return as(std::uint8_t{});
  if (t == "int16") return as(std::int16_t{});
  if (t == "uint16") return as(std::uint16_t{});
  if (t == "int32") return as(std::int32_t{});
  if (t == "uint32") return as(std::uint32_t{});
  if (t == "int64") return as(std::int64_t{});
  if (t == "uint64") return as(std::uint64_t{});
  throw InputError(type_ + "." + path + " is " + (t.empty() ? "not a field" : t) + ", not a number");
}

}  // namespace unimap::io
