# -*- Python -*-
# Runs the gtest unit tests (every *Tests binary under build/unittests).

import os

import lit.formats

config.name = "SIM-Unit"
config.suffixes = []
config.test_exec_root = os.path.join(config.sim_obj_root, "unittests")
config.test_source_root = config.test_exec_root
config.test_format = lit.formats.GoogleTest(".", "Tests")
