// The golden-vector generator's vector file (cig_hls_vectors, write_vectors.cpp): runs each added
// input through its testbench case and writes the inputs and outputs.
#pragma once

#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "tb/vector_io.hpp"

namespace cig::hls_tb {

// One vector file: every add() runs the case, writes its inputs and outputs, and returns the outputs.
template <class Case>
class VectorFile {
 public:
  VectorFile(const std::string& dir, const std::string& what) : path_(dir + "/" + Case::kTop + ".vec"), out_(path_) {
    out_ << "# Golden vectors of " << Case::kTop << ": " << what << ".\n"
         << "# Written by cig_hls_vectors (verif/hls_export/write_vectors.cpp); replayed by tb_" << Case::kTop
         << ".\ntop " << Case::kTop << '\n';
  }
  ~VectorFile() noexcept(false) {
    out_.close();
    if (!out_) throw std::runtime_error(path_ + ": cannot write the vector file");
    std::cout << path_ << ": " << count_ << " vectors\n";
  }
  const typename Case::Output& add(const typename Case::Input& in) {
    last_ = std::make_unique<typename Case::Output>();
    Case::run(in, *last_);
    out_ << '>' << to_text(in) << "\n<" << to_text(*last_) << '\n';
    ++count_;
    return *last_;
  }

 private:
  std::string path_;
  std::ofstream out_;
  int count_ = 0;
  std::unique_ptr<typename Case::Output> last_;
};

}  // namespace cig::hls_tb
