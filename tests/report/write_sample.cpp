// write_sample_report <path.html>: writes the sample report (for a look in a browser, and for the
// headless-Chromium render check).
#include <cstdio>
#include <exception>

#include "tests/report/sample_report.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <out.html>\n", argv[0]);
    return 2;
  }
  try {
    sinsim::report::testing::samplePage().write(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
