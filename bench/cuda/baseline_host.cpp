//===- baseline_host.cpp - The CUDA baseline's kernels, run on the host ---===//
//
// baseline.cu compiled by a C++ compiler: cuda_compat.h emulates the CUDA
// it uses, so CI checks the hand-written kernels without a GPU.
//
//===----------------------------------------------------------------------===//

#include "baseline.cu"
