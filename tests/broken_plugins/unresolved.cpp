// libunimap_payload_unresolved.so: a correctly exported plugin that needs a
// function no library defines, so dlopen with RTLD_NOW refuses it (the
// loader must answer PluginLoadError quoting dlerror).
#include "MinimalPlugin.hpp"
#include "unimap/PluginExport.hpp"

// Defined nowhere.
extern "C" int unimap_test_function_defined_nowhere(int x);

namespace unimap_test {

class UnresolvedPlugin : public MinimalPlugin {
 public:
  bool UsesEncoder() const override { return unimap_test_function_defined_nowhere(1) != 0; }
};

}  // namespace unimap_test

UNIMAP_EXPORT_PAYLOAD_PLUGIN(unimap_test::UnresolvedPlugin)
