// A shared library that is not a Plywood plug-in: loading it must fail with one line naming the
// file and the missing entry point (tests/plugin_errors_test.cc).
extern "C" int not_a_plywood_plugin() { return 42; }
