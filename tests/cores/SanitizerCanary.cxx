// SPDX-License-Identifier: BSD-3-Clause
// A program with deliberate bugs, built only with MESOLIGHT_SANITIZER_CANARY=ON: under
// AddressSanitizer + UndefinedBehaviorSanitizer each mode must end the program with a report, so
// that its ctest fails. scripts/sanitize-cores.sh with MESOLIGHT_SANITIZE_CANARY=1 shows the stage
// failing (docs/fuzzing.md); without the sanitizers both modes exit 0, unnoticed.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

int main(int argc, char** argv)
{
  const int extra = argc; // not known to the compiler: the bugs cannot be folded away
  if (argc > 1 && std::strcmp(argv[1], "heap") == 0)
  {
    std::vector<int> values(4, 0);
    int* data = values.data();
    data[3 + extra - 1] = 1; // one past the end (argc is 2)
    std::printf("heap: wrote past the end, unnoticed\n");
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "signed") == 0)
  {
    const int big = std::numeric_limits<int>::max() - 1;
    const int sum = big + extra; // overflows (argc is 2)
    std::printf("signed: %d, unnoticed\n", sum);
    return 0;
  }
  std::fprintf(stderr, "usage: %s heap|signed\n", argv[0]);
  return 2;
}
