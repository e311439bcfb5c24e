# -*- Python -*-
# The sim lit suite: FileCheck, --verify-diagnostics and tool tests. The unit
# tests run from test/Unit and the runtime's tests from test/Runtime, each
# with its own configuration.

import os

import lit.formats
from lit.llvm import llvm_config
from lit.llvm.subst import ToolSubst

config.name = "SIM"
config.test_format = lit.formats.ShTest(not llvm_config.use_lit_shell)
config.suffixes = [".mlir", ".test"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = os.path.join(config.sim_obj_root, "test")
config.excludes = ["Inputs", "CMakeLists.txt", "README.txt", "lit.cfg.py",
                   "lit.site.cfg.py", "Unit", "Runtime"]

llvm_config.use_default_substitutions()
llvm_config.with_environment("PATH", config.llvm_tools_dir, append_path=True)

tool_dirs = [config.sim_tools_dir, config.llvm_tools_dir]
tools = [
    "sim-opt",
    "sim-run",
    ToolSubst("%python", config.python_executable, unresolved="fatal"),
]
llvm_config.add_tool_substitutions(tools, tool_dirs)

config.substitutions.append(("%sim_src_root", config.sim_src_root))
config.substitutions.append(("%sim_obj_root", config.sim_obj_root))
config.substitutions.append(("%examples", os.path.join(config.sim_src_root,
                                                        "examples")))

# `dot` renders the dependency graph in tests when Graphviz is installed.
if lit.util.which("dot"):
    config.available_features.add("dot")
