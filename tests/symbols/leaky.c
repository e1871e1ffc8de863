/* leaky.c - a library that breaks the seal, for the self-test of
   cmake/CheckSymbols.cmake (test lib_symbols_selftest, expected to fail):
   one public name, one ssda__ internal, one bare global (as stream_rect
   was before the library was sealed). */
int ssda_match(void);
int ssda__kept_internal(void);
int stream_rect(void);

int ssda_match(void) { return 0; }
int ssda__kept_internal(void) { return 1; }
int stream_rect(void) { return 2; }
