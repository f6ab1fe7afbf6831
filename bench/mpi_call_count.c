// mpi_call_count: an MPI profiling (PMPI) library that counts a process's collective calls and the bytes
// they and the point-to-point sends move, and prints one line per rank at MPI_Finalize. Used by
// bench/mpi_collectives.sh through LD_PRELOAD (the weak-scaling estimate, bench/README.md); not linked into Contessa.
#include <mpi.h>
#include <stdio.h>

enum { ALLREDUCE, REDUCE, BCAST, ALLGATHER, ALLGATHERV, GATHER, GATHERV, SCATTER, SCATTERV, ALLTOALL, ALLTOALLV,
       BARRIER, SEND, ISEND, KINDS };
static const char* names[KINDS] = {"allreduce", "reduce", "bcast", "allgather", "allgatherv", "gather", "gatherv",
                                   "scatter", "scatterv", "alltoall", "alltoallv", "barrier", "send", "isend"};
static long long calls[KINDS], bytes[KINDS];

static long long size_of(MPI_Datatype t, long long count) {
  int s = 0;
  PMPI_Type_size(t, &s);
  return (long long)s * count;
}
#define COUNT(kind, n) (calls[kind]++, bytes[kind] += (n))

int MPI_Allreduce(const void* s, void* r, int c, MPI_Datatype t, MPI_Op o, MPI_Comm m) {
  COUNT(ALLREDUCE, size_of(t, c));
  return PMPI_Allreduce(s, r, c, t, o, m);
}
int MPI_Reduce(const void* s, void* r, int c, MPI_Datatype t, MPI_Op o, int root, MPI_Comm m) {
  COUNT(REDUCE, size_of(t, c));
  return PMPI_Reduce(s, r, c, t, o, root, m);
}
int MPI_Bcast(void* b, int c, MPI_Datatype t, int root, MPI_Comm m) {
  COUNT(BCAST, size_of(t, c));
  return PMPI_Bcast(b, c, t, root, m);
}
int MPI_Allgather(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt, MPI_Comm m) {
  COUNT(ALLGATHER, size_of(st, sc));
  return PMPI_Allgather(s, sc, st, r, rc, rt, m);
}
int MPI_Allgatherv(const void* s, int sc, MPI_Datatype st, void* r, const int* rc, const int* d, MPI_Datatype rt,
                   MPI_Comm m) {
  COUNT(ALLGATHERV, size_of(st, sc));
  return PMPI_Allgatherv(s, sc, st, r, rc, d, rt, m);
}
int MPI_Gather(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt, int root, MPI_Comm m) {
  COUNT(GATHER, size_of(st, sc));
  return PMPI_Gather(s, sc, st, r, rc, rt, root, m);
}
int MPI_Gatherv(const void* s, int sc, MPI_Datatype st, void* r, const int* rc, const int* d, MPI_Datatype rt, int root,
                MPI_Comm m) {
  COUNT(GATHERV, size_of(st, sc));
  return PMPI_Gatherv(s, sc, st, r, rc, d, rt, root, m);
}
int MPI_Scatter(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt, int root, MPI_Comm m) {
  COUNT(SCATTER, size_of(rt, rc));
  return PMPI_Scatter(s, sc, st, r, rc, rt, root, m);
}
int MPI_Scatterv(const void* s, const int* sc, const int* d, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
                 int root, MPI_Comm m) {
  COUNT(SCATTERV, size_of(rt, rc));
  return PMPI_Scatterv(s, sc, d, st, r, rc, rt, root, m);
}
int MPI_Alltoall(const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt, MPI_Comm m) {
  COUNT(ALLTOALL, size_of(st, sc));
  return PMPI_Alltoall(s, sc, st, r, rc, rt, m);
}
int MPI_Alltoallv(const void* s, const int* sc, const int* sd, MPI_Datatype st, void* r, const int* rc, const int* rd,
                  MPI_Datatype rt, MPI_Comm m) {
  int n = 0;
  PMPI_Comm_size(m, &n);
  long long total = 0;
  for (int i = 0; i < n; ++i) total += sc[i];
  COUNT(ALLTOALLV, size_of(st, total));
  return PMPI_Alltoallv(s, sc, sd, st, r, rc, rd, rt, m);
}
int MPI_Barrier(MPI_Comm m) {
  COUNT(BARRIER, 0);
  return PMPI_Barrier(m);
}
int MPI_Send(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm m) {
  COUNT(SEND, size_of(t, c));
  return PMPI_Send(b, c, t, d, tag, m);
}
int MPI_Isend(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm m, MPI_Request* q) {
  COUNT(ISEND, size_of(t, c));
  return PMPI_Isend(b, c, t, d, tag, m, q);
}
int MPI_Finalize(void) {
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  fprintf(stderr, "mpi_call_count rank %d:", rank);
  for (int k = 0; k < KINDS; ++k) fprintf(stderr, " %s=%lld/%lld", names[k], calls[k], bytes[k]);
  fprintf(stderr, "\n");
  return PMPI_Finalize();
}
