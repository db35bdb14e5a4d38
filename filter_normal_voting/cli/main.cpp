// nvv: Normal Vector Voting from the command line. Reads a mesh, runs the filter with the
// parameters of nvv::FilterParameterTable(), applies the results as the MeshLab plugin does
// and writes the full-result PLY (io/result_ply.h). See `nvv --help` and docs/cli.md; the
// whole tool is cli_main.h.
#include "cli/cli_main.h"

int main(int argc, char** argv) { return nvv_cli::Main(argc, argv); }
