#pragma once
// The fixture of the payload conformance suite (private to
// libunimap_conformance; not installed).
#include <string>

#include <gtest/gtest.h>

#include "unimap/BodyScan.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/PayloadPlugin.hpp"
#include "unimap/PluginLoader.hpp"

namespace unimap::conformance {

// Value-parameterised over plugin library paths: SetUp loads the library
// (PluginLoader::Load) and configures the plugin with its own defaults; a
// failure to do either fails the test with the loader's message.
class PayloadConformanceTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override;

  // The configured plugin (valid after a successful SetUp).
  PayloadPlugin& plugin() const { return *loaded_.plugin; }
  // The plugin with the library it came from.
  const LoadedPlugin& loaded() const { return loaded_; }
  // Defaults().DefaultMap() of the plugin.
  ParameterMap DefaultMap() const;
  // "<payload name>" for messages.
  std::string Label() const;

  // True when a and b are bit-for-bit equal (reference time, drop count and
  // every point's position, time, intensity and ring); *why names the first
  // difference.
  static bool Identical(const BodyScan& a, const BodyScan& b, std::string* why);

 private:
  LoadedPlugin loaded_;
};

}  // namespace unimap::conformance
