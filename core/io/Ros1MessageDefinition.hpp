#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace unimap::io {

// A ROS 1 message type as its definition text describes it (the
// `message_definition` a bag's connection header carries: the type's
// fields, then each type it uses after a line of '=' and "MSG: pkg/Type").
// It locates fields in a serialized message without generated code, so a
// custom message (e.g. a LaserScan followed by a float64 angle) is read by
// what it says it is. Serialization (ROS 1): little-endian primitives,
// string = uint32 length + bytes, time and duration = two 32-bit integers,
// T[] = uint32 count + elements, T[N] = N elements, nested types inline;
// constants are not serialized.
class Ros1MessageDefinition {
 public:
  // Where a field's bytes are in a message.
  struct Span {
    std::size_t offset = 0;
    std::size_t length = 0;
  };

  // Parses `definition` for the message type `type` ("pkg/Name"). Throws
  // InputError naming the type and the line for a field whose type is
  // neither a primitive nor defined in the text, a malformed line, a type
  // that contains itself (outside an array) or one that expands into more
  // than 100,000 fields.
  Ros1MessageDefinition(const std::string& type, const std::string& definition);

  // Top-level field paths (nested with '.', e.g. "laserScan.header.stamp")
  // whose type is `type` ("sensor_msgs/LaserScan", "float64"), outermost
  // first; arrays are not searched.
  std::vector<std::string> FieldsOfType(const std::string& type) const;
  // The type of a field path, "" when there is none (arrays: "T[]").
  std::string TypeOf(const std::string& path) const;
  // Locates the field path in the serialized message [data, data + size).
  // Throws InputError when the message is shorter than its definition says
  // or the path does not exist.
  Span Locate(const std::uint8_t* data, std::size_t size, const std::string& path) const;
  // The value of a numeric primitive field (bool, [u]int8-64, float32/64)
  // as a double; throws InputError like Locate, or for a non-numeric field.
  double ReadNumber(const std::uint8_t* data, std::size_t size, const std::string& path) const;

  const std::string& type() const { return type_; }

 private:
  struct Field {
    std::string type;  // resolved: a primitive or "pkg/Name"
    std::string name;
    bool is_array = false;       // T[] or T[N]
    long long fixed_count = -1;  // N for T[N], -1 for T[]
  };
  // Bytes a value of `type` takes at data[offset...]; throws on truncation.
  std::size_t SizeOf(const std::string& type, const std::uint8_t* data, std::size_t size, std::size_t offset,
                     int depth) const;
  std::size_t SizeOfField(const Field& f, const std::uint8_t* data, std::size_t size, std::size_t offset,
                          int depth) const;
  std::string type_;
  std::map<std::string, std::vector<Field>> types_;  // "pkg/Name" -> its fields in order
};

}  // namespace unimap::io
