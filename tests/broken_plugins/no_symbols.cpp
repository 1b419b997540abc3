// libunimap_payload_no_symbols.so: a loadable shared library without any
// unimap symbol (the loader must answer NotAPluginError).
extern "C" __attribute__((visibility("default"))) int unimap_test_unrelated_function(int x) { return x + 1; }
