/* Decodes a .qmc file from C with nothing but qmc.h and qmc::qmc. */
#include <qmc/qmc.h>

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  static uint8_t bytes[1 << 20];
  size_t size;
  qmc_decoder* decoder;
  qmc_mesh mesh;
  int result;
  FILE* f = argc == 2 ? fopen(argv[1], "rb") : NULL;
  if (!f) return 2;
  size = fread(bytes, 1, sizeof bytes, f);
  fclose(f);
  decoder = qmc_decoder_create(NULL);
  result = qmc_decoder_decode(decoder, bytes, size);
  if (result == QMC_OK) result = qmc_decoder_mesh(decoder, QMC_FINEST, &mesh);
  if (result != QMC_OK) {
    fprintf(stderr, "%s: %s\n", qmc_error_name(result), qmc_decoder_message(decoder));
    qmc_decoder_destroy(decoder);
    return 1;
  }
  printf("C: %u vertices, %u faces, %u triangles\n", mesh.vertex_count, mesh.face_count, mesh.triangle_count);
  qmc_mesh_free(&mesh);
  qmc_decoder_destroy(decoder);
  return 0;
}
