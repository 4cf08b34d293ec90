// libsystemc's main() calls sc_main; the tests have their own main (GoogleTest), so this is never
// run, but the library needs the symbol.
extern "C" int sc_main(int, char**) { return 0; }
