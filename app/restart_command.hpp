#pragma once
// The command that continues an interrupted run: the user's own command line, with every
// override it had, pointed at the checkpoint. Rebuilt from argv rather than from the parsed
// options so that an option added later is carried without anyone remembering to.
#include <string>
#include <vector>

namespace tridem::app {

/// `argv` as the program received it (argv[0] first); any --restart it had is replaced by
/// `--restart checkpoint`. Arguments a shell would split or expand are single-quoted.
std::string restart_command(const std::vector<std::string>& argv, const std::string& checkpoint);

}  // namespace tridem::app
