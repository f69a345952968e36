// Writes a synthetic result file for the h5py check (tests/api/check_result_file.py).
//   write_synthetic_result PATH
#include "synthetic_run.hpp"

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_synthetic_result PATH\n";
    return 2;
  }
  slipfront::testing::write_synthetic_file(argv[1], 37, 150);
  return 0;
}
