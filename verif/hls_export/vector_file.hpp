// The golden-vector generator's pieces (cig_hls_vectors: write_vectors.cpp and one file per stage's
// writers): a vector file that runs each added input through its testbench case, and the writers
// of the stages that live in their own files.
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

// Stage A (write_vectors_manager.cpp): manager_channel_setup_top, manager_visibility_top.
void write_manager_vectors(const std::string& dir, const std::string& scenes);
// Stage F (write_vectors_invparam.cpp): invparam_column_top, invparam_pixel_processor_top.
void write_invparam_vectors(const std::string& dir, const std::string& scenes);

}  // namespace cig::hls_tb
