// SPDX-License-Identifier: BSD-3-Clause
// The plain driver of a fuzz target, for builds without libFuzzer (g++): feeds every file of the
// directories (or the files) given to LLVMFuzzerTestOneInput, once, in name order. The ctests
// fuzz.<target>.corpus run it on the committed corpus, crash inputs included, so every bug the
// fuzzer found stays fixed. Exit 0 when every input ran; a bug crashes or aborts.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int a = 1; a < argc; ++a)
  {
    std::error_code ec;
    if (fs::is_directory(argv[a], ec))
    {
      for (const fs::directory_entry& entry : fs::directory_iterator(argv[a], ec))
      {
        if (entry.is_regular_file())
        {
          inputs.push_back(entry.path());
        }
      }
    }
    else if (fs::is_regular_file(argv[a], ec))
    {
      inputs.emplace_back(argv[a]);
    }
    else
    {
      std::cerr << argv[0] << ": '" << argv[a] << "' is not a file or directory\n";
      return 2;
    }
  }
  if (inputs.empty())
  {
    std::cerr << argv[0] << ": no inputs (usage: " << argv[0] << " CORPUS_DIR|FILE...)\n";
    return 2;
  }
  std::sort(inputs.begin(), inputs.end());
  for (const fs::path& input : inputs)
  {
    std::ifstream in(input, std::ios::binary);
    const std::vector<char> bytes(
      (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof())
    {
      std::cerr << argv[0] << ": cannot read '" << input.string() << "'\n";
      return 2;
    }
    std::cout << "input " << input.filename().string() << " (" << bytes.size() << " bytes)"
              << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << inputs.size() << " inputs ran" << std::endl;
  return 0;
}
