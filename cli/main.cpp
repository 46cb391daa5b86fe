// lutkit: the command-line front end. Everything lives in the lutkit_cli library
// (CommandLine.h: the subcommands of commands/, help, errors and exit codes).
#include "CommandLine.h"

int main(int argc, char** argv) {
    return lut::cli::CommandLine().run(argc, argv);
}
