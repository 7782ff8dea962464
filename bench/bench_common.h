// Helpers shared by the benchmark programs: timing medians, text
// formatting, and the connectivity-only decode used to time CONN alone.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "qmc/encoder.h"

namespace qmc::bench {

// Prints "PROGRAM: message" and exits with status 3.
[[noreturn]] void fail(const char* program, const std::string& message);

// What a long benchmark is doing, on one line of a terminal's stderr
// (nothing when stderr is not a terminal); "" clears the line.
void progress(const std::string& what);

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

double median(std::vector<double> values);

// Median wall time in seconds of `runs` calls of f.
template <class F>
double median_seconds(int runs, F&& f) {
  std::vector<double> seconds;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(seconds);
}

inline double bits_per_vertex(double bytes, size_t vertices) { return 8.0 * bytes / double(vertices); }

std::string cpu_model();
// Folder and file name of a corpus path, as in the result tables: "quad/suzanne.obj".
std::string display_name(const std::string& path);

// File offset just past CONN: the signature, then the chunks in the order
// the encoder reports them. 0 if there is no CONN.
size_t end_of_connectivity(const EncodeStats& stats);

// The streaming decoder decodes each chunk the moment its last byte arrives,
// so feeding it the file up to the end of CONN does the container checks and
// the connectivity decode and nothing of POSN. False if that did not yield
// `faces` faces.
bool decode_connectivity_only(const std::vector<uint8_t>& file, size_t conn_end, size_t faces);

// A mesh file as the geometry benchmarks compare it: positions and faces,
// without its attributes and face labels (spec 15, 16), which the peers are
// not given there (attributes.md compares those).
Status read_geometry(const std::string& path, Mesh* mesh, std::vector<std::string>* notes);

// Removes the vertices no face uses and renumbers the rest in order; returns
// how many went. Draco's edgebreaker keeps only vertices of faces, so a
// benchmark that compares bytes with it gives every codec the mesh without
// them (qmc keeps them: spec 5.2.1, 5.4.9).
size_t drop_unused_vertices(Mesh* mesh);

}  // namespace qmc::bench
