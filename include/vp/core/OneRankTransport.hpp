#pragma once
// A job of one rank has no peer to reach, yet Open MPI's default transport (UCX) probes the
// network devices in MPI_Init: 0.25 s of every one-rank run on the development machine (an
// empty run through mpirun -n 1: 0.57 s against 0.33 s, benchmarks/RESULTS.md). When mpirun
// says the job has one rank (OMPI_COMM_WORLD_SIZE=1) and the user chose no point-to-point layer
// (OMPI_MCA_pml unset), vpsolve asks for Open MPI's own (ob1) before MPI starts. Any other
// launch, MPI or rank count is left alone.

namespace vp {

// Call before PetscInitialize.
void useLocalTransportForOneRank();

} // namespace vp
