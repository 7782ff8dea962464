// qmc: command-line front end of the codec.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "commands.h"
#include "cli_common.h"
#include "qmc/format.h"

namespace {

// The first line names the format version this build writes (qmc/format.h).
const char kUsage[] =
    "\n"
    "usage: qmc COMMAND [ARGS]\n"
    "\n"
    "commands:\n"
    "  encode IN OUT.qmc [options]   compress a mesh (.obj .off .ply .stl)\n"
    "  decode IN.qmc OUT             decompress to .obj, .off or .ply\n"
    "  info IN.qmc [--json]          chunks, bytes per component, bits per vertex\n"
    "  verify IN OUT.qmc             decode OUT.qmc and compare it with IN\n"
    "  conform DIR                   check the conformance vectors listed in DIR/MANIFEST\n"
    "  compare A B [--json]          surface distances: Hausdorff, L2 (RMS), mean, PSNR\n"
    "  gim export IN.qmc DIR         a geometry image's planes as 16-bit PNG / PFM files\n"
    "  gim import DIR OUT.qmc        ... and back\n"
    "\n"
    "Positions are quantized to 12 bits per axis by default, which keeps every\n"
    "vertex within 1/4096 of the largest bounding-box side (-q to change).\n"
    "Run 'qmc COMMAND --help' for a command's options.\n"
    "exit codes: 0 ok, 1 check failed (verify, conform), 2 usage, 3 error\n";

// glibc gives every freed block of 128 KB or more back to the system and
// takes the next one with a page fault for each of its pages. An encode or a
// decode frees and allocates tables of the mesh's size stage after stage, so
// a process that runs one of them faults most of its memory in again at each
// stage (stanford-bunny's decode: 2,423 faults; 1,527 with the memory kept).
// This process runs one command and exits: it keeps what it frees for the
// next stage.
void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest; bigger blocks are still mapped apart
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  keep_freed_memory();
  // Past a file-size limit (ulimit -f) a write then fails with EFBIG, which
  // is reported and cleaned up, instead of the signal killing the process
  // with a half-written temporary file left behind.
  std::signal(SIGXFSZ, SIG_IGN);
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    std::FILE* out = argc < 2 ? stderr : stdout;
    std::fprintf(out, "qmc - mesh compression codec (format version %d.%d, spec/qmc-format.md)\n", int(qmc::kFormatMajor),
                 int(qmc::kFormatMinor));
    std::fputs(kUsage, out);
    return argc < 2 ? qmc::cli::kExitUsage : qmc::cli::kExitOk;
  }
  const std::string command = argv[1];
  if (command == "--version") {
    std::printf("qmc %s (format %d.%d)\n", QMC_VERSION, int(qmc::kFormatMajor), int(qmc::kFormatMinor));
    return 0;
  }
  if (command == "encode") return qmc::cli::run_encode(argc - 1, argv + 1);
  if (command == "decode") return qmc::cli::run_decode(argc - 1, argv + 1);
  if (command == "info") return qmc::cli::run_info(argc - 1, argv + 1);
  if (command == "verify") return qmc::cli::run_verify(argc - 1, argv + 1);
  if (command == "conform") return qmc::cli::run_conform(argc - 1, argv + 1);
  if (command == "compare") return qmc::cli::run_compare(argc - 1, argv + 1);
  if (command == "gim") return qmc::cli::run_gim(argc - 1, argv + 1);
  std::fprintf(stderr, "qmc: unknown command '%s'\n\n%s", command.c_str(), kUsage);
  return qmc::cli::kExitUsage;
}
