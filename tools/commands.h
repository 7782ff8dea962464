// The qmc subcommands; each returns the process exit code (cli_common.h).
#pragma once

namespace qmc::cli {

int run_encode(int argc, char** argv);
int run_decode(int argc, char** argv);
int run_info(int argc, char** argv);
int run_verify(int argc, char** argv);
int run_conform(int argc, char** argv);
int run_compare(int argc, char** argv);
int run_gim(int argc, char** argv);

}  // namespace qmc::cli
