# -*- Python -*-
# Runs the runtime's gtest binary (runtime/test: bundle reader, executor on
# the CPU backend, C API, sim-run). The runtime is a CMake project of its
# own, so its tests live in its build tree.

import lit.formats

config.name = "SIM-Runtime"
config.suffixes = []
config.test_exec_root = config.sim_runtime_test_dir
config.test_source_root = config.test_exec_root
config.test_format = lit.formats.GoogleTest(".", "Tests")
