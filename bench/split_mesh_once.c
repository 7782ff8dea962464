/* qmc bench: the time of qmc_decoder_split_mesh (include/qmc/qmc.h) on a
 * decoded file, through the C API alone: the median and least of REPEAT
 * splits (default 5), the split vertices and triangles.
 *
 *   qmc_split_mesh_once FILE.qmc [REPEAT]
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "qmc/qmc.h"

static double seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

int main(int argc, char** argv) {
  FILE* f = argc >= 2 ? fopen(argv[1], "rb") : NULL;
  if (!f) {
    fprintf(stderr, "usage: qmc_split_mesh_once FILE.qmc [REPEAT]\n");
    return 2;
  }
  fseek(f, 0, SEEK_END);
  const long size = ftell(f);
  fseek(f, 0, SEEK_SET);
  uint8_t* bytes = malloc(size > 0 ? (size_t)size : 1);
  const int read_all = bytes && fread(bytes, 1, (size_t)size, f) == (size_t)size;
  fclose(f);
  qmc_decoder* d = qmc_decoder_create(NULL);
  if (!read_all || !d || qmc_decoder_decode(d, bytes, (size_t)size) != QMC_OK) {
    fprintf(stderr, "qmc_split_mesh_once: %s: %s\n", argv[1], d ? qmc_decoder_message(d) : "out of memory");
    return 3;
  }
  const int repeat = argc >= 3 ? atoi(argv[2]) : 5;
  double* times = malloc(sizeof(double) * (size_t)(repeat > 0 ? repeat : 1));
  qmc_split_mesh split = {0, 0, NULL, NULL};
  for (int r = 0; r < repeat; ++r) {
    const double start = seconds();
    if (qmc_decoder_split_mesh(d, &split) != QMC_OK) return 3;
    times[r] = seconds() - start;
    if (r + 1 < repeat) qmc_split_mesh_free(&split);
  }
  qsort(times, (size_t)repeat, sizeof(double), by_value);
  printf("%u split vertices, %u triangles; split median %.3f ms, least %.3f ms\n", split.vertex_count,
         split.triangle_count, 1e3 * times[repeat / 2], 1e3 * times[0]);
  qmc_split_mesh_free(&split);
  qmc_decoder_destroy(d);
  free(times);
  free(bytes);
  return 0;
}
