#pragma once
// The bash completion script, written from the command line as registered
// (so from the same parameter tables): `penumbra completion` prints it,
// and the build installs it as share/bash-completion/completions/penumbra.
#include <CLI/CLI.hpp>
#include <string>

namespace penumbra {

// A script that defines _penumbra and registers it for `penumbra`: it
// completes the commands, each command's options, and option values:
// names from each option's choices (LIST options after a comma too),
// files for FILE options, folders for FOLDER ones.
std::string bash_completion_script(const CLI::App& app);

}  // namespace penumbra
