// libunimap_payload_factory_throws.so: a correctly exported plugin whose
// constructor, and hence its factory, throws (the loader must answer
// PluginFactoryError).
#include <stdexcept>

#include "MinimalPlugin.hpp"
#include "unimap/PluginExport.hpp"

namespace unimap_test {

class ThrowingPlugin : public MinimalPlugin {
 public:
  ThrowingPlugin() { throw std::runtime_error("deliberate failure in ThrowingPlugin()"); }
};

}  // namespace unimap_test

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap_test::ThrowingPlugin)
