// The hand-off testbench's main, shared by every kernel: replays a golden vector file through the
// kernel's top and compares every output bit. Each bundle's tb/tb_<top>.cpp (written by
// tools/hls_export.sh) includes its case, <top>.hpp, and this, and instantiates CIG_TB_MAIN(<top>).
//
//   tb_<top> [VECTORS]   replay VECTORS (default vectors/<top>.vec, else <top>.vec in the folder it
//                        runs in); exit 0 when every vector matches, 1 on any difference (the first
//                        differing field of each vector is printed), 2 when the file is missing,
//                        malformed or holds no vector
//   tb_<top> --ports     print the top's ports (direction, interface, C++ type, bits, fields) as
//                        Markdown rows
//
// Vector file: '#' comment lines; "top NAME"; then per vector a "> inputs" line followed by a
// "< outputs" line, the records written as vector_io.hpp describes.
#pragma once

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "top_case.hpp"

namespace cig {
namespace hls_tb {

// Reads the next non-comment line; false at the end of the file.
inline bool next_line(std::istream& in, std::string& line, int& number) {
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line[0] != '#') return true;
  }
  return false;
}

template <class T>
bool parse_record(const std::string& text, T& record, const std::string& where) {
  TextReader reader(text);
  reader.read(record);
  reader.finish();
  if (reader.error().empty()) return true;
  std::cerr << where << ": " << reader.error() << '\n';
  return false;
}

template <class Case>
int replay(const std::string& file) {
  std::ifstream in(file);
  if (!in) return std::cerr << file << ": cannot read the vector file\n", 2;
  std::string line;
  int number = 0;
  const std::string header = std::string("top ") + Case::kTop;
  if (!next_line(in, line, number) || line != header)
    return std::cerr << file << ":" << number << ": the first line must be '" << header << "'\n", 2;
  int vectors = 0, failed = 0;
  while (next_line(in, line, number)) {
    const std::string at = file + ":" + std::to_string(number);
    if (line.rfind("> ", 0) != 0) return std::cerr << at << ": expected a '> inputs' line\n", 2;
    auto input = std::make_unique<typename Case::Input>();
    auto expected = std::make_unique<typename Case::Output>();
    auto got = std::make_unique<typename Case::Output>();
    if (!parse_record(line.substr(2), *input, at)) return 2;
    if (!next_line(in, line, number) || line.rfind("< ", 0) != 0)
      return std::cerr << file << ":" << number << ": expected a '< outputs' line after line " << at << "\n", 2;
    if (!parse_record(line.substr(2), *expected, file + ":" + std::to_string(number))) return 2;
    Case::run(*input, *got);
    const std::string diff = first_difference(*expected, *got);
    if (!diff.empty()) {
      ++failed;
      std::cout << Case::kTop << ": vector " << vectors << " (" << at << ") differs: " << diff << '\n';
    }
    ++vectors;
  }
  if (vectors == 0) return std::cerr << file << ": no vectors\n", 2;
  std::cout << Case::kTop << ": " << vectors - failed << " of " << vectors << " vectors match\n";
  return failed == 0 ? 0 : 1;
}

template <class Case>
int testbench_main(int argc, char** argv) {
  // In the bundle, or where Vitis's tb.file copies it (the folder the testbench runs in).
  std::string file = std::string("vectors/") + Case::kTop + ".vec";
  if (!std::ifstream(file)) file = std::string(Case::kTop) + ".vec";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--ports") {
      PortPrinter printer;
      Case::ports(printer);
      return 0;
    }
    if (a.empty() || a[0] == '-' || k + 1 < argc) {
      std::cerr << "usage: tb_" << Case::kTop << " [VECTORS] | --ports\n";
      return 2;
    }
    file = a;
  }
  return replay<Case>(file);
}

}  // namespace hls_tb
}  // namespace cig

// The testbench's main (CCS_MAIN under Catapult's SCVerify).
#ifdef CCS_SCVERIFY
#define CIG_TB_MAIN(top) \
  CCS_MAIN(int argc, char** argv) { CCS_RETURN(cig::hls_tb::testbench_main<cig::hls_tb::top##_tb::Case>(argc, argv)); }
#else
#define CIG_TB_MAIN(top) \
  int main(int argc, char** argv) { return cig::hls_tb::testbench_main<cig::hls_tb::top##_tb::Case>(argc, argv); }
#endif

#ifdef CIG_HLS_SYSTEMC
// SystemC's library defines main() and calls sc_main; the testbench has its own main.
int sc_main(int, char**) { return 0; }
#endif
