// LD_PRELOADed into the app under LeakSanitizer (scripts/stress.sh asan): libraries are never
// unloaded, so that what a driver keeps in its own statics stays reachable at exit. Mesa's
// driver is unloaded when the GL context goes, and the few hundred bytes its statics still held
// were reported as leaks from an "<unknown module>" (no name left to suppress them by).
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
