// Built into every program of a sanitizer build (cmake/RtproSanitizers.cmake): the sanitizers'
// default options, so ctest, the fuzzers and a developer's own run all behave the same without
// environment variables. ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS still override them.

extern "C" {

// Stop at the first finding with a stack trace; a test that triggers undefined behaviour fails.
const char* __asan_default_options() { return "abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=1"; }
const char* __ubsan_default_options() { return "halt_on_error=1:print_stacktrace=1"; }

// Leaks inside Debian's uninstrumented libraries that rtpro cannot free, one line each with why.
const char* __lsan_default_suppressions() {
  return
      // OpenImageIO 2.4.7: ImageInput::geterror() copies the message out of its thread-local
      // error map and the copy left in the map is never freed (31 bytes per failed read; seen
      // reading a PNG whose header declares 65535x65535 pixels). rtpro only calls geterror().
      "leak:OpenImageIO_v2_4::ImageInput::geterror\n";
}

}  // extern "C"
