// Built into every program of a sanitizer build (cmake/RtproSanitizers.cmake): the sanitizers'
// default options, so ctest, the fuzzers and a developer's own run all behave the same without
// environment variables. ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS still override them.

extern "C" {

// Stop at the first finding with a stack trace; a test that triggers undefined behaviour fails.
// intercept_tls_get_addr=0: clang 14's LeakSanitizer tracks the dynamic TLS blocks of dlopened
// libraries through __tls_get_addr, and once the image layer has opened OpenImageIO's chain of
// libraries its leak check at exit read a stale block ("DTLS 29 at 0xc46-0x800001d48") and its
// tracer died with signal 11 on every image read (rtpro compare, the image-layer and hostile-image
// tests): a crash that came and went with the executable's layout (adding the path integrator's
// code set it off; removing its one thread_local did not). Without the interception the leak
// check runs and passes; only pointers held solely in those libraries' dynamic TLS go unseen.
const char* __asan_default_options() {
  return "abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0";
}
const char* __ubsan_default_options() { return "halt_on_error=1:print_stacktrace=1"; }

// Leaks inside Debian's uninstrumented libraries that rtpro cannot free, one line each with why.
const char* __lsan_default_suppressions() {
  return
      // OpenImageIO 2.4.7: ImageInput::geterror() copies the message out of its thread-local
      // error map and the copy left in the map is never freed (31 bytes per failed read; seen
      // reading a PNG whose header declares 65535x65535 pixels). rtpro only calls geterror().
      "leak:OpenImageIO_v2_4::ImageInput::geterror\n"
      // OpenVDB 10.0.1 (tree/RootNode.h, tree/InternalNode.h): readTopology allocates each child
      // and reads it before inserting it, so a child whose values fail to decompress (a corrupt
      // Blosc or zlib stream of the right size, found by the vdb fuzz target) is lost with its
      // subtree when the error propagates: once per failed read, bounded by the file's nodes.
      "leak:openvdb::v10_0::tree::*::readTopology\n";
}

}  // extern "C"
