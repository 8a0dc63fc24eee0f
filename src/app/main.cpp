#include "app/cli.hpp"

int main(int argc, char** argv) {
  return penumbra::run_cli(argc, argv);
}
