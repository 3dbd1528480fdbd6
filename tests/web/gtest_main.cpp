// GoogleTest's main for the core's tests compiled to WebAssembly: runs them, prints as usual (to
// the page's console), then hands the result to the harness page (gtest.html), which the
// browser test reads.
#include <emscripten.h>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const int failed = RUN_ALL_TESTS();
  EM_ASM({ window.gtestFinished($0); }, failed);
  return failed;
}
