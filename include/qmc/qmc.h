/* qmc C API: the decoder for programs in C and for WebAssembly.
 *
 * A C99 wrapper of include/qmc/decoder.h. No C++ exception or type
 * crosses it: every call returns a qmc_error (0 = QMC_OK), a failed decoder
 * keeps the message naming what was wrong and where (qmc_decoder_message).
 *
 * Use:
 *   qmc_decoder* d = qmc_decoder_create(NULL);       (NULL: default limits)
 *   qmc_decoder_feed(d, bytes, n);                    (as often as bytes arrive)
 *   qmc_decoder_finish(d);                            (once the input ended)
 *   qmc_mesh m; qmc_decoder_mesh(d, QMC_FINEST, &m);  (arrays owned by m)
 *   ... m.positions, m.triangles ...
 *   qmc_mesh_free(&m); qmc_decoder_destroy(d);
 *
 * Arrays handed out (qmc_mesh's, attributes, canonical output) are the caller's: free them
 * with qmc_mesh_free, or keep one by copying its pointer and setting the
 * field to NULL before qmc_mesh_free, then release it with qmc_free.
 */
#ifndef QMC_QMC_H_
#define QMC_QMC_H_

#include <stddef.h>
#include <stdint.h>

#include "qmc/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Spec section 9: the identifiers of the rejection rules, numbered as
 * qmc::ErrorCode. qmc_error_name gives the identifier ("bad_crc"). */
typedef enum qmc_error {
  QMC_OK = 0,
  QMC_BAD_SIGNATURE = 1,
  QMC_UNSUPPORTED_VERSION = 2,
  QMC_TRUNCATED = 3,
  QMC_BAD_CRC = 4,
  QMC_BAD_CHUNK_LENGTH = 5,
  QMC_BAD_CHUNK_TYPE = 6,
  QMC_UNKNOWN_CRITICAL_CHUNK = 7,
  QMC_CHUNK_ORDER = 8,
  QMC_TRAILING_DATA = 9,
  QMC_BAD_CHUNK_PAYLOAD = 10,
  QMC_UNSUPPORTED_FEATURE = 11,
  QMC_BAD_HUFFMAN_TABLE = 12,
  QMC_BAD_SYMBOL = 13,
  QMC_LIMIT_EXCEEDED = 14,   /* also: memory ran out */
  QMC_INVALID_ARGUMENT = 15  /* a NULL pointer or a level that does not exist */
} qmc_error;

QMC_API const char* qmc_error_name(int error);

/* Spec 8.1: what one file may cost. qmc_limits_default fills the defaults of
 * decoder.h (256 MiB of output, 2^24 vertices, 8 levels ...); QMC_NO_LIMIT
 * switches a 64-bit limit off. */
#define QMC_NO_LIMIT UINT64_MAX
typedef struct qmc_limits {
  uint32_t max_chunk_length;
  uint32_t max_levels;
  uint64_t max_vertices;
  uint64_t max_faces;
  uint64_t max_pixels;
  uint64_t max_output_bytes;
} qmc_limits;

QMC_API void qmc_limits_default(qmc_limits* limits);

/* What a file's first chunks say it will cost (spec 8.1), read without
 * decoding: from QHDR, LOOP and the CONN or GIMG header. */
typedef struct qmc_summary {
  uint32_t version_major, version_minor;
  uint32_t has_connectivity;   /* the CONN header was read */
  uint32_t method;             /* CONN's connectivity method (5.1) */
  uint64_t vertex_count, face_count;  /* CONN (a progressive file's base mesh) */
  uint32_t level_count;        /* LOOP's K, 0 if not progressive */
  uint64_t finest_face_count;  /* progressive: 4^K faces of the base */
  uint32_t has_geometry_image;
  uint32_t gim_width, gim_height, gim_plane_count;
  uint64_t min_output_bytes;   /* compared with max_output_bytes */
} qmc_summary;

/* QMC_OK with the summary, QMC_TRUNCATED if more bytes are needed, or the
 * error of a chunk read so far. message (may be NULL) receives the reason,
 * cut to message_size bytes with a terminating NUL. */
QMC_API int qmc_peek(const uint8_t* data, size_t size, qmc_summary* out, char* message, size_t message_size);

/* A decoded mesh. Faces are polygons: face f has face_sizes[f] corners,
 * consecutive in corners. triangles is the same surface with each polygon cut
 * into a fan from its first corner, for rendering. */
typedef struct qmc_mesh {
  uint32_t vertex_count;
  uint32_t face_count;
  uint32_t corner_count;    /* sum of face_sizes */
  uint32_t triangle_count;  /* triangles holds 3 * triangle_count indices */
  float* positions;         /* 3 * vertex_count: x0 y0 z0 x1 ... */
  uint32_t* face_sizes;
  uint32_t* corners;
  uint32_t* triangles;
} qmc_mesh;

QMC_API void qmc_mesh_free(qmc_mesh* mesh); /* frees its arrays, zeroes it */
QMC_API void qmc_free(void* array);          /* one array kept from a qmc_mesh or canonical output */

/* A decoder of one file, whole or streamed (spec 3.5). */
typedef struct qmc_decoder qmc_decoder;

/* NULL if memory ran out; limits NULL means qmc_limits_default. */
QMC_API qmc_decoder* qmc_decoder_create(const qmc_limits* limits);
QMC_API void qmc_decoder_destroy(qmc_decoder* decoder);

/* Consumes the next bytes of the file. After an error every further call
 * returns it again. */
QMC_API int qmc_decoder_feed(qmc_decoder* decoder, const uint8_t* data, size_t size);
/* The input has ended: a file that stopped before QEND is QMC_TRUNCATED. */
QMC_API int qmc_decoder_finish(qmc_decoder* decoder);
/* A complete file held in memory: feed then finish. */
QMC_API int qmc_decoder_decode(qmc_decoder* decoder, const uint8_t* data, size_t size);

QMC_API int qmc_decoder_error(const qmc_decoder* decoder);          /* QMC_OK until a rejection */
QMC_API const char* qmc_decoder_message(const qmc_decoder* decoder); /* "" while QMC_OK */
QMC_API int qmc_decoder_complete(const qmc_decoder* decoder);       /* QEND seen and valid */
QMC_API int qmc_decoder_has_mesh(const qmc_decoder* decoder);       /* positions have arrived */
/* Section 12: LOOP's K (0: not progressive), and the finest level decoded so
 * far (0 = base mesh), -1 before the base mesh or without LOOP. */
QMC_API int qmc_decoder_level_count(const qmc_decoder* decoder);
QMC_API int qmc_decoder_complete_level(const qmc_decoder* decoder);

/* The mesh of level `level` (0 .. complete_level), or with QMC_FINEST the
 * file's mesh as decoded so far: the finest level, a geometry image's mesh
 * (13.9), or the mesh of a file without LOOP. */
#define QMC_FINEST (-1)
QMC_API int qmc_decoder_mesh(const qmc_decoder* decoder, int level, qmc_mesh* out);

/* Section 13.2: a geometry image's planes after X, Y, Z are per-vertex
 * attributes of its mesh (13.9): kind 3, 4, 5 a normal's X, Y, Z, 6 a
 * curvature, 7 a colour or texture channel, 8 any other scalar. Attribute i
 * is plane 3 + i, one value per vertex of the QMC_FINEST mesh, its
 * representative pixel's sample (13.2). attribute_count counts those decoded
 * so far (0 for a file without GIMG); values are freed with qmc_free. */
typedef struct qmc_attribute {
  uint32_t kind;
  uint32_t count;  /* the mesh's vertex_count */
  float* values;
} qmc_attribute;

QMC_API int qmc_decoder_attribute_count(const qmc_decoder* decoder);
QMC_API int qmc_decoder_attribute(const qmc_decoder* decoder, int index, qmc_attribute* out);

/* Section 15: an attribute of the mesh's corners (aTTR): texture
 * coordinates (kind 1), normals (2), colours (3) or generic values (0; a
 * kind this revision does not name is passed on). Corner k of the
 * QMC_FINEST mesh (in qmc_mesh's corners order) has the value
 * values[components * corner_values[k] .. + components - 1]. The arrays are
 * freed with qmc_corner_attribute_free, or kept one by one with qmc_free. */
typedef struct qmc_corner_attribute {
  char name[256];           /* NUL-terminated; names are 1..255 bytes */
  uint32_t kind;
  uint32_t components;      /* 1..3 */
  uint32_t value_count;
  uint32_t corner_count;    /* the mesh's corner_count */
  float* values;            /* components * value_count */
  uint32_t* corner_values;  /* corner_count indices below value_count */
} qmc_corner_attribute;

QMC_API int qmc_decoder_corner_attribute_count(const qmc_decoder* decoder);
QMC_API int qmc_decoder_corner_attribute(const qmc_decoder* decoder, int index, qmc_corner_attribute* out);
QMC_API void qmc_corner_attribute_free(qmc_corner_attribute* attribute); /* frees its arrays, zeroes it */

/* The QMC_FINEST mesh split for drawing with its corner attributes: one
 * vertex per distinct (mesh vertex, value of every corner attribute) among
 * the corners, numbered in the order of their first corners, so a mesh vertex
 * is split only where a seam gives it several values (a texture atlas's
 * borders). Vertex i is drawn with the position of mesh vertex
 * corners[first_corner[i]] and, of each corner attribute, the value
 * corner_values[first_corner[i]]; triangles are qmc_mesh's fans over these
 * vertices. Without corner attributes the vertices are the mesh vertices that
 * some face uses. Its time grows as K log K in the K corners, however many
 * values meet at one vertex. The arrays are freed with qmc_split_mesh_free,
 * or kept one by one with qmc_free. */
typedef struct qmc_split_mesh {
  uint32_t vertex_count;
  uint32_t triangle_count;
  uint32_t* first_corner;  /* vertex_count corners of the mesh */
  uint32_t* triangles;     /* 3 * triangle_count vertex numbers below vertex_count */
} qmc_split_mesh;

QMC_API int qmc_decoder_split_mesh(const qmc_decoder* decoder, qmc_split_mesh* out);
QMC_API void qmc_split_mesh_free(qmc_split_mesh* mesh); /* frees its arrays, zeroes it */

/* Section 16: labels of the faces (fLBL): OBJ objects, groups, materials,
 * smoothing groups. Face f of the QMC_FINEST mesh has label face_values[f],
 * an index below value_count, or value_count for none. face_values is freed
 * with qmc_free. The strings stay owned by the decoder, valid until its next
 * feed, finish or destroy; they may hold any bytes (length given). */
typedef struct qmc_face_labels {
  char name[256];          /* NUL-terminated */
  uint32_t value_count;
  uint32_t reference_count;
  uint32_t face_count;
  uint32_t* face_values;
} qmc_face_labels;

QMC_API int qmc_decoder_face_labels_count(const qmc_decoder* decoder);
QMC_API int qmc_decoder_face_labels(const qmc_decoder* decoder, int index, qmc_face_labels* out);
/* Value `value` (0 .. value_count - 1) of labels `index`, or, with reference
 * set, reference `value`; NULL if out of range. */
QMC_API const char* qmc_decoder_face_label_string(const qmc_decoder* decoder, int index, int reference,
                                                  uint32_t value, uint32_t* length);

/* Spec 10.2, 12.9, 13.10: the canonical output of the file decoded so far,
 * whose SHA-256 the conformance manifest lists. *bytes is freed with qmc_free. */
QMC_API int qmc_decoder_canonical_output(const qmc_decoder* decoder, uint8_t** bytes, size_t* size);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* QMC_QMC_H_ */
