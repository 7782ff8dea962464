// qmc tools: PNG through libpng, PFM by hand.
//
// libpng reports errors by longjmp. Each function below that calls setjmp
// holds only pointers and plain integers, so nothing needing a destructor is
// skipped when libpng jumps back; the C++ containers live in the callers, and
// libpng's own structures are freed on every path. libpng's error message is
// copied into a fixed buffer (the error path allocates nothing) and becomes
// the Status message.
#include "image_io.h"

#include <png.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <new>
#include <string_view>
#include <system_error>
#include <utility>

#include "atomic_file.h"

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Status;

constexpr const char* kPlaneRule = "a geometry-image plane must be 16-bit gray";

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

std::string size_text(uint64_t width, uint64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// Width and height at least 1, at most kMaxImagePixels pixels.
Status check_dimensions(const std::string& path, uint64_t width, uint64_t height) {
  if (width == 0 || height == 0) {
    return invalid(path + ": image size " + size_text(width, height) + "; width and height must be at least 1");
  }
  if (width * height > kMaxImagePixels) {
    return invalid(path + ": image size " + size_text(width, height) + " is over the limit of 2^26 pixels");
  }
  return Status::Ok();
}

// The dimensions, and `count` values for `per_pixel` values per pixel.
Status check_buffer(const std::string& path, uint32_t width, uint32_t height, size_t count, uint32_t per_pixel) {
  Status status = check_dimensions(path, width, height);
  if (!status.ok()) return status;
  const uint64_t expected = uint64_t{width} * height * per_pixel;
  if (count != expected) {
    return invalid(path + ": " + std::to_string(count) + " values given for a " + size_text(width, height) +
                   " image (expected " + std::to_string(expected) + ")");
  }
  return Status::Ok();
}

Status read_file(const std::string& path, std::vector<uint8_t>* data) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return Status(ErrorCode::kIo, "cannot open " + path + ": " + std::strerror(errno));
  uint8_t buffer[1 << 16];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) data->insert(data->end(), buffer, buffer + n);
  int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error != 0) return Status(ErrorCode::kIo, "cannot read " + path + ": " + std::strerror(error));
  return Status::Ok();
}

Status write_file(const std::string& path, const std::vector<uint8_t>& data) {
  return write_file_atomically(path, data.data(), data.size());
}

// ---------------------------------------------------------------------------
// libpng plumbing

struct PngErrorSink {
  char message[200] = "libpng failed without a message";
};

[[noreturn]] void png_error_to_sink(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message != nullptr ? message : "unknown error");
  png_longjmp(png, 1);
}

void png_ignore_warning(png_structp, png_const_charp) {}

struct PngWriteJob {
  uint32_t width = 0, height = 0;
  int bit_depth = 8, colour_type = PNG_COLOR_TYPE_GRAY, compression_level = 6;
  const uint8_t* pixels = nullptr;  // rows top to bottom, 16-bit samples big-endian
  size_t row_bytes = 0;
  std::vector<uint8_t>* out = nullptr;
  PngErrorSink error;
};

void append_png_bytes(png_structp png, png_bytep data, size_t length) {
  auto* job = static_cast<PngWriteJob*>(png_get_io_ptr(png));
  bool ok = true;
  try {
    job->out->insert(job->out->end(), data, data + length);
  } catch (const std::bad_alloc&) {
    ok = false;
  }
  if (!ok) png_error(png, "out of memory for the encoded PNG");
}

void no_flush(png_structp) {}

// setjmp frame: plain locals only (see the file comment).
bool run_png_write(PngWriteJob* job) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job->error, png_error_to_sink, png_ignore_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, job, append_png_bytes, no_flush);
  png_set_compression_level(png, job->compression_level);
  png_set_IHDR(png, info, job->width, job->height, job->bit_depth, job->colour_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (uint32_t y = 0; y < job->height; ++y) png_write_row(png, job->pixels + size_t{y} * job->row_bytes);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// Encodes rows already in PNG sample layout; the caller checked the sizes.
Status encode_png(const std::string& path, uint32_t width, uint32_t height, int bit_depth, int colour_type,
                  int compression_level, const uint8_t* pixels, size_t row_bytes, std::vector<uint8_t>* out) {
  PngWriteJob job;
  job.width = width;
  job.height = height;
  job.bit_depth = bit_depth;
  job.colour_type = colour_type;
  job.compression_level = compression_level;
  job.pixels = pixels;
  job.row_bytes = row_bytes;
  job.out = out;
  if (!run_png_write(&job)) return Status(ErrorCode::kIo, path + ": PNG encoding failed: " + job.error.message);
  return Status::Ok();
}

std::vector<uint8_t> big_endian_bytes(const std::vector<uint16_t>& samples) {
  std::vector<uint8_t> bytes(samples.size() * 2);
  for (size_t i = 0; i < samples.size(); ++i) {
    bytes[2 * i] = static_cast<uint8_t>(samples[i] >> 8);
    bytes[2 * i + 1] = static_cast<uint8_t>(samples[i] & 0xff);
  }
  return bytes;
}

Status encode_gray16(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint16_t>& samples,
                     std::vector<uint8_t>* out) {
  Status status = check_buffer(path, width, height, samples.size(), 1);
  if (!status.ok()) return status;
  const std::vector<uint8_t> bytes = big_endian_bytes(samples);
  return encode_png(path, width, height, 16, PNG_COLOR_TYPE_GRAY, 9, bytes.data(), size_t{width} * 2, out);
}

Status write_png_8bit(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& bytes,
                      uint32_t channels, int colour_type) {
  Status status = check_buffer(path, width, height, bytes.size(), channels);
  if (!status.ok()) return status;
  std::vector<uint8_t> encoded;
  status = encode_png(path, width, height, 8, colour_type, 6, bytes.data(), size_t{width} * channels, &encoded);
  if (!status.ok()) return status;
  return write_file(path, encoded);
}

// ---------------------------------------------------------------------------
// PNG reading, in two setjmp stages around the size check: the header, then
// (once the caller has checked the size and allocated) the pixels.

struct PngSource {
  const uint8_t* data = nullptr;
  size_t size = 0, position = 0;
};

void read_png_bytes(png_structp png, png_bytep out, size_t length) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (length > source->size - source->position) png_error(png, "file ends early (truncated PNG)");
  std::memcpy(out, source->data + source->position, length);
  source->position += length;
}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

// Owns libpng's read structures across both stages.
struct PngReadStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrorSink error;
  PngReadStructs() {
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, png_error_to_sink, png_ignore_warning);
    if (png != nullptr) info = png_create_info_struct(png);
  }
  ~PngReadStructs() {
    if (png != nullptr) png_destroy_read_struct(&png, &info, nullptr);
  }
  PngReadStructs(const PngReadStructs&) = delete;
  PngReadStructs& operator=(const PngReadStructs&) = delete;
};

// setjmp frame: plain locals only.
bool run_png_read_header(PngReadStructs* structs, PngSource* source, PngHeader* header) {
  if (setjmp(png_jmpbuf(structs->png))) return false;
  png_set_read_fn(structs->png, source, read_png_bytes);
  // Our own pixel-count limit speaks instead of libpng's per-side default.
  png_set_user_limits(structs->png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  png_read_info(structs->png, structs->info);
  int interlace = 0, compression = 0, filter = 0;
  png_get_IHDR(structs->png, structs->info, &header->width, &header->height, &header->bit_depth,
               &header->colour_type, &interlace, &compression, &filter);
  return true;
}

// setjmp frame: plain locals only. `pixels` holds height rows of row_bytes.
bool run_png_read_pixels(PngReadStructs* structs, uint8_t* pixels, size_t row_bytes, uint32_t height) {
  if (setjmp(png_jmpbuf(structs->png))) return false;
  const int passes = png_set_interlace_handling(structs->png);
  png_read_update_info(structs->png, structs->info);
  if (png_get_rowbytes(structs->png, structs->info) != row_bytes) png_error(structs->png, "unexpected row size");
  for (int pass = 0; pass < passes; ++pass) {
    for (uint32_t y = 0; y < height; ++y) png_read_row(structs->png, pixels + size_t{y} * row_bytes, nullptr);
  }
  png_read_end(structs->png, nullptr);
  return true;
}

const char* colour_type_name(int colour_type) {
  switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY:
      return "gray";
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return "gray+alpha";
    case PNG_COLOR_TYPE_RGB:
      return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return "RGBA";
    case PNG_COLOR_TYPE_PALETTE:
      return "palette";
    default:
      return "unknown-colour-type";
  }
}

// ---------------------------------------------------------------------------
// PFM

bool is_pfm_space(uint8_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// The next header token after at least one whitespace byte; false if the
// file ends first or no whitespace separates it.
bool next_pfm_token(const std::vector<uint8_t>& data, size_t* position, std::string_view* token) {
  size_t i = *position;
  if (i >= data.size() || !is_pfm_space(data[i])) return false;
  while (i < data.size() && is_pfm_space(data[i])) ++i;
  const size_t start = i;
  while (i < data.size() && !is_pfm_space(data[i])) ++i;
  if (i == start) return false;
  *token = std::string_view(reinterpret_cast<const char*>(data.data()) + start, i - start);
  *position = i;
  return true;
}

// Tokens go into messages; keep them short and printable.
std::string quoted(std::string_view token) {
  std::string shown = "'";
  for (size_t i = 0; i < token.size() && i < 24; ++i) {
    const char c = token[i];
    shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  }
  if (token.size() > 24) shown += "...";
  return shown + "'";
}

Status parse_pfm_side(const std::string& path, std::string_view name, std::string_view token, uint32_t* side) {
  uint64_t value = 0;
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || value == 0 || value > kMaxImagePixels) {
    return invalid(path + ": PFM " + std::string(name) + " " + quoted(token) + " is not an integer in 1..2^26");
  }
  *side = static_cast<uint32_t>(value);
  return Status::Ok();
}

struct PfmHeader {
  uint32_t width = 0, height = 0;
  bool little_endian = true;
  size_t data_offset = 0;
};

Status parse_pfm_header(const std::string& path, const std::vector<uint8_t>& data, PfmHeader* header) {
  if (data.size() < 2 || data[0] != 'P' || (data[1] != 'f' && data[1] != 'F')) {
    return invalid(path + ": not a PFM file (it must start with 'Pf')");
  }
  if (data[1] == 'F') return invalid(path + ": colour PFM ('PF'); a geometry-image plane must be greyscale 'Pf'");
  size_t position = 2;
  std::string_view width, height, scale;
  if (!next_pfm_token(data, &position, &width) || !next_pfm_token(data, &position, &height) ||
      !next_pfm_token(data, &position, &scale)) {
    return invalid(path + ": PFM header ends early or is malformed (expected 'Pf', width, height, scale)");
  }
  Status status = parse_pfm_side(path, "width", width, &header->width);
  if (status.ok()) status = parse_pfm_side(path, "height", height, &header->height);
  if (status.ok()) status = check_dimensions(path, header->width, header->height);
  if (!status.ok()) return status;
  double value = 0;
  const char* end = scale.data() + scale.size();
  auto [ptr, ec] = std::from_chars(scale.data(), end, value);
  if (ec != std::errc() || ptr != end || value == 0 || !std::isfinite(value)) {
    return invalid(path + ": PFM scale " + quoted(scale) + " must be a non-zero number (negative: little-endian)");
  }
  if (position >= data.size()) return invalid(path + ": PFM header ends early (nothing after the scale)");
  header->little_endian = value < 0;
  header->data_offset = position + 1;  // exactly one whitespace byte ends the header
  return Status::Ok();
}

uint32_t load_u32(const uint8_t* bytes, bool little_endian) {
  if (little_endian) {
    return uint32_t{bytes[0]} | uint32_t{bytes[1]} << 8 | uint32_t{bytes[2]} << 16 | uint32_t{bytes[3]} << 24;
  }
  return uint32_t{bytes[3]} | uint32_t{bytes[2]} << 8 | uint32_t{bytes[1]} << 16 | uint32_t{bytes[0]} << 24;
}

}  // namespace

// ---------------------------------------------------------------------------
// PNG

Status write_png_gray16(const std::string& path, uint32_t width, uint32_t height,
                        const std::vector<uint16_t>& samples) {
  std::vector<uint8_t> encoded;
  Status status = encode_gray16(path, width, height, samples, &encoded);
  if (!status.ok()) return status;
  return write_file(path, encoded);
}

std::vector<uint8_t> encode_png_gray16_to_memory(uint32_t width, uint32_t height,
                                                 const std::vector<uint16_t>& samples) {
  std::vector<uint8_t> encoded;
  if (!encode_gray16("(memory)", width, height, samples, &encoded).ok()) encoded.clear();
  return encoded;
}

Status read_png_gray16(const std::string& path, uint32_t* width, uint32_t* height, std::vector<uint16_t>* samples) {
  std::vector<uint8_t> file;
  Status status = read_file(path, &file);
  if (!status.ok()) return status;
  if (file.size() < 8 || png_sig_cmp(file.data(), 0, 8) != 0) return invalid(path + ": not a PNG file (bad signature)");

  PngReadStructs structs;
  if (structs.png == nullptr || structs.info == nullptr) return Status(ErrorCode::kIo, path + ": out of memory for libpng");
  PngSource source;
  source.data = file.data();
  source.size = file.size();
  PngHeader header;
  if (!run_png_read_header(&structs, &source, &header)) return invalid(path + ": " + structs.error.message);
  if (header.bit_depth != 16 || header.colour_type != PNG_COLOR_TYPE_GRAY) {
    return invalid(path + ": " + std::to_string(header.bit_depth) + "-bit " + colour_type_name(header.colour_type) +
                   " PNG; " + kPlaneRule);
  }
  status = check_dimensions(path, header.width, header.height);
  if (!status.ok()) return status;

  const size_t row_bytes = size_t{header.width} * 2;
  std::vector<uint8_t> pixels(row_bytes * header.height);
  if (!run_png_read_pixels(&structs, pixels.data(), row_bytes, header.height)) {
    return invalid(path + ": " + structs.error.message);
  }
  std::vector<uint16_t> result(pixels.size() / 2);
  for (size_t i = 0; i < result.size(); ++i) {
    result[i] = static_cast<uint16_t>(pixels[2 * i] << 8 | pixels[2 * i + 1]);
  }
  *width = header.width;
  *height = header.height;
  *samples = std::move(result);
  return Status::Ok();
}

Status write_png_gray8(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& samples) {
  return write_png_8bit(path, width, height, samples, 1, PNG_COLOR_TYPE_GRAY);
}

Status write_png_rgb8(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgb) {
  return write_png_8bit(path, width, height, rgb, 3, PNG_COLOR_TYPE_RGB);
}

// ---------------------------------------------------------------------------
// PFM

Status write_pfm_gray(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& samples) {
  Status status = check_buffer(path, width, height, samples.size(), 1);
  if (!status.ok()) return status;
  const std::string text = "Pf\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
  std::vector<uint8_t> bytes(text.begin(), text.end());
  bytes.reserve(bytes.size() + samples.size() * 4);
  for (uint32_t row = height; row-- > 0;) {  // PFM: bottom row first
    for (uint32_t x = 0; x < width; ++x) {
      uint32_t bits = 0;
      std::memcpy(&bits, &samples[size_t{row} * width + x], sizeof bits);
      for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<uint8_t>(bits >> shift));
    }
  }
  return write_file(path, bytes);
}

Status read_pfm_gray(const std::string& path, uint32_t* width, uint32_t* height, std::vector<float>* samples) {
  std::vector<uint8_t> file;
  Status status = read_file(path, &file);
  if (!status.ok()) return status;
  PfmHeader header;
  status = parse_pfm_header(path, file, &header);
  if (!status.ok()) return status;

  const uint64_t expected = uint64_t{header.width} * header.height * 4;
  const uint64_t present = file.size() - header.data_offset;
  const std::string size = size_text(header.width, header.height);
  if (present < expected) {
    return invalid(path + ": truncated PFM: " + std::to_string(present) + " bytes of float data, " +
                   std::to_string(expected) + " needed for " + size);
  }
  if (present > expected) {
    return invalid(path + ": " + std::to_string(present - expected) + " extra bytes after the " + size +
                   " float data");
  }
  std::vector<float> result(size_t{header.width} * header.height);
  const uint8_t* data = file.data() + header.data_offset;
  for (uint32_t file_row = 0; file_row < header.height; ++file_row) {
    const size_t image_row = header.height - 1 - file_row;
    for (uint32_t x = 0; x < header.width; ++x) {
      const uint32_t bits = load_u32(data + (size_t{file_row} * header.width + x) * 4, header.little_endian);
      std::memcpy(&result[image_row * header.width + x], &bits, sizeof bits);
    }
  }
  *width = header.width;
  *height = header.height;
  *samples = std::move(result);
  return Status::Ok();
}

}  // namespace qmc::tools
