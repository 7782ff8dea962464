/* The C API (include/qmc/qmc.h) over every conformance vector, from a C
 * program that includes nothing else of qmc: each vector decoded whole and
 * streamed in 1-byte, random and 4 KB pieces (spec 3.5). A valid vector must
 * give the manifest's SHA-256 of the canonical output (10.2), an invalid one
 * the manifest's error identifier (section 9). Then the API's own promises:
 * limits, peek, polygon and triangle arrays, attributes, the split mesh, ownership,
 * bad arguments.
 *
 *   qmc_c_test conformance/MANIFEST
 *
 * Prints a line per failure and "N passed, N failed"; exits 1 on a failure. */
#include <qmc/qmc.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sha256.h"

static int passed, failed;

static void check(int ok, const char* what, const char* name) {
  if (ok) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL %s: %s\n", name, what);
  }
}

static uint8_t* read_file(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  uint8_t* data;
  long n;
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  n = ftell(f);
  fseek(f, 0, SEEK_SET);
  data = (uint8_t*)malloc(n > 0 ? (size_t)n : 1);
  *size = data ? fread(data, 1, (size_t)n, f) : 0;
  fclose(f);
  return data;
}

/* How a vector's bytes are handed to the decoder. */
enum { WHOLE, PIECES_1, PIECES_RANDOM, PIECES_4K, MODE_COUNT };
static const char* const kModeNames[MODE_COUNT] = {"whole", "1-byte pieces", "random pieces", "4 KB pieces"};

static uint32_t next_random(uint32_t* state) { /* xorshift32: reproducible piece sizes */
  *state ^= *state << 13;
  *state ^= *state >> 17;
  *state ^= *state << 5;
  return *state;
}

static size_t piece_size(int mode, uint32_t* random) {
  switch (mode) {
    case PIECES_1: return 1;
    case PIECES_RANDOM: return 1 + next_random(random) % 700;
    default: return 4096;
  }
}

/* Feeds data as the mode says; while streaming, the complete level never
 * goes back and each complete level's mesh can be had (spec 3.5, 12). */
static int decode_in(int mode, const uint8_t* data, size_t size, qmc_decoder* d, int* levels_ok) {
  uint32_t random = 0x9e3779b9u ^ (uint32_t)size;
  size_t at = 0;
  int last_level = -1;
  *levels_ok = 1;
  if (mode == WHOLE) return qmc_decoder_decode(d, data, size);
  while (at < size) {
    size_t n = piece_size(mode, &random);
    if (n > size - at) n = size - at;
    if (qmc_decoder_feed(d, data + at, n) != QMC_OK) return qmc_decoder_error(d);
    at += n;
    if (qmc_decoder_complete_level(d) != last_level) {
      qmc_mesh mesh;
      last_level = qmc_decoder_complete_level(d);
      if (last_level < 0 || qmc_decoder_mesh(d, last_level, &mesh) != QMC_OK ||
          mesh.triangle_count != mesh.face_count)
        *levels_ok = 0;
      qmc_mesh_free(&mesh);
    }
  }
  return qmc_decoder_finish(d);
}

static void check_vector(const char* kind, const char* path, const char* expected, int mode) {
  char what[512], hex[65];
  size_t size = 0, out_size = 0;
  uint8_t* data = read_file(path, &size);
  uint8_t* out = NULL;
  qmc_decoder* d = qmc_decoder_create(NULL);
  int levels_ok, result;
  if (!data || !d) {
    check(0, "cannot read the vector or create a decoder", path);
    free(data);
    qmc_decoder_destroy(d);
    return;
  }
  result = decode_in(mode, data, size, d, &levels_ok);
  if (strcmp(kind, "valid") == 0) {
    if (result == QMC_OK) result = qmc_decoder_canonical_output(d, &out, &out_size);
    if (result == QMC_OK) sha256_hex(out, out_size, hex);
    snprintf(what, sizeof what, "%s: expected SHA-256 %s, got %s %s", kModeNames[mode], expected,
             qmc_error_name(result), result == QMC_OK ? hex : qmc_decoder_message(d));
    check(result == QMC_OK && strcmp(hex, expected) == 0 && levels_ok, what, path);
  } else {
    snprintf(what, sizeof what, "%s: expected %s, got %s (%s)", kModeNames[mode], expected, qmc_error_name(result),
             qmc_decoder_message(d));
    check(strcmp(qmc_error_name(result), expected) == 0 && *qmc_decoder_message(d) != '\0', what, path);
  }
  qmc_free(out);
  free(data);
  qmc_decoder_destroy(d);
}

static int run_manifest(const char* manifest) {
  char line[1024], kind[16], relative[512], expected[128], path[2048];
  size_t dir_length;
  int vectors = 0, mode;
  FILE* f = fopen(manifest, "r");
  const char* slash = strrchr(manifest, '/');
  if (!f) return 0;
  dir_length = slash ? (size_t)(slash - manifest + 1) : 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#' || sscanf(line, "%15s %511s %127s", kind, relative, expected) != 3) continue;
    snprintf(path, sizeof path, "%.*s%s", (int)dir_length, manifest, relative);
    for (mode = 0; mode < MODE_COUNT; ++mode) check_vector(kind, path, expected, mode);
    ++vectors;
  }
  fclose(f);
  return vectors;
}

static char* vector_path(const char* manifest, const char* name) {
  static char path[2048];
  const char* slash = strrchr(manifest, '/');
  snprintf(path, sizeof path, "%.*svectors/%s", slash ? (int)(slash - manifest + 1) : 0, manifest, name);
  return path;
}

/* Spec 8.1: a limit below the file's count rejects it as limit_exceeded,
 * the message naming the limit; the default limits decode it. */
static void check_limits(const char* manifest) {
  size_t size = 0;
  uint8_t* cube = read_file(vector_path(manifest, "valid_cube_8bit.qmc"), &size);
  qmc_limits limits;
  qmc_decoder* d;
  qmc_limits_default(&limits);
  check(limits.max_output_bytes == 256u << 20 && limits.max_levels == 8, "default limits are decoder.h's", "limits");
  limits.max_vertices = 7; /* the cube has 8 */
  d = qmc_decoder_create(&limits);
  check(qmc_decoder_decode(d, cube, size) == QMC_LIMIT_EXCEEDED, "8 vertices over max_vertices 7", "limits");
  check(strstr(qmc_decoder_message(d), "max_vertices") != NULL, "the message names max_vertices", "limits");
  qmc_decoder_destroy(d);
  limits.max_vertices = 8;
  d = qmc_decoder_create(&limits);
  check(qmc_decoder_decode(d, cube, size) == QMC_OK, "8 vertices within max_vertices 8", "limits");
  qmc_decoder_destroy(d);
  free(cube);
}

/* Spec 8.1: peek reads the counts before anything is allocated. */
static void check_peek(const char* manifest) {
  size_t size = 0;
  uint8_t* cube = read_file(vector_path(manifest, "valid_cube_8bit.qmc"), &size);
  qmc_summary s;
  char message[128];
  check(qmc_peek(cube, size, &s, message, sizeof message) == QMC_OK && s.version_major == 1 &&
            s.has_connectivity && s.vertex_count == 8 && s.face_count == 6 && s.level_count == 0,
        "peek of the cube: version 1, 8 vertices, 6 faces, no LOOP", "peek");
  check(qmc_peek(cube, 12, &s, message, sizeof message) == QMC_TRUNCATED && message[0] != '\0',
        "12 bytes are truncated, with a message", "peek");
  cube[0] ^= 0xff;
  check(qmc_peek(cube, size, &s, NULL, 0) == QMC_BAD_SIGNATURE, "a broken signature is bad_signature", "peek");
  free(cube);
}

/* The cube of quads: 6 polygons of 4 corners, 12 triangles in fans; an array
 * kept out of qmc_mesh_free is the caller's, released with qmc_free. */
static void check_mesh_arrays(const char* manifest) {
  size_t size = 0;
  uint8_t* cube = read_file(vector_path(manifest, "valid_cube_8bit.qmc"), &size);
  qmc_decoder* d = qmc_decoder_create(NULL);
  qmc_mesh mesh;
  float* kept;
  uint32_t f, corner = 0, fan_ok = 1;
  check(qmc_decoder_decode(d, cube, size) == QMC_OK && qmc_decoder_complete(d) && qmc_decoder_has_mesh(d),
        "the cube decodes whole", "mesh");
  check(qmc_decoder_mesh(d, QMC_FINEST, &mesh) == QMC_OK && mesh.vertex_count == 8 && mesh.face_count == 6 &&
            mesh.corner_count == 24 && mesh.triangle_count == 12,
        "8 vertices, 6 quads, 24 corners, 12 triangles", "mesh");
  for (f = 0; f < mesh.face_count && mesh.triangles; corner += mesh.face_sizes[f], ++f)
    fan_ok &= mesh.triangles[6 * f] == mesh.corners[corner] && mesh.triangles[6 * f + 1] == mesh.corners[corner + 1] &&
              mesh.triangles[6 * f + 5] == mesh.corners[corner + 3];
  check(fan_ok, "each quad is the fan (c0 c1 c2) (c0 c2 c3)", "mesh");
  kept = mesh.positions;
  mesh.positions = NULL;
  qmc_mesh_free(&mesh);
  check(mesh.corners == NULL && mesh.vertex_count == 0, "qmc_mesh_free zeroes the mesh", "mesh");
  qmc_free(kept);
  check(qmc_decoder_mesh(d, 0, &mesh) == QMC_INVALID_ARGUMENT, "a file without LOOP has no level 0", "mesh");
  check(qmc_decoder_attribute_count(d) == 0, "a file without GIMG has no attributes", "mesh");
  check(qmc_decoder_feed(NULL, cube, size) == QMC_INVALID_ARGUMENT, "feeding a NULL decoder", "mesh");
  check(strcmp(qmc_error_name(QMC_BAD_CRC), "bad_crc") == 0 && strcmp(qmc_error_name(99), "unknown") == 0,
        "error names are spec 9's identifiers", "mesh");
  qmc_decoder_destroy(d);
  free(cube);
}

/* Spec 13.2: valid_gim_f32_attributes carries planes of kinds 3..6 after
 * X Y Z, made by the vector generator as the position over 3 (kinds 3..5)
 * and half the pixel's raster index (kind 6); each is one value a vertex. */
static void check_attributes(const char* manifest) {
  size_t size = 0;
  uint8_t* gim = read_file(vector_path(manifest, "valid_gim_f32_attributes.qmc"), &size);
  qmc_decoder* d = qmc_decoder_create(NULL);
  qmc_mesh mesh;
  qmc_attribute attribute;
  uint32_t v, over_three = 1, halves = 1;
  int i, kinds_ok = 1;
  check(qmc_decoder_decode(d, gim, size) == QMC_OK && qmc_decoder_mesh(d, QMC_FINEST, &mesh) == QMC_OK &&
            qmc_decoder_attribute_count(d) == 4,
        "a geometry image with 4 attribute planes", "attributes");
  for (i = 0; i < qmc_decoder_attribute_count(d); ++i) {
    if (qmc_decoder_attribute(d, i, &attribute) != QMC_OK || attribute.kind != (uint32_t)(3 + i) ||
        attribute.count != mesh.vertex_count) {
      kinds_ok = 0;
      continue;
    }
    for (v = 0; v < attribute.count; ++v) {
      const float value = attribute.values[v];
      if (i < 3) over_three &= value - mesh.positions[3 * v + i] / 3 < 1e-6f && mesh.positions[3 * v + i] / 3 - value < 1e-6f;
      else halves &= value >= 0 && value <= 40 && value * 2 == (float)(int)(value * 2);
    }
    qmc_free(attribute.values);
  }
  check(kinds_ok, "attribute i has kind 3 + i and a value per vertex", "attributes");
  check(over_three, "kinds 3..5 are the vertex's X, Y, Z over 3", "attributes");
  check(halves, "kind 6 is half a raster index of the 9 x 9 image", "attributes");
  check(qmc_decoder_attribute(d, 4, &attribute) == QMC_INVALID_ARGUMENT, "no fifth attribute", "attributes");
  qmc_mesh_free(&mesh);
  qmc_decoder_destroy(d);
  free(gim);
}

/* Spec 15 for drawing: valid_attr_mapping3_texcoords has 160 vertices and,
 * over its 960 corners, 176 distinct (vertex, texture coordinate) pairs;
 * qmc_decoder_split_mesh gives one vertex per pair, and at every corner of
 * every fan triangle a vertex whose first corner has that corner's vertex and
 * texture coordinate. The cube, without corner attributes, keeps its 8. */
static void check_split_mesh(const char* manifest) {
  size_t file_size = 0, cube_size = 0;
  uint8_t* file = read_file(vector_path(manifest, "valid_attr_mapping3_texcoords.qmc"), &file_size);
  uint8_t* cube = read_file(vector_path(manifest, "valid_cube_8bit.qmc"), &cube_size);
  qmc_decoder* d = qmc_decoder_create(NULL);
  qmc_mesh mesh;
  qmc_corner_attribute uv;
  qmc_split_mesh split;
  uint32_t f, i, j, k, t = 0, pairs = 0, faithful = 1;
  check(qmc_decoder_decode(d, file, file_size) == QMC_OK && qmc_decoder_mesh(d, QMC_FINEST, &mesh) == QMC_OK &&
            qmc_decoder_corner_attribute(d, 0, &uv) == QMC_OK && uv.kind == 1 && mesh.corner_count == 960,
        "texture coordinates on 960 corners", "split");
  for (k = 0; k < mesh.corner_count; ++k) {
    for (j = 0; j < k; ++j)
      if (mesh.corners[j] == mesh.corners[k] && uv.corner_values[j] == uv.corner_values[k]) break;
    pairs += j == k;
  }
  check(qmc_decoder_split_mesh(d, &split) == QMC_OK && split.vertex_count == pairs && pairs == 176 &&
            split.triangle_count == mesh.triangle_count,
        "one vertex per distinct (vertex, texture coordinate): 176", "split");
  for (f = 0, k = 0; f < mesh.face_count && split.triangles; k += mesh.face_sizes[f], ++f)
    for (i = 1; i + 1 < mesh.face_sizes[f]; ++i) {
      const uint32_t fan[3] = {k, k + i, k + i + 1};
      for (j = 0; j < 3; ++j, ++t) {
        const uint32_t first = split.first_corner[split.triangles[t]];
        faithful &= split.triangles[t] < split.vertex_count && mesh.corners[first] == mesh.corners[fan[j]] &&
                    uv.corner_values[first] == uv.corner_values[fan[j]];
      }
    }
  check(faithful && t == 3 * mesh.triangle_count, "each fan corner's vertex has its position and value", "split");
  qmc_split_mesh_free(&split);
  check(split.triangles == NULL && split.vertex_count == 0, "qmc_split_mesh_free zeroes it", "split");
  qmc_corner_attribute_free(&uv);
  qmc_mesh_free(&mesh);
  qmc_decoder_destroy(d);

  d = qmc_decoder_create(NULL);
  faithful = 1;
  check(qmc_decoder_decode(d, cube, cube_size) == QMC_OK && qmc_decoder_mesh(d, QMC_FINEST, &mesh) == QMC_OK &&
            qmc_decoder_split_mesh(d, &split) == QMC_OK && split.vertex_count == 8 && split.triangle_count == 12,
        "without corner attributes, the cube's 8 vertices", "split");
  for (t = 0; t < 3 * split.triangle_count && split.triangles; ++t)
    faithful &= mesh.corners[split.first_corner[split.triangles[t]]] == mesh.triangles[t];
  check(faithful, "... under qmc_mesh's triangles", "split");
  qmc_split_mesh_free(&split);
  qmc_mesh_free(&mesh);
  check(qmc_decoder_split_mesh(NULL, &split) == QMC_INVALID_ARGUMENT && qmc_decoder_split_mesh(d, NULL) == QMC_INVALID_ARGUMENT,
        "NULL arguments", "split");
  qmc_decoder_destroy(d);
  free(file);
  free(cube);
}

int main(int argc, char** argv) {
  int vectors;
  if (argc != 2) {
    fprintf(stderr, "usage: qmc_c_test conformance/MANIFEST\n");
    return 2;
  }
  vectors = run_manifest(argv[1]);
  check(vectors > 0, "the manifest lists vectors", argv[1]);
  check_limits(argv[1]);
  check_peek(argv[1]);
  check_mesh_arrays(argv[1]);
  check_attributes(argv[1]);
  check_split_mesh(argv[1]);
  printf("%d vectors x %d ways\n%d passed, %d failed\n", vectors, MODE_COUNT, passed, failed);
  return failed ? 1 : 0;
}
