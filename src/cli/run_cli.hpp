#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace cosmems {

/// The `cosmems` command line of doc/cli.md, in process: `args` without the program name,
/// results on `out`, diagnostics on `err`. Returns the exit status: 0 success; 2 invalid input
/// (scene errors, bad usage, an unknown scene, an unreadable file or unwritable --out), with
/// exactly one line on `err`; 3 numerical failure, with the result still printed and its
/// `status` saying why; 1 an internal error (out of memory, a bug), also one line.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace cosmems
