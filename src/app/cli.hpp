#pragma once
// The `penumbra` command line. Returns the process exit status: 0 on
// success, 2 for usage errors, 1 for run-time failures; every error is one
// line "penumbra: error: ..." on stderr.
namespace penumbra {

int run_cli(int argc, char** argv);

}  // namespace penumbra
