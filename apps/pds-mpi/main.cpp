// pds-mpi: `pds chunks` split over the processes of an MPI job. Run as
//   mpirun -np P pds-mpi chunks --radius R --region ... --chunk C -o DIR
// with exactly the options of `pds chunks` (the same parser and writer,
// apps/pds/unbounded.cpp): process k writes the chunks i with i mod P = k,
// and process 0 the manifest once all have written theirs (an all-reduce of
// the chunks' counts is the barrier). The files are those of `pds chunks`,
// byte for byte, for any P. docs/unbounded.md: on a cluster.
// Exit status as pds: 0 success, 2 bad usage or input, 1 failure.

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "commands.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  CLI::App app{"pds-mpi: the chunks of the unbounded Poisson disk field, over the processes of an MPI job.\n"};
  app.name("pds-mpi");
  app.require_subcommand(1);
  pds::cli::ChunkTeam team;
  team.rank = rank;
  team.size = size;
  team.max_all = [](std::vector<std::int64_t>& values) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
  };
  pds::cli::add_chunks(app, team);
  // Bad usage is the same on every process: only process 0 says so.
  const int status = pds::cli::run_app(app, argc, argv, rank != 0);
  MPI_Finalize();
  return status;
}
