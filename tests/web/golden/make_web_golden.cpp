// web_make_golden ROOT [NAME...]: writes the browser's golden files (all, or
// the NAMEs) to ROOT/<name>/<name>.json from the C++ code as it is now.
// `cmake --build <build> --target web_golden` runs it on tests/vectors.
#include <cstdio>
#include <exception>
#include <set>
#include <string>

#include "golden_json.hpp"

int main(int argc, char** argv) {
  using namespace fw::test::web_golden;
  if (argc < 2) {
    std::fprintf(stderr, "usage: web_make_golden ROOT [NAME...]\n");
    return 2;
  }
  const std::set<std::string> wanted(argv + 2, argv + argc);
  try {
    for (const GoldenSet& set : golden_sets()) {
      if (!wanted.empty() && !wanted.contains(set.name)) continue;
      const auto path = golden_path(argv[1], set.name);
      write_golden(path, set.make());
      std::printf("wrote %s\n", path.string().c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "web_make_golden: %s\n", e.what());
    return 1;
  }
  return 0;
}
