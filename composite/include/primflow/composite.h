/* primflow/composite.h: sort-last depth compositing over MPI -- the image composition PixelFlow
 * scaled by (Molnar et al. 1992, cited in seed 003's introduction): every rank draws part of the
 * scene into a full colour and depth buffer, and pfCompositeDepthMPI merges them by depth, pixel
 * by pixel, as PixelFlow's compositing network did -- here over MPI (binary-swap, or direct-send),
 * the way IceT / ParaView composite. Built only when CMake finds MPI (target primflow_composite);
 * the core library never needs MPI. C-compatible. docs/api.md, "Compositing over MPI". */
#ifndef PRIMFLOW_COMPOSITE_H
#define PRIMFLOW_COMPOSITE_H

#include <mpi.h>

#include <primflow/context.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Where the composited image ends up. */
#define PF_COMPOSITE_GATHER      0 /* whole image in the root rank's colour and depth buffers */
#define PF_COMPOSITE_DISTRIBUTED 1 /* each rank holds the final rows of its own band (stats) */

/* How the ranks exchange pixels. */
#define PF_COMPOSITE_AUTO        0 /* binary-swap for a power-of-two rank count, else direct-send */
#define PF_COMPOSITE_BINARY_SWAP 1 /* log2(p) rounds of halving; other counts fold pairs first */
#define PF_COMPOSITE_DIRECT_SEND 2 /* one round: every rank sends band j to rank j */

/* Return codes: 0 on success. Every rank returns an error when any rank fails (its own code on
 * the rank that failed, PF_COMPOSITE_PEER_FAILED on the others). */
#define PF_COMPOSITE_OK               0
#define PF_COMPOSITE_NO_CONTEXT       1 /* no current context, or it has no depth buffer / no buffer bound */
#define PF_COMPOSITE_BAD_OPTIONS      2 /* root out of range, an unknown mode, a negative timeout */
#define PF_COMPOSITE_SIZE_MISMATCH    3 /* the ranks' buffers differ in size */
#define PF_COMPOSITE_OPTIONS_MISMATCH 4 /* the ranks passed different root, result, algorithm or compression */
#define PF_COMPOSITE_PEER_FAILED      5 /* another rank failed (its code is on that rank) */
#define PF_COMPOSITE_TIMEOUT          6 /* the deadline passed: the communicator must not be used again */
#define PF_COMPOSITE_MPI_ERROR        7 /* MPI not initialised, MPI_COMM_NULL, or an MPI call failed */
#define PF_COMPOSITE_NO_MEMORY        8 /* scratch buffers could not be allocated */
#define PF_COMPOSITE_BAD_MESSAGE      9 /* a compressed message did not decode (never from a correct peer) */
#define PF_COMPOSITE_BAD_BUFFER      10 /* the colour buffer is not 4-byte aligned */

typedef struct PFcompositeOptions {
  int result;             /* PF_COMPOSITE_GATHER or PF_COMPOSITE_DISTRIBUTED */
  int root;               /* the rank receiving the image (GATHER) */
  int algorithm;          /* PF_COMPOSITE_AUTO, _BINARY_SWAP or _DIRECT_SEND */
  int compress;           /* 1: run-length code runs of identical pixels (a cleared region is one run) */
  double timeout_seconds; /* > 0: give up with PF_COMPOSITE_TIMEOUT after this long; 0: wait as MPI does */
} PFcompositeOptions;

typedef struct PFcompositeStats {
  unsigned long long bytes_sent;      /* payload bytes this rank sent (all phases) */
  unsigned long long bytes_received;  /* payload bytes this rank received */
  unsigned long long pixels_merged;   /* depth comparisons this rank made */
  double seconds;                     /* the whole call, wall clock */
  double merge_seconds;               /* of which comparing depths and encoding/decoding runs */
  int algorithm;                      /* the one used (PF_COMPOSITE_BINARY_SWAP or _DIRECT_SEND) */
  int ranks;                          /* the communicator's size */
  int first_row, row_count;           /* this rank's band of the final image (row 0 at the bottom) */
} PFcompositeStats;

/* Defaults: GATHER to rank 0, AUTO, no compression, no timeout. */
void pfCompositeDefaultOptions(PFcompositeOptions *options);

/* Composites the calling thread's current context (colour GL_RGBA bytes and float depth, as
 * pfGetColorBuffer / pfGetDepthBuffer hand them out) with every other rank of `comm`, by depth:
 * per pixel the smallest depth wins (the depth test GL_LESS); on equal depths the lower rank
 * wins. Collective: every rank of comm must call it with the same options and buffers of the
 * same size. Pending drawing is finished first. The result is the image one process would draw
 * with rank 0's objects first, then rank 1's, ..., independent of the exchange pattern.
 * GATHER: the root's colour and depth buffers hold the whole image; other ranks' are left
 * partly composited (unspecified). DISTRIBUTED: rows [first_row, first_row + row_count) of
 * each rank's buffers are final (stats). `options` NULL: the defaults; `stats` may be NULL.
 * Before any pixel is exchanged, one MPI_Allreduce agrees on sizes, options and every rank's
 * status, so a rank that fails makes every rank return an error instead of waiting. */
int pfCompositeDepthMPI(MPI_Comm comm, const PFcompositeOptions *options, PFcompositeStats *stats);

/* A short English description of a return code. */
const char *pfCompositeErrorString(int code);

#ifdef __cplusplus
}
#endif

#endif
