// qmc tools: OBJ, OFF, PLY and STL readers and OBJ, OFF, PLY writers.
//
// Every reader keeps faces and vertices exactly as the file lists them: no
// welding (except STL, which has no shared vertices to begin with), no
// removal of degenerate or non-manifold faces, no reordering.
#include "mesh_io.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <system_error>
#include <unordered_map>
#include <utility>

#include <sys/stat.h>

#include "atomic_file.h"

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Mesh;
using qmc::Status;

constexpr uint64_t kMaxIndex = std::numeric_limits<uint32_t>::max();

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

// "bunny.obj line 12: " -- the prefix of every text-format error.
std::string at_line(std::string_view name, uint64_t line) {
  return std::string(name) + " line " + std::to_string(line) + ": ";
}

// Tokens from a file go into messages; keep them short and printable so a
// binary file misread as text cannot flood the terminal.
std::string quoted(std::string_view token) {
  constexpr size_t kMaxShown = 40;
  std::string shown = "'";
  for (size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    shown += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (token.size() > kMaxShown) shown += "...";
  return shown + "'";
}

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

std::string to_lower(std::string_view text) {
  std::string result(text);
  for (char& c : result) c = lower(c);
  return result;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view strip_comment(std::string_view line) { return line.substr(0, line.find('#')); }

std::string_view strip_utf8_bom(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

void split_tokens(std::string_view line, std::vector<std::string_view>* tokens) {
  tokens->clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) tokens->push_back(line.substr(start, i - start));
  }
}

// ---------------------------------------------------------------------------
// Numbers. std::from_chars is locale-independent and correctly rounded, so
// text written with "%.9g" reads back bit-exact; it does not accept the
// leading '+' that some writers emit, so that is dropped first.

std::string_view drop_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-') token.remove_prefix(1);
  return token;
}

enum class Parse { kOk, kUnparsable, kOutOfRange };

template <class Number>
Parse parse_whole(std::string_view token, Number* out) {
  token = drop_plus(token);
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, *out);
  if (ec == std::errc::invalid_argument || ptr != end) return Parse::kUnparsable;
  if (ec == std::errc::result_out_of_range) return Parse::kOutOfRange;
  return Parse::kOk;
}

bool parse_int(std::string_view token, int64_t* out) { return parse_whole(token, out) == Parse::kOk; }

bool parse_count(std::string_view token, uint64_t* out) {
  return !token.empty() && token[0] != '-' && parse_whole(token, out) == Parse::kOk;
}

Parse parse_double(std::string_view token, double* out) {
  double value = 0;
  Parse result = parse_whole(token, &value);
  if (result == Parse::kOk) *out = value;
  return result;
}

// Parses straight to float (not via double) so the result is the float
// nearest to the decimal text. libstdc++ reports float underflow as out of
// range; such values are retried through double, which rounds them to a
// subnormal or zero as the text intends.
Parse parse_float(std::string_view token, float* out) {
  float value = 0;
  Parse result = parse_whole(token, &value);
  if (result == Parse::kOk) {
    *out = value;
    return result;
  }
  double wide = 0;
  if (result == Parse::kOutOfRange && parse_double(token, &wide) == Parse::kOk && std::fabs(wide) <= FLT_MAX) {
    *out = static_cast<float>(wide);
    return Parse::kOk;
  }
  return result;
}

// A coordinate must end up a finite float: the encoder cannot carry NaN or
// infinity, so the reader rejects them where the message can name the line.
// Returns an empty string on success, else the problem.
std::string parse_coordinate(std::string_view token, float* out) {
  switch (parse_float(token, out)) {
    case Parse::kOk:
      if (std::isfinite(*out)) return {};
      return "non-finite coordinate " + quoted(token);
    case Parse::kOutOfRange:
      return "coordinate " + quoted(token) + " is outside the float range";
    case Parse::kUnparsable:
      break;
  }
  return "unparsable number " + quoted(token);
}

// Values the mesh does not keep (colours, normals, w) must still be numbers.
bool is_number(std::string_view token) {
  double ignored = 0;
  return parse_double(token, &ignored) != Parse::kUnparsable;
}

// ---------------------------------------------------------------------------
// Line and token iteration with 1-based line numbers.

class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  bool next(std::string_view* line) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    *line = text_.substr(pos_, end - pos_);
    if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return true;
  }
  uint64_t line_number() const { return line_; }
  // Offset just past the last line returned (and its newline).
  size_t position() const { return std::min(pos_, text_.size()); }
  size_t bytes_left() const { return text_.size() - position(); }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  uint64_t line_ = 0;
};

// Whitespace-separated tokens across lines (ASCII PLY data, ASCII STL).
class TokenStream {
 public:
  TokenStream(std::string_view text, uint64_t first_line)
      : text_(text), line_(first_line), token_line_(first_line) {}

  bool next(std::string_view* token) {
    skip_space();
    if (pos_ >= text_.size()) return false;
    token_line_ = line_;
    size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    *token = text_.substr(start, pos_ - start);
    return true;
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }
  // Line of the last token returned (so "data ends early" points at the
  // last thing that was there).
  uint64_t line() const { return token_line_; }
  size_t bytes_left() const { return text_.size() - pos_; }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  std::string_view text_;
  size_t pos_ = 0;
  uint64_t line_;
  uint64_t token_line_;
};

// ---------------------------------------------------------------------------
// Warnings are tallied by kind so a file with a million normals yields one
// line ("ignored normal (vn) lines: 1000000"), not a million.

class WarningTally {
 public:
  void add(std::string_view kind, uint64_t count = 1) {
    if (count == 0) return;
    for (auto& entry : counted_) {
      if (entry.first == kind) {
        entry.second += count;
        return;
      }
    }
    counted_.emplace_back(std::string(kind), count);
  }
  size_t kinds() const { return counted_.size(); }
  // A sentence that already carries its counts.
  void note(std::string sentence) { notes_.push_back(std::move(sentence)); }

  void append_to(std::vector<std::string>* out) const {
    if (out == nullptr) return;
    for (const auto& entry : counted_) out->push_back(entry.first + ": " + std::to_string(entry.second));
    for (const auto& sentence : notes_) out->push_back(sentence);
  }

 private:
  std::vector<std::pair<std::string, uint64_t>> counted_;
  std::vector<std::string> notes_;
};

// Reserves for `claimed` items, but no more than the remaining input could
// possibly hold: a header claiming 2^40 vertices must not allocate before the
// data is there.
template <class T>
void reserve_bounded(std::vector<T>* items, uint64_t claimed, uint64_t bytes_left, uint64_t min_bytes_per_item) {
  uint64_t justified = bytes_left / std::max<uint64_t>(min_bytes_per_item, 1);
  items->reserve(items->size() + static_cast<size_t>(std::min(claimed, justified)));
}

// ---------------------------------------------------------------------------
// OBJ

// The vt or vn lines of an OBJ file (3 numbers each, missing ones 0) and the
// index each face corner gives, 0-based, resolved against the lines so far.
struct ObjValues {
  std::vector<float> values;
  uint32_t components = 0;  // the most numbers a line needs (vt: trailing zeros dropped)
  std::vector<int64_t> indices;
  std::vector<uint64_t> lines;  // of each index, for messages

  Status refer(int64_t value, uint64_t line, std::string_view file) {
    const int64_t stored = int64_t(values.size() / 3);
    if (value == 0) return invalid(at_line(file, line) + "index 0 is invalid (OBJ indices start at 1)");
    const int64_t index = value < 0 ? stored + value : value - 1;
    if (index < 0)
      return invalid(at_line(file, line) + "relative index " + std::to_string(value) + " reaches before the first");
    indices.push_back(index);
    lines.push_back(line);
    return Status::Ok();
  }
};

// What an OBJ statement after `keyword` says: the rest of the line, trimmed.
std::string_view rest_of(std::string_view statement, std::string_view keyword) {
  statement = trim(statement);
  return trim(statement.substr(std::min(statement.size(), keyword.size())));
}

// Objects, groups, materials and smoothing groups (o, g, usemtl, s): the face
// labels of spec section 16, "material" with the mtllib files as references.
struct ObjLabel {
  static constexpr uint32_t kUnset = UINT32_MAX;
  ObjLabel(const char* k, const char* n) : keyword(k), name(n) {}
  std::string_view keyword;
  const char* name;
  bool used = false;
  uint32_t current = kUnset;
  std::vector<std::string> values, references;
  std::vector<uint32_t> face_values;

  Status set(std::string_view value) {
    used = true;
    const auto it = std::find(values.begin(), values.end(), value);
    current = uint32_t(it - values.begin());
    if (it == values.end()) values.emplace_back(value);
    return Status::Ok();
  }
  FaceLabels finish() {
    FaceLabels out;
    out.name = name;
    out.references = std::move(references);
    out.values = std::move(values);
    out.face_values = std::move(face_values);
    for (uint32_t& v : out.face_values)
      if (v == kUnset) v = out.none();
    return out;
  }
};

class ObjParser {
 public:
  ObjParser(std::string_view name, WarningTally* warnings) : name_(name), warnings_(warnings) {}

  Status parse(std::string_view text, Mesh* mesh) {
    // OBJ is text: a NUL byte means a binary file given the wrong name,
    // whose lines would otherwise all be skipped as unknown keywords.
    if (size_t nul = text.find('\0'); nul != std::string_view::npos)
      return invalid(std::string(name_) + " byte " + std::to_string(nul) + ": a NUL byte; OBJ files are text");
    LineReader lines(text);
    std::string joined;
    std::string_view statement;
    uint64_t line = 0;
    while (next_statement(&lines, &joined, &statement, &line)) {
      const std::string_view body = strip_comment(statement);
      if (first_statement_line_ == 0 && !trim(body).empty()) {
        first_statement_line_ = line;
        first_statement_ = quoted(trim(body));
      }
      Status status = parse_statement(body, line, mesh);
      if (!status.ok()) return status;
    }
    // Statements but no geometry: not an OBJ mesh (or not one we can read).
    // A file of only blank and comment lines is an empty mesh.
    if (first_statement_line_ != 0 && mesh->positions.empty() && mesh->face_sizes.empty())
      return invalid(at_line(name_, first_statement_line_) +
                     "no vertex (v) or face (f) line in the whole file, which starts " + first_statement_);
    if (largest_index_ != kNoIndex && largest_index_ >= mesh->vertex_count()) {
      return invalid(at_line(name_, largest_index_line_) + "vertex index " + std::to_string(largest_index_ + 1) +
                     " is out of range (the file has " + std::to_string(mesh->vertex_count()) + " vertices)");
    }
    if (Status s = finish_attribute(&texcoords_, "texcoord", AttributeKind::kTextureCoordinate, "texture coordinate (vt)",
                                    mesh);
        !s.ok())
      return s;
    finish_vertex_colours(mesh);
    for (ObjLabel& label : labels_)
      if (label.used) mesh->face_labels.push_back(label.finish());
    return finish_attribute(&normals_, "normal", AttributeKind::kNormal, "normal (vn)", mesh);
  }

 private:
  static constexpr uint64_t kNoIndex = std::numeric_limits<uint64_t>::max();
  static constexpr size_t kMaxUnknownKinds = 16;

  // A trailing backslash continues a statement on the next line; errors
  // report the line the statement starts on.
  static bool next_statement(LineReader* lines, std::string* joined, std::string_view* statement,
                             uint64_t* first_line) {
    std::string_view line;
    if (!lines->next(&line)) return false;
    *first_line = lines->line_number();
    if (!ends_with_backslash(line)) {
      *statement = line;
      return true;
    }
    joined->clear();
    do {
      std::string_view body = trim(line);
      body.remove_suffix(1);
      joined->append(body);
      joined->push_back(' ');
    } while (lines->next(&line) && ends_with_backslash(line));
    if (!ends_with_backslash(line)) joined->append(line);
    *statement = *joined;
    return true;
  }

  // Statements a qmc::Mesh has no place for, each counted in a note. Groups,
  // objects, smoothing groups and materials carry no geometry but are
  // information all the same, so they never vanish silently either.
  static const char* ignored_statement_note(std::string_view keyword) {
    static constexpr std::pair<std::string_view, const char*> kNotes[] = {
        {"vp", "ignored parameter-space vertex (vp) lines"},
        {"l", "ignored polyline (l) elements"},
        {"p", "ignored point (p) elements"},
    };
    for (const auto& [name, note] : kNotes)
      if (keyword == name) return note;
    return nullptr;
  }

  static bool ends_with_backslash(std::string_view line) {
    line = trim(line);
    return !line.empty() && line.back() == '\\';
  }

  Status parse_statement(std::string_view statement, uint64_t line, Mesh* mesh) {
    split_tokens(statement, &tokens_);
    if (tokens_.empty()) return Status::Ok();
    std::string_view keyword = tokens_[0];
    if (keyword == "v") return parse_vertex(line, mesh);
    if (keyword == "f") return parse_face(line, mesh);
    if (keyword == "vt") return parse_values(line, 1, 3, &texcoords_);
    if (keyword == "vn") return parse_values(line, 3, 3, &normals_);
    for (ObjLabel& label : labels_)
      if (keyword == label.keyword) return label.set(rest_of(statement, keyword));
    if (keyword == "mtllib") {
      for (size_t i = 1; i < tokens_.size(); ++i) labels_[2].references.emplace_back(tokens_[i]);
      labels_[2].used = true;
      return Status::Ok();
    }
    if (const char* note = ignored_statement_note(keyword)) {
      warnings_->add(note);
    } else if (unknown_kinds_ < kMaxUnknownKinds) {
      size_t before = warnings_->kinds();
      warnings_->add("ignored lines with unknown keyword " + quoted(keyword));
      if (warnings_->kinds() > before) ++unknown_kinds_;
    } else {
      warnings_->add("ignored lines with other unknown keywords");
    }
    return Status::Ok();
  }

  // vt / vn: `min` .. `max` numbers (vt's v and w default to 0).
  Status parse_values(uint64_t line, size_t min, size_t max, ObjValues* out) {
    const size_t count = tokens_.size() - 1;
    if (count < min || count > max)
      return invalid(at_line(name_, line) + quoted(tokens_[0]) + " line has " + std::to_string(count) +
                     " number(s); " + std::to_string(min) + ".." + std::to_string(max) + " are allowed");
    for (size_t i = 0; i < max; ++i) {
      float value = 0;
      if (i < count)
        if (std::string problem = parse_coordinate(tokens_[1 + i], &value); !problem.empty())
          return invalid(at_line(name_, line) + problem + " in " + quoted(tokens_[0]) + " line");
      out->values.push_back(value);
      if (value != 0) out->components = std::max(out->components, uint32_t(i + 1));
    }
    out->components = std::max<uint32_t>(out->components, uint32_t(std::min<size_t>(count, 2)));
    return Status::Ok();
  }

  // Section 15 of the spec carries an attribute on every corner or none: a
  // file whose faces give some corners an index and others none keeps the
  // values out, with a note (qmc encode then asks for --drop-unsupported).
  Status finish_attribute(ObjValues* in, const char* name, AttributeKind kind, const char* what, Mesh* mesh) {
    const size_t stored = in->values.size() / 3;
    if (in->indices.empty()) {
      warnings_->add(std::string("ignored ") + what + " lines no face corner refers to", stored);
      return Status::Ok();
    }
    if (in->indices.size() != mesh->corners.size()) {
      warnings_->note("ignored " + std::string(what) + " values: only " + std::to_string(in->indices.size()) + " of " +
                      std::to_string(mesh->corners.size()) + " face corners refer to one");
      return Status::Ok();
    }
    MeshAttribute a;
    a.name = name;
    a.kind = kind;
    a.components = kind == AttributeKind::kNormal ? 3 : std::max<uint32_t>(in->components, 1);
    for (size_t i = 0; i < stored; ++i)
      for (uint32_t c = 0; c < a.components; ++c) a.values.push_back(in->values[3 * i + c]);
    a.corner_values.resize(in->indices.size());
    for (size_t k = 0; k < in->indices.size(); ++k) {
      const int64_t index = in->indices[k];
      if (index >= int64_t(stored))
        return invalid(at_line(name_, in->lines[k]) + what + " index " + std::to_string(index + 1) +
                       " is out of range (the file has " + std::to_string(stored) + ")");
      a.corner_values[k] = uint32_t(index);
    }
    mesh->attributes.push_back(std::move(a));
    return Status::Ok();
  }

  // `v x y z r g b` on every vertex: the attribute "colour", one value a
  // vertex. On only some vertices they are kept out, with a note.
  void finish_vertex_colours(Mesh* mesh) {
    const size_t coloured = vertex_colours_.size() / 3;
    if (coloured == 0) return;
    if (coloured != mesh->vertex_count()) {
      warnings_->note("ignored per-vertex colours on v lines: only " + std::to_string(coloured) + " of " +
                      std::to_string(mesh->vertex_count()) + " vertices have one");
      return;
    }
    MeshAttribute a;
    a.name = "colour";
    a.kind = AttributeKind::kColour;
    a.components = 3;
    a.values = std::move(vertex_colours_);
    a.corner_values = mesh->corners;
    mesh->attributes.push_back(std::move(a));
  }

  Status parse_vertex(uint64_t line, Mesh* mesh) {
    size_t values = tokens_.size() - 1;
    if (values < 3) {
      return invalid(at_line(name_, line) + "vertex has " + std::to_string(values) + " coordinate(s); 3 are needed");
    }
    if (mesh->vertex_count() >= kMaxIndex) return invalid(at_line(name_, line) + "more than 2^32-1 vertices");
    for (size_t i = 1; i <= 3; ++i) {
      float value = 0;
      std::string problem = parse_coordinate(tokens_[i], &value);
      if (!problem.empty()) return invalid(at_line(name_, line) + problem + " in vertex");
      mesh->positions.push_back(value);
    }
    for (size_t i = 4; i < tokens_.size(); ++i) {
      if (!is_number(tokens_[i])) return invalid(at_line(name_, line) + "unparsable number " + quoted(tokens_[i]));
    }
    if (values == 4) {
      warnings_->add("ignored w (homogeneous weight) values on v lines");
    } else if (values == 6) {  // x y z r g b: a colour per vertex
      for (size_t i = 4; i <= 6; ++i) {
        float value = 0;
        if (std::string problem = parse_coordinate(tokens_[i], &value); !problem.empty())
          return invalid(at_line(name_, line) + problem + " in a vertex colour");
        vertex_colours_.push_back(value);
      }
    } else if (values == 7) {
      warnings_->add("ignored per-vertex colours on v lines of 7 numbers");
    } else if (values > 3) {
      warnings_->add("ignored extra values on v lines");
    }
    return Status::Ok();
  }

  Status parse_face(uint64_t line, Mesh* mesh) {
    size_t corners = tokens_.size() - 1;
    if (corners < 3) {
      return invalid(at_line(name_, line) + "face has " + std::to_string(corners) +
                     " corner(s); at least 3 are needed");
    }
    for (size_t i = 1; i < tokens_.size(); ++i) {
      uint32_t index = 0;
      Status status = parse_corner(tokens_[i], line, mesh->vertex_count(), &index);
      if (!status.ok()) return status;
      mesh->corners.push_back(index);
    }
    mesh->face_sizes.push_back(static_cast<uint32_t>(corners));
    for (ObjLabel& label : labels_) label.face_values.push_back(label.current);
    return Status::Ok();
  }

  // Corner forms: i, i/t, i/t/n, i//n. Texture and normal references are
  // checked for syntax and counted; the mesh has nowhere to keep them.
  Status parse_corner(std::string_view token, uint64_t line, size_t vertices_so_far, uint32_t* index) {
    size_t slash = token.find('/');
    std::string_view vertex = token.substr(0, slash);
    if (slash != std::string_view::npos) {
      std::string_view rest = token.substr(slash + 1);
      size_t second = rest.find('/');
      std::string_view texture = rest.substr(0, second);
      bool has_normal = second != std::string_view::npos;
      std::string_view normal = has_normal ? rest.substr(second + 1) : std::string_view();
      int64_t texture_index = 0, normal_index = 0;
      bool texture_ok = texture.empty() ? has_normal : parse_int(texture, &texture_index);
      bool normal_ok = !has_normal || parse_int(normal, &normal_index);
      if (!texture_ok || !normal_ok) return invalid(at_line(name_, line) + "malformed face corner " + quoted(token));
      if (!texture.empty())
        if (Status s = texcoords_.refer(texture_index, line, name_); !s.ok()) return s;
      if (has_normal)
        if (Status s = normals_.refer(normal_index, line, name_); !s.ok()) return s;
    }
    int64_t value = 0;
    if (!parse_int(vertex, &value)) return invalid(at_line(name_, line) + "unparsable vertex index " + quoted(token));
    if (value == 0) return invalid(at_line(name_, line) + "vertex index 0 is invalid (OBJ indices start at 1)");
    if (value < 0) {
      // Relative: -1 is the most recent vertex.
      int64_t resolved = static_cast<int64_t>(vertices_so_far) + value;
      if (resolved < 0) {
        return invalid(at_line(name_, line) + "relative vertex index " + std::to_string(value) +
                       " reaches before the first vertex (" + std::to_string(vertices_so_far) + " so far)");
      }
      *index = static_cast<uint32_t>(resolved);
      return Status::Ok();
    }
    uint64_t zero_based = static_cast<uint64_t>(value) - 1;
    if (zero_based >= kMaxIndex) {
      return invalid(at_line(name_, line) + "vertex index " + std::to_string(value) + " is out of range");
    }
    // Positive indices may refer ahead; the largest is checked at the end.
    if (largest_index_ == kNoIndex || zero_based > largest_index_) {
      largest_index_ = zero_based;
      largest_index_line_ = line;
    }
    *index = static_cast<uint32_t>(zero_based);
    return Status::Ok();
  }

  std::string_view name_;
  WarningTally* warnings_;
  std::vector<std::string_view> tokens_;
  ObjValues texcoords_, normals_;
  std::vector<float> vertex_colours_;  // r g b of each v line that has them
  ObjLabel labels_[4] = {{"o", "object"}, {"g", "group"}, {"usemtl", "material"}, {"s", "smoothing"}};
  size_t unknown_kinds_ = 0;
  uint64_t largest_index_ = kNoIndex;
  uint64_t largest_index_line_ = 0;
  uint64_t first_statement_line_ = 0;  // 0: none yet
  std::string first_statement_;
};

// ---------------------------------------------------------------------------
// OFF

// Header keyword [ST][C][N][4][n]OFF, per the Geomview OFF description.
struct OffKind {
  bool texture = false;
  bool colour = false;
  bool normal = false;
  bool homogeneous = false;
  bool dimension = false;
};

bool parse_off_keyword(std::string_view token, OffKind* kind) {
  auto take = [&token](std::string_view prefix) {
    if (token.substr(0, prefix.size()) != prefix) return false;
    token.remove_prefix(prefix.size());
    return true;
  };
  kind->texture = take("ST");
  kind->colour = take("C");
  kind->normal = take("N");
  kind->homogeneous = take("4");
  kind->dimension = take("n");
  return token == "OFF";
}

class OffParser {
 public:
  OffParser(std::string_view text, std::string_view name, WarningTally* warnings)
      : lines_(text), name_(name), warnings_(warnings) {}

  Status parse(Mesh* mesh) {
    uint64_t vertex_count = 0;
    uint64_t face_count = 0;
    Status status = parse_header(&vertex_count, &face_count);
    if (status.ok()) status = parse_vertices(vertex_count, mesh);
    if (status.ok()) status = parse_faces(face_count, mesh);
    if (!status.ok()) return status;
    uint64_t trailing = 0;
    while (next_content()) ++trailing;
    warnings_->add("ignored lines after the last OFF face", trailing);
    return Status::Ok();
  }

 private:
  // Next line with anything left after removing '#' comments.
  bool next_content() {
    std::string_view line;
    while (lines_.next(&line)) {
      split_tokens(strip_comment(line), &tokens_);
      if (!tokens_.empty()) return true;
    }
    return false;
  }

  Status error(const std::string& problem) const { return invalid(at_line(name_, lines_.line_number()) + problem); }

  // The keyword is optional; the counts may follow it on the same line.
  Status parse_header(uint64_t* vertex_count, uint64_t* face_count) {
    if (!next_content()) return invalid(std::string(name_) + ": empty file, expected an OFF header");
    size_t first = 0;
    if (parse_off_keyword(tokens_[0], &kind_)) {
      first = 1;
      if (tokens_.size() > 1 && tokens_[1] == "BINARY") {
        return error("binary OFF is not supported; convert the file to ASCII OFF");
      }
      if (kind_.homogeneous) return error("4OFF (homogeneous coordinates) is not supported");
    } else if (!is_number(tokens_[0])) {
      return error("expected an OFF header keyword, found " + quoted(tokens_[0]));
    }
    auto refill = [&]() {
      if (first < tokens_.size()) return true;
      first = 0;
      return next_content();
    };
    if (kind_.dimension) {
      if (!refill()) return error("file ends before the nOFF dimension");
      int64_t dimension = 0;
      if (!parse_int(tokens_[first], &dimension)) return error("unparsable dimension " + quoted(tokens_[first]));
      if (dimension != 3) return error("nOFF with dimension " + std::to_string(dimension) + " is not supported");
      ++first;
    }
    if (!refill()) return error("file ends before the vertex and face counts");
    size_t counts = tokens_.size() - first;
    if (counts < 2 || counts > 3) return error("expected 'vertices faces [edges]' counts");
    uint64_t edges = 0;
    if (!parse_count(tokens_[first], vertex_count) || !parse_count(tokens_[first + 1], face_count) ||
        (counts == 3 && !parse_count(tokens_[first + 2], &edges))) {
      return error("unparsable vertex, face or edge count");
    }
    if (*vertex_count > kMaxIndex) return error("more than 2^32-1 vertices");
    return Status::Ok();
  }

  Status parse_vertices(uint64_t count, Mesh* mesh) {
    // Shortest vertex line: "0 0 0\n".
    reserve_bounded(&mesh->positions, count * 3, lines_.bytes_left() * 3, 6);
    for (uint64_t v = 0; v < count; ++v) {
      if (!next_content()) {
        return error("file ends after " + std::to_string(v) + " of " + std::to_string(count) + " vertices");
      }
      if (tokens_.size() < 3) return error("vertex line has fewer than 3 coordinates");
      for (size_t i = 0; i < 3; ++i) {
        float value = 0;
        std::string problem = parse_coordinate(tokens_[i], &value);
        if (!problem.empty()) return error(problem + " in vertex");
        mesh->positions.push_back(value);
      }
      for (size_t i = 3; i < tokens_.size(); ++i) {
        if (!is_number(tokens_[i])) return error("unparsable number " + quoted(tokens_[i]));
      }
      if (tokens_.size() > 3) tally_vertex_extras();
    }
    return Status::Ok();
  }

  void tally_vertex_extras() {
    if (kind_.normal) warnings_->add("ignored per-vertex normals (NOFF)");
    if (kind_.colour) warnings_->add("ignored per-vertex colours (COFF)");
    if (kind_.texture) warnings_->add("ignored per-vertex texture coordinates (STOFF)");
    if (!kind_.normal && !kind_.colour && !kind_.texture) warnings_->add("ignored extra values on OFF vertex lines");
  }

  Status parse_faces(uint64_t count, Mesh* mesh) {
    // Shortest face line: "3 0 0 0\n".
    reserve_bounded(&mesh->face_sizes, count, lines_.bytes_left(), 8);
    const uint64_t vertices = mesh->vertex_count();
    for (uint64_t f = 0; f < count; ++f) {
      if (!next_content()) {
        return error("file ends after " + std::to_string(f) + " of " + std::to_string(count) + " faces");
      }
      int64_t corners = 0;
      if (!parse_int(tokens_[0], &corners)) return error("unparsable face size " + quoted(tokens_[0]));
      if (corners < 3) {
        return error("face has " + std::to_string(corners) + " corner(s); at least 3 are needed");
      }
      if (static_cast<uint64_t>(corners) > tokens_.size() - 1) {
        return error("face declares " + std::to_string(corners) + " corners but lists " +
                     std::to_string(tokens_.size() - 1) + " values");
      }
      for (size_t i = 1; i <= static_cast<size_t>(corners); ++i) {
        int64_t index = 0;
        if (!parse_int(tokens_[i], &index)) return error("unparsable vertex index " + quoted(tokens_[i]));
        if (index < 0 || static_cast<uint64_t>(index) >= vertices) {
          return error("vertex index " + std::to_string(index) + " is out of range (the file has " +
                       std::to_string(vertices) + " vertices)");
        }
        mesh->corners.push_back(static_cast<uint32_t>(index));
      }
      for (size_t i = static_cast<size_t>(corners) + 1; i < tokens_.size(); ++i) {
        if (!is_number(tokens_[i])) return error("unparsable number " + quoted(tokens_[i]));
      }
      if (tokens_.size() > static_cast<size_t>(corners) + 1) warnings_->add("ignored face colours (OFF)");
      mesh->face_sizes.push_back(static_cast<uint32_t>(corners));
    }
    return Status::Ok();
  }

  LineReader lines_;
  std::string_view name_;
  WarningTally* warnings_;
  std::vector<std::string_view> tokens_;
  OffKind kind_;
};

// ---------------------------------------------------------------------------
// PLY header

enum class PlyType : uint8_t { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
enum class PlyFormat : uint8_t { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

bool parse_ply_type(std::string_view name, PlyType* type) {
  static const struct {
    const char* name;
    PlyType type;
  } kTypes[] = {
      {"char", PlyType::kInt8},     {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},   {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16}, {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},   {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32}, {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64},
  };
  for (const auto& entry : kTypes) {
    if (name == entry.name) {
      *type = entry.type;
      return true;
    }
  }
  return false;
}

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 8;
}

bool ply_type_is_integral(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;
  PlyType value_type = PlyType::kFloat32;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  uint64_t line = 0;
  std::vector<PlyProperty> properties;

  int find(std::string_view property) const {
    for (size_t i = 0; i < properties.size(); ++i) {
      if (properties[i].name == property) return static_cast<int>(i);
    }
    return -1;
  }
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;
  uint64_t data_line = 0;
};

class PlyHeaderParser {
 public:
  PlyHeaderParser(std::string_view text, std::string_view name) : lines_(text), name_(name) {}

  Status parse(PlyHeader* header) {
    std::string_view line;
    if (!lines_.next(&line) || trim(line) != "ply") return error("missing the 'ply' magic line");
    bool have_format = false;
    while (lines_.next(&line)) {
      split_tokens(line, &tokens_);
      if (tokens_.empty() || tokens_[0] == "comment" || tokens_[0] == "obj_info") continue;
      Status status;
      if (tokens_[0] == "format") {
        status = parse_format(&header->format);
        have_format = true;
      } else if (tokens_[0] == "element") {
        status = parse_element(header);
      } else if (tokens_[0] == "property") {
        status = parse_property(header);
      } else if (tokens_[0] == "end_header") {
        if (!have_format) return error("no 'format' line before end_header");
        header->data_offset = lines_.position();
        header->data_line = lines_.line_number() + 1;
        return Status::Ok();
      } else {
        status = error("unknown PLY header keyword " + quoted(tokens_[0]));
      }
      if (!status.ok()) return status;
    }
    return invalid(std::string(name_) + ": PLY header has no end_header line");
  }

 private:
  Status error(const std::string& problem) const { return invalid(at_line(name_, lines_.line_number()) + problem); }

  Status parse_format(PlyFormat* format) {
    if (tokens_.size() != 3) return error("expected 'format <encoding> 1.0'");
    if (tokens_[2] != "1.0" && tokens_[2] != "1") return error("unsupported PLY version " + quoted(tokens_[2]));
    if (tokens_[1] == "ascii") {
      *format = PlyFormat::kAscii;
    } else if (tokens_[1] == "binary_little_endian") {
      *format = PlyFormat::kBinaryLittleEndian;
    } else if (tokens_[1] == "binary_big_endian") {
      *format = PlyFormat::kBinaryBigEndian;
    } else {
      return error("unknown PLY encoding " + quoted(tokens_[1]));
    }
    return Status::Ok();
  }

  Status parse_element(PlyHeader* header) {
    if (tokens_.size() != 3) return error("expected 'element <name> <count>'");
    PlyElement element;
    element.name = std::string(tokens_[1]);
    element.line = lines_.line_number();
    if (!parse_count(tokens_[2], &element.count)) return error("unparsable element count " + quoted(tokens_[2]));
    for (const PlyElement& other : header->elements) {
      if (other.name == element.name) return error("element " + quoted(element.name) + " is declared twice");
    }
    header->elements.push_back(std::move(element));
    return Status::Ok();
  }

  Status parse_property(PlyHeader* header) {
    if (header->elements.empty()) return error("property before any element");
    PlyProperty property;
    bool ok = false;
    if (tokens_.size() == 5 && tokens_[1] == "list") {
      property.is_list = true;
      ok = parse_ply_type(tokens_[2], &property.count_type) && parse_ply_type(tokens_[3], &property.value_type);
      if (ok && !ply_type_is_integral(property.count_type)) return error("list count type must be an integer type");
      property.name = std::string(tokens_[4]);
    } else if (tokens_.size() == 3) {
      ok = parse_ply_type(tokens_[1], &property.value_type);
      property.name = std::string(tokens_[2]);
    } else {
      return error("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
    }
    if (!ok) return error("unknown PLY property type");
    header->elements.back().properties.push_back(std::move(property));
    return Status::Ok();
  }

  LineReader lines_;
  std::string_view name_;
  std::vector<std::string_view> tokens_;
};

// ---------------------------------------------------------------------------
// PLY data

struct PlyValue {
  int64_t integer = 0;  // integral types
  float single = 0;     // float32
  double real = 0;      // float64
};

// What is being read, for messages: "element 'face' item 12".
struct PlyItem {
  const PlyElement* element;
  uint64_t index;
};

std::string describe(const PlyItem& item) {
  return "element " + quoted(item.element->name) + " item " + std::to_string(item.index);
}

// Reads scalars from ASCII or binary PLY data with bounds checks, so a short
// or corrupt file gives an error naming the line or byte offset.
class PlyDataReader {
 public:
  PlyDataReader(std::string_view data, const PlyHeader& header, std::string_view name)
      : data_(data),
        tokens_(data, header.data_line),
        format_(header.format),
        base_offset_(header.data_offset),
        name_(name) {}

  bool binary() const { return format_ != PlyFormat::kAscii; }
  uint64_t bytes_left() const { return binary() ? data_.size() - pos_ : tokens_.bytes_left(); }

  // "bunny.ply line 40: " or "bunny.ply byte 1234: ".
  std::string where() const {
    if (!binary()) return at_line(name_, tokens_.line());
    return std::string(name_) + " byte " + std::to_string(base_offset_ + pos_) + ": ";
  }

  Status read(PlyType type, const PlyItem& item, PlyValue* value) {
    return binary() ? read_binary(type, item, value) : read_ascii(type, item, value);
  }

  // Skips `count` values of `type`; binary data is skipped without a loop so
  // a huge claimed count costs nothing before the bounds check fails it.
  Status skip(PlyType type, uint64_t count, const PlyItem& item) {
    if (binary()) return skip_bytes(count, ply_type_size(type), item);
    PlyValue ignored;
    for (uint64_t i = 0; i < count; ++i) {
      Status status = read_ascii(type, item, &ignored);
      if (!status.ok()) return status;
    }
    return Status::Ok();
  }

  // Skips `count` values of `size` bytes; `item` is where they start.
  Status skip_bytes(uint64_t count, uint64_t size, const PlyItem& item) {
    uint64_t left = data_.size() - pos_;
    if (size != 0 && count > left / size) return truncated(item);
    pos_ += static_cast<size_t>(count * size);
    return Status::Ok();
  }

  // Skips `count` whole items of `size` bytes each, naming the first item
  // that does not fit if the data is short.
  Status skip_items(const PlyElement& element, uint64_t size) {
    uint64_t left = data_.size() - pos_;
    if (size != 0 && element.count > left / size) {
      pos_ += static_cast<size_t>(left / size * size);
      return truncated(PlyItem{&element, left / size});
    }
    pos_ += static_cast<size_t>(element.count * size);
    return Status::Ok();
  }

  // Leftover data after the last element, for a warning.
  uint64_t trailing() {
    if (binary()) return data_.size() - pos_;
    uint64_t count = 0;
    std::string_view token;
    while (tokens_.next(&token)) ++count;
    return count;
  }

 private:
  Status truncated(const PlyItem& item) const {
    return invalid(where() + "truncated binary data in " + describe(item) + " (" +
                   std::to_string(data_.size() - pos_) + " bytes left)");
  }

  Status read_binary(PlyType type, const PlyItem& item, PlyValue* value) {
    size_t size = ply_type_size(type);
    if (data_.size() - pos_ < size) return truncated(item);
    uint64_t bits = 0;
    for (size_t i = 0; i < size; ++i) {
      size_t byte = format_ == PlyFormat::kBinaryLittleEndian ? i : size - 1 - i;
      bits |= uint64_t{static_cast<unsigned char>(data_[pos_ + byte])} << (8 * i);
    }
    pos_ += size;
    decode_bits(type, bits, value);
    return Status::Ok();
  }

  static void decode_bits(PlyType type, uint64_t bits, PlyValue* value) {
    switch (type) {
      case PlyType::kInt8:
        value->integer = static_cast<int8_t>(static_cast<uint8_t>(bits));
        break;
      case PlyType::kInt16:
        value->integer = static_cast<int16_t>(static_cast<uint16_t>(bits));
        break;
      case PlyType::kInt32:
        value->integer = static_cast<int32_t>(static_cast<uint32_t>(bits));
        break;
      case PlyType::kUint8:
      case PlyType::kUint16:
      case PlyType::kUint32:
        value->integer = static_cast<int64_t>(bits);
        break;
      case PlyType::kFloat32: {
        uint32_t narrow = static_cast<uint32_t>(bits);
        std::memcpy(&value->single, &narrow, sizeof narrow);
        break;
      }
      case PlyType::kFloat64:
        std::memcpy(&value->real, &bits, sizeof bits);
        break;
    }
  }

  Status read_ascii(PlyType type, const PlyItem& item, PlyValue* value) {
    std::string_view token;
    if (!tokens_.next(&token)) return invalid(where() + "data ends inside " + describe(item));
    bool ok = false;
    if (type == PlyType::kFloat32) {
      ok = parse_float(token, &value->single) == Parse::kOk;
    } else if (type == PlyType::kFloat64) {
      ok = parse_double(token, &value->real) == Parse::kOk;
    } else {
      ok = parse_int(token, &value->integer) && fits(type, value->integer);
    }
    if (!ok) return invalid(where() + "unparsable or out-of-range value " + quoted(token) + " in " + describe(item));
    return Status::Ok();
  }

  static bool fits(PlyType type, int64_t v) {
    switch (type) {
      case PlyType::kInt8:
        return v >= -128 && v <= 127;
      case PlyType::kUint8:
        return v >= 0 && v <= 255;
      case PlyType::kInt16:
        return v >= -32768 && v <= 32767;
      case PlyType::kUint16:
        return v >= 0 && v <= 65535;
      case PlyType::kInt32:
        return v >= INT32_MIN && v <= INT32_MAX;
      case PlyType::kUint32:
        return v >= 0 && v <= int64_t{UINT32_MAX};
      default:
        return true;
    }
  }

  std::string_view data_;
  size_t pos_ = 0;  // binary position within data_
  TokenStream tokens_;
  PlyFormat format_;
  size_t base_offset_;
  std::string_view name_;
};

// Converts a stored x/y/z value; false if it is not a finite float.
bool ply_coordinate(PlyType type, const PlyValue& value, float* out) {
  if (type == PlyType::kFloat32) {
    *out = value.single;
  } else if (type == PlyType::kFloat64) {
    // A double beyond the float range has no float value (casting it is UB).
    if (!(std::fabs(value.real) <= FLT_MAX)) return false;
    *out = static_cast<float>(value.real);
  } else {
    *out = static_cast<float>(value.integer);
  }
  return std::isfinite(*out);
}

std::string describe_value(PlyType type, const PlyValue& value) {
  if (type == PlyType::kFloat32) return std::to_string(value.single);
  if (type == PlyType::kFloat64) return std::to_string(value.real);
  return std::to_string(value.integer);
}

// Minimum bytes (binary) or characters (ASCII: a digit and a separator per
// value) an item of this element occupies, for bounded reservations.
uint64_t min_item_size(const PlyElement& element, bool binary, uint64_t min_list_length) {
  uint64_t size = 0;
  for (const PlyProperty& property : element.properties) {
    if (property.is_list) {
      size += binary ? ply_type_size(property.count_type) + min_list_length * ply_type_size(property.value_type)
                     : 2 * (1 + min_list_length);
    } else {
      size += binary ? ply_type_size(property.value_type) : 2;
    }
  }
  return size;
}

std::string property_names(const PlyElement& element, const std::vector<int>& used) {
  std::string names;
  for (size_t i = 0; i < element.properties.size(); ++i) {
    if (std::find(used.begin(), used.end(), static_cast<int>(i)) != used.end()) continue;
    if (!names.empty()) names += ", ";
    names += element.properties[i].name;
  }
  return names;
}

// A per-vertex attribute of a PLY file (spec 15): the vertex properties
// that make it, and its values as read.
struct PlyVertexAttribute {
  const char* name;
  AttributeKind kind;
  std::vector<int> properties;  // indices in the vertex element, in component order
  std::vector<float> values;
};

// The property names PLY files use for normals, texture coordinates and
// colours, in order of preference.
const std::vector<std::pair<std::vector<const char*>, std::pair<const char*, AttributeKind>>>& ply_attribute_names() {
  static const std::vector<std::pair<std::vector<const char*>, std::pair<const char*, AttributeKind>>> kNames = {
      {{"nx", "ny", "nz"}, {"normal", AttributeKind::kNormal}},
      {{"u", "v"}, {"texcoord", AttributeKind::kTextureCoordinate}},
      {{"s", "t"}, {"texcoord", AttributeKind::kTextureCoordinate}},
      {{"texture_u", "texture_v"}, {"texcoord", AttributeKind::kTextureCoordinate}},
      {{"texture_s", "texture_t"}, {"texcoord", AttributeKind::kTextureCoordinate}},
      {{"red", "green", "blue"}, {"colour", AttributeKind::kColour}},
      {{"alpha"}, {"alpha", AttributeKind::kGeneric}},
  };
  return kNames;
}

class PlyParser {
 public:
  PlyParser(std::string_view text, std::string_view name, WarningTally* warnings)
      : text_(text), name_(name), warnings_(warnings) {}

  Status parse(Mesh* mesh) {
    Status status = PlyHeaderParser(text_, name_).parse(&header_);
    if (!status.ok()) return status;
    status = find_roles();
    if (!status.ok()) return status;
    PlyDataReader reader(text_.substr(header_.data_offset), header_, name_);
    for (const PlyElement& element : header_.elements) {
      if (&element == vertex_element_) {
        status = read_vertices(element, &reader, mesh);
      } else if (&element == face_element_) {
        status = read_faces(element, &reader, mesh);
      } else {
        status = skip_element(element, &reader);
      }
      if (!status.ok()) return status;
    }
    if (faces_before_vertices_) {
      status = check_deferred_indices(*mesh);
      if (!status.ok()) return status;
    }
    finish_attributes(mesh);
    warnings_->add(reader.binary() ? "ignored trailing bytes after the PLY data" : "ignored trailing values after the PLY data",
                   reader.trailing());
    return Status::Ok();
  }

 private:
  Status header_error(const PlyElement& element, const std::string& problem) const {
    return invalid(at_line(name_, element.line) + problem);
  }

  Status find_roles() {
    for (const PlyElement& element : header_.elements) {
      if (element.name == "vertex") vertex_element_ = &element;
      if (element.name == "face") face_element_ = &element;
    }
    if (vertex_element_ == nullptr) return invalid(std::string(name_) + ": PLY file has no 'vertex' element");
    const char* axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      xyz_[axis] = vertex_element_->find(axes[axis]);
      if (xyz_[axis] < 0 || vertex_element_->properties[xyz_[axis]].is_list) {
        return header_error(*vertex_element_, std::string("vertex element has no scalar property '") + axes[axis] + "'");
      }
    }
    find_vertex_attributes();
    if (face_element_ == nullptr) return Status::Ok();
    texcoord_list_ = face_element_->find("texcoord");
    if (texcoord_list_ >= 0 && (!face_element_->properties[texcoord_list_].is_list ||
                                ply_type_is_integral(face_element_->properties[texcoord_list_].value_type)))
      texcoord_list_ = -1;
    indices_ = face_element_->find("vertex_indices");
    if (indices_ < 0) indices_ = face_element_->find("vertex_index");
    if (indices_ < 0 || !face_element_->properties[indices_].is_list) {
      return header_error(*face_element_, "face element has no list property 'vertex_indices' or 'vertex_index'");
    }
    if (!ply_type_is_integral(face_element_->properties[indices_].value_type)) {
      return header_error(*face_element_, "face vertex indices have a floating-point type");
    }
    return Status::Ok();
  }

  // Spec 15: normals, texture coordinates, colours and alpha, each whole
  // (every component a scalar property) or not at all; one texcoord.
  void find_vertex_attributes() {
    for (const auto& [names, what] : ply_attribute_names()) {
      PlyVertexAttribute a{what.first, what.second, {}, {}};
      for (const char* name : names) {
        const int p = vertex_element_->find(name);
        if (p < 0 || vertex_element_->properties[p].is_list) break;
        a.properties.push_back(p);
      }
      if (a.properties.size() != names.size()) continue;
      bool taken = false;
      for (const PlyVertexAttribute& b : vertex_attributes_) taken = taken || std::string(b.name) == a.name;
      if (!taken) vertex_attributes_.push_back(std::move(a));
    }
  }

  // Per-vertex attributes: each corner refers to its vertex's value; the
  // face texcoord lists, per corner, take the place of vertex ones.
  void finish_attributes(Mesh* mesh) {
    for (PlyVertexAttribute& a : vertex_attributes_) {
      if (a.kind == AttributeKind::kTextureCoordinate && corner_texcoords_.size() == mesh->corners.size() &&
          !mesh->corners.empty())
        continue;
      MeshAttribute out;
      out.name = a.name;
      out.kind = a.kind;
      out.components = uint32_t(a.properties.size());
      out.values = std::move(a.values);
      out.corner_values = mesh->corners;
      mesh->attributes.push_back(std::move(out));
    }
    if (corner_texcoords_.empty()) return;
    if (corner_texcoords_.size() != mesh->corners.size()) {
      warnings_->note("ignored PLY face texcoord lists: only " + std::to_string(corner_texcoords_.size()) + " of " +
                      std::to_string(mesh->corners.size()) + " face corners have one");
      return;
    }
    MeshAttribute out{"texcoord", AttributeKind::kTextureCoordinate, 2, {}, {}};
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> index;  // equal bit patterns share a value
    for (const auto& [u, v] : corner_texcoords_) {
      uint32_t key[2];
      std::memcpy(&key[0], &u, 4);
      std::memcpy(&key[1], &v, 4);
      const auto [it, added] = index.emplace(std::make_pair(key[0], key[1]), uint32_t(out.value_count()));
      if (added) out.values.insert(out.values.end(), {u, v});
      out.corner_values.push_back(it->second);
    }
    mesh->attributes.push_back(std::move(out));
  }

  Status read_vertices(const PlyElement& element, PlyDataReader* reader, Mesh* mesh) {
    reserve_bounded(&mesh->positions, element.count * 3, reader->bytes_left() * 3,
                    min_item_size(element, reader->binary(), 0));
    for (uint64_t v = 0; v < element.count; ++v) {
      PlyItem item{&element, v};
      float xyz[3] = {0, 0, 0};
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.is_list) {
          Status status = skip_list(property, item, reader);
          if (!status.ok()) return status;
          continue;
        }
        PlyValue value;
        Status status = reader->read(property.value_type, item, &value);
        if (!status.ok()) return status;
        for (int axis = 0; axis < 3; ++axis) {
          if (xyz_[axis] != static_cast<int>(p)) continue;
          if (!ply_coordinate(property.value_type, value, &xyz[axis])) {
            return invalid(reader->where() + "non-finite or out-of-range coordinate " +
                           describe_value(property.value_type, value) + " in " + describe(item));
          }
        }
        for (PlyVertexAttribute& a : vertex_attributes_)
          for (size_t c = 0; c < a.properties.size(); ++c)
            if (a.properties[c] == static_cast<int>(p)) {
              float x = 0;
              if (!ply_coordinate(property.value_type, value, &x))
                return invalid(reader->where() + "non-finite " + property.name + " in " + describe(item));
              a.values.push_back(x);
            }
      }
      mesh->positions.insert(mesh->positions.end(), xyz, xyz + 3);
    }
    vertices_read_ = true;
    std::vector<int> used = {xyz_[0], xyz_[1], xyz_[2]};
    for (const PlyVertexAttribute& a : vertex_attributes_) used.insert(used.end(), a.properties.begin(), a.properties.end());
    std::string extra = property_names(element, used);
    if (!extra.empty() && element.count > 0) {
      warnings_->note("ignored PLY vertex properties (" + extra + ") on " + std::to_string(element.count) +
                      " vertices");
    }
    return Status::Ok();
  }

  Status read_faces(const PlyElement& element, PlyDataReader* reader, Mesh* mesh) {
    faces_before_vertices_ = !vertices_read_;
    reserve_bounded(&mesh->face_sizes, element.count, reader->bytes_left(), min_item_size(element, reader->binary(), 3));
    for (uint64_t f = 0; f < element.count; ++f) {
      PlyItem item{&element, f};
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        Status status = static_cast<int>(p) == indices_        ? read_face_corners(property, item, reader, mesh)
                        : static_cast<int>(p) == texcoord_list_ ? read_face_texcoords(property, item, reader)
                        : property.is_list                     ? skip_list(property, item, reader)
                                                               : reader->skip(property.value_type, 1, item);
        if (!status.ok()) return status;
      }
    }
    std::string extra = property_names(element, {indices_, texcoord_list_});
    if (!extra.empty() && element.count > 0) {
      warnings_->note("ignored PLY face properties (" + extra + ") on " + std::to_string(element.count) + " faces");
    }
    return Status::Ok();
  }

  Status read_face_corners(const PlyProperty& property, const PlyItem& item, PlyDataReader* reader, Mesh* mesh) {
    PlyValue count;
    Status status = reader->read(property.count_type, item, &count);
    if (!status.ok()) return status;
    if (count.integer < 3) {
      return invalid(reader->where() + describe(item) + ": face has " + std::to_string(count.integer) +
                     " corner(s); at least 3 are needed");
    }
    uint64_t corners = static_cast<uint64_t>(count.integer);
    size_t index_size = ply_type_size(property.value_type);
    if (reader->binary() && corners > reader->bytes_left() / index_size) {
      return reader->skip_bytes(corners, index_size, item);  // reports the truncation
    }
    const uint64_t vertices = mesh->vertex_count();
    for (uint64_t c = 0; c < corners; ++c) {
      PlyValue index;
      status = reader->read(property.value_type, item, &index);
      if (!status.ok()) return status;
      bool in_range = index.integer >= 0 && static_cast<uint64_t>(index.integer) < kMaxIndex &&
                      (faces_before_vertices_ || static_cast<uint64_t>(index.integer) < vertices);
      if (!in_range) {
        return invalid(reader->where() + "vertex index " + std::to_string(index.integer) + " in " + describe(item) +
                       " is out of range (the file has " + std::to_string(vertex_element_->count) + " vertices)");
      }
      mesh->corners.push_back(static_cast<uint32_t>(index.integer));
    }
    mesh->face_sizes.push_back(static_cast<uint32_t>(corners));
    last_degree_ = corners;
    return Status::Ok();
  }

  // A face's texcoord list: u v per corner (spec 15, texture coordinates
  // with their own value per corner). A list of another length is an error.
  Status read_face_texcoords(const PlyProperty& property, const PlyItem& item, PlyDataReader* reader) {
    PlyValue count;
    if (Status status = reader->read(property.count_type, item, &count); !status.ok()) return status;
    const bool degree_known = indices_ < texcoord_list_;  // the corners came first in this face
    if (count.integer < 0 || count.integer % 2 != 0 || count.integer > int64_t(reader->bytes_left()) ||
        (degree_known && count.integer != 0 && uint64_t(count.integer) != 2 * last_degree_))
      return invalid(reader->where() + describe(item) + ": a texcoord list of " + std::to_string(count.integer) +
                     " numbers, not two per corner");
    for (int64_t i = 0; i < count.integer; i += 2) {
      PlyValue u, v;
      float uv[2];
      if (Status status = reader->read(property.value_type, item, &u); !status.ok()) return status;
      if (Status status = reader->read(property.value_type, item, &v); !status.ok()) return status;
      if (!ply_coordinate(property.value_type, u, &uv[0]) || !ply_coordinate(property.value_type, v, &uv[1]))
        return invalid(reader->where() + "non-finite texcoord in " + describe(item));
      corner_texcoords_.emplace_back(uv[0], uv[1]);
    }
    return Status::Ok();
  }

  Status skip_list(const PlyProperty& property, const PlyItem& item, PlyDataReader* reader) {
    PlyValue count;
    Status status = reader->read(property.count_type, item, &count);
    if (!status.ok()) return status;
    if (count.integer < 0) return invalid(reader->where() + "negative list length in " + describe(item));
    return reader->skip(property.value_type, static_cast<uint64_t>(count.integer), item);
  }

  Status skip_element(const PlyElement& element, PlyDataReader* reader) {
    if (element.count > 0) {
      warnings_->note("ignored PLY element " + quoted(element.name) + " (" + std::to_string(element.count) +
                      " items)");
    }
    if (element.properties.empty()) return Status::Ok();
    bool fixed_size = reader->binary() && std::none_of(element.properties.begin(), element.properties.end(),
                                                       [](const PlyProperty& p) { return p.is_list; });
    if (fixed_size) return reader->skip_items(element, min_item_size(element, true, 0));
    // Every item consumes at least one byte or token, so this loop is bounded by the data.
    for (uint64_t i = 0; i < element.count; ++i) {
      PlyItem item{&element, i};
      for (const PlyProperty& property : element.properties) {
        Status status = property.is_list ? skip_list(property, item, reader) : reader->skip(property.value_type, 1, item);
        if (!status.ok()) return status;
      }
    }
    return Status::Ok();
  }

  // Only when faces precede vertices in the file: indices could not be
  // checked while reading.
  Status check_deferred_indices(const Mesh& mesh) const {
    for (size_t i = 0; i < mesh.corners.size(); ++i) {
      if (mesh.corners[i] >= mesh.vertex_count()) {
        return invalid(std::string(name_) + ": face vertex index " + std::to_string(mesh.corners[i]) +
                       " is out of range (the file has " + std::to_string(mesh.vertex_count()) + " vertices)");
      }
    }
    return Status::Ok();
  }

  std::string_view text_;
  std::string_view name_;
  WarningTally* warnings_;
  PlyHeader header_;
  const PlyElement* vertex_element_ = nullptr;
  const PlyElement* face_element_ = nullptr;
  int xyz_[3] = {-1, -1, -1};
  int indices_ = -1;
  int texcoord_list_ = -1;                 // face "texcoord" list (u v per corner), if any
  uint64_t last_degree_ = 0;               // corners of the face read last
  std::vector<PlyVertexAttribute> vertex_attributes_;
  std::vector<std::pair<float, float>> corner_texcoords_;
  bool vertices_read_ = false;
  bool faces_before_vertices_ = false;
};

// ---------------------------------------------------------------------------
// STL

// STL lists each triangle's corners by value; corners with bit-identical
// positions become one vertex, numbered in order of first appearance.
class StlVertexMerger {
 public:
  explicit StlVertexMerger(Mesh* mesh) : mesh_(mesh) {}

  void reserve(uint64_t corners) { map_.reserve(static_cast<size_t>(corners)); }

  void add(const float xyz[3]) {
    Key key{bits(xyz[0]), bits(xyz[1]), bits(xyz[2])};
    auto [it, inserted] = map_.try_emplace(key, static_cast<uint32_t>(mesh_->vertex_count()));
    if (inserted) mesh_->positions.insert(mesh_->positions.end(), xyz, xyz + 3);
    mesh_->corners.push_back(it->second);
    ++corners_;
  }

  void report(WarningTally* warnings) const {
    if (corners_ == 0) return;
    warnings->note("merged " + std::to_string(corners_) + " STL corners into " +
                   std::to_string(mesh_->vertex_count()) + " vertices");
  }

 private:
  struct Key {
    uint32_t x, y, z;
    bool operator==(const Key& other) const { return x == other.x && y == other.y && z == other.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& key) const {
      uint64_t h = (uint64_t{key.x} << 32 | key.y) * 0x9E3779B97F4A7C15ull;
      h ^= (h >> 29) ^ (uint64_t{key.z} * 0xBF58476D1CE4E5B9ull);
      return static_cast<size_t>(h ^ (h >> 32));
    }
  };
  static uint32_t bits(float value) {
    uint32_t result = 0;
    std::memcpy(&result, &value, sizeof result);
    return result;
  }

  Mesh* mesh_;
  std::unordered_map<Key, uint32_t, KeyHash> map_;
  uint64_t corners_ = 0;
};

uint32_t read_le32(const char* p) {
  uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(p[i]);
  return value;
}

float read_le_float(const char* p) {
  uint32_t bits = read_le32(p);
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

constexpr uint64_t kStlHeaderBytes = 84;
constexpr uint64_t kStlTriangleBytes = 50;

// Binary when the size matches the triangle count exactly (some binary files
// also begin with "solid"); otherwise ASCII if it starts with "solid" and
// holds no NUL byte (which ASCII STL never does, and a binary file whose
// count is wrong almost always does, in the count itself if nowhere else).
bool stl_is_binary(std::string_view data) {
  if (data.size() >= kStlHeaderBytes &&
      kStlHeaderBytes + kStlTriangleBytes * uint64_t{read_le32(data.data() + 80)} == data.size()) {
    return true;
  }
  std::string_view start = trim(data.substr(0, 64));
  const bool says_solid = start.size() >= 5 && equals_ignoring_case(start.substr(0, 5), "solid") &&
                          (start.size() == 5 || is_space(start[5]));
  return !says_solid || data.find('\0') != std::string_view::npos;
}

Status parse_binary_stl(std::string_view data, std::string_view name, Mesh* mesh, WarningTally* warnings) {
  if (data.size() < kStlHeaderBytes) {
    return invalid(std::string(name) + ": truncated binary STL: " + std::to_string(data.size()) +
                   " bytes, the header alone needs 84");
  }
  uint64_t triangles = read_le32(data.data() + 80);
  uint64_t needed = kStlHeaderBytes + kStlTriangleBytes * triangles;
  if (data.size() < needed) {
    return invalid(std::string(name) + ": truncated binary STL: header says " + std::to_string(triangles) +
                   " triangles (" + std::to_string(needed) + " bytes) but the file has " +
                   std::to_string(data.size()) + " bytes");
  }
  // More whole triangles than the count says: the count is wrong (some
  // writers leave it 0), and reading only that many would silently drop the
  // rest. Fewer than 50 extra bytes are padding, noted below.
  if (const uint64_t room = (data.size() - kStlHeaderBytes) / kStlTriangleBytes; room != triangles) {
    return invalid(std::string(name) + " byte 80: binary STL header says " + std::to_string(triangles) +
                   " triangles but the file's " + std::to_string(data.size()) + " bytes hold " + std::to_string(room) +
                   " (84-byte header, 50 bytes per triangle)");
  }
  StlVertexMerger merger(mesh);
  merger.reserve(triangles * 3);
  mesh->face_sizes.reserve(static_cast<size_t>(triangles));
  uint64_t attributes = 0;
  for (uint64_t t = 0; t < triangles; ++t) {
    const char* record = data.data() + kStlHeaderBytes + kStlTriangleBytes * t;
    for (int corner = 0; corner < 3; ++corner) {
      float xyz[3];
      for (int axis = 0; axis < 3; ++axis) xyz[axis] = read_le_float(record + 12 + 12 * corner + 4 * axis);
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        return invalid(std::string(name) + " byte " + std::to_string(kStlHeaderBytes + kStlTriangleBytes * t) +
                       ": non-finite coordinate in triangle " + std::to_string(t));
      }
      merger.add(xyz);
    }
    mesh->face_sizes.push_back(3);
    if (record[48] != 0 || record[49] != 0) ++attributes;
  }
  warnings->add("ignored STL facet normals", triangles);
  warnings->add("ignored non-zero STL attribute words", attributes);
  warnings->add("ignored trailing bytes after the STL triangles", data.size() - needed);
  merger.report(warnings);
  return Status::Ok();
}

class AsciiStlParser {
 public:
  AsciiStlParser(std::string_view text, std::string_view name, WarningTally* warnings)
      : tokens_(text, 1), name_(name), warnings_(warnings) {}

  Status parse(Mesh* mesh) {
    StlVertexMerger merger(mesh);
    std::string_view token;
    while (tokens_.next(&token)) {
      if (!equals_ignoring_case(token, "solid")) return error("expected 'solid', found " + quoted(token));
      tokens_.skip_line();  // the solid's name
      Status status = parse_solid(&merger, mesh);
      if (!status.ok()) return status;
    }
    warnings_->add("ignored STL facet normals", facets_);
    merger.report(warnings_);
    return Status::Ok();
  }

 private:
  Status error(const std::string& problem) const { return invalid(at_line(name_, tokens_.line()) + problem); }

  Status expect(std::string_view keyword) {
    std::string_view token;
    if (!tokens_.next(&token)) return error("file ends where '" + std::string(keyword) + "' was expected");
    if (!equals_ignoring_case(token, keyword)) {
      return error("expected '" + std::string(keyword) + "', found " + quoted(token));
    }
    return Status::Ok();
  }

  Status parse_solid(StlVertexMerger* merger, Mesh* mesh) {
    std::string_view token;
    while (tokens_.next(&token)) {
      if (equals_ignoring_case(token, "endsolid")) {
        tokens_.skip_line();
        return Status::Ok();
      }
      if (!equals_ignoring_case(token, "facet")) return error("expected 'facet' or 'endsolid', found " + quoted(token));
      Status status = parse_facet(merger, mesh);
      if (!status.ok()) return status;
    }
    warnings_->add("STL solids without 'endsolid'");
    return Status::Ok();
  }

  Status parse_facet(StlVertexMerger* merger, Mesh* mesh) {
    Status status = expect("normal");
    for (int i = 0; i < 3 && status.ok(); ++i) status = read_number(nullptr);
    if (status.ok()) status = expect("outer");
    if (status.ok()) status = expect("loop");
    if (!status.ok()) return status;
    std::string_view token;
    uint32_t corners = 0;
    while (tokens_.next(&token) && equals_ignoring_case(token, "vertex")) {
      float xyz[3];
      for (int axis = 0; axis < 3 && status.ok(); ++axis) status = read_number(&xyz[axis]);
      if (!status.ok()) return status;
      merger->add(xyz);
      ++corners;
    }
    if (!equals_ignoring_case(token, "endloop")) return error("expected 'vertex' or 'endloop'");
    if (corners < 3) return error("facet has " + std::to_string(corners) + " vertices; at least 3 are needed");
    mesh->face_sizes.push_back(corners);
    ++facets_;
    return expect("endfacet");
  }

  // With a null `coordinate` (normals) any number is accepted, even NaN.
  Status read_number(float* coordinate) {
    std::string_view token;
    if (!tokens_.next(&token)) return error("file ends inside a facet");
    if (coordinate == nullptr) return is_number(token) ? Status::Ok() : error("unparsable number " + quoted(token));
    std::string problem = parse_coordinate(token, coordinate);
    return problem.empty() ? Status::Ok() : error(problem + " in vertex");
  }

  TokenStream tokens_;
  std::string_view name_;
  WarningTally* warnings_;
  uint64_t facets_ = 0;
};

// ---------------------------------------------------------------------------
// Dispatch

Status parse_any(std::string_view data, const std::string& format, std::string_view name, Mesh* mesh,
                 WarningTally* warnings) {
  if (format == "obj") return ObjParser(name, warnings).parse(strip_utf8_bom(data), mesh);
  if (format == "off") return OffParser(strip_utf8_bom(data), name, warnings).parse(mesh);
  if (format == "ply") return PlyParser(data, name, warnings).parse(mesh);
  if (stl_is_binary(data)) return parse_binary_stl(data, name, mesh, warnings);
  return AsciiStlParser(data, name, warnings).parse(mesh);
}

bool is_readable_format(const std::string& format) {
  return format == "obj" || format == "off" || format == "ply" || format == "stl";
}

Status read_named(std::string_view data, const std::string& format, std::string_view name, Mesh* mesh,
                  std::vector<std::string>* warnings) {
  if (mesh == nullptr) return invalid("read_mesh: mesh is null");
  Mesh parsed;
  WarningTally tally;
  Status status = parse_any(data, format, name, &parsed, &tally);
  if (!status.ok()) return status;
  *mesh = std::move(parsed);
  tally.append_to(warnings);
  return Status::Ok();
}

// Lower-case extension without the dot; empty if there is none.
std::string extension_of(const std::string& path) {
  size_t slash = path.find_last_of("/\\");
  size_t dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  return to_lower(std::string_view(path).substr(dot + 1));
}

Status read_file(const std::string& path, std::string* data) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return Status(ErrorCode::kIo, "cannot open " + path + ": " + std::strerror(errno));
  // One allocation for a regular file, rather than copying a big mesh file
  // each time the string grows.
  struct stat st;
  if (fstat(fileno(file), &st) == 0 && S_ISREG(st.st_mode)) data->reserve(size_t(st.st_size));
  char buffer[1 << 16];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) data->append(buffer, n);
  int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error != 0) return Status(ErrorCode::kIo, "cannot read " + path + ": " + std::strerror(error));
  return Status::Ok();
}

// ---------------------------------------------------------------------------
// Writers

// Text output, flushed to a file in pieces so huge meshes need no huge buffer.
class TextSink {
 public:
  explicit TextSink(std::FILE* file) : file_(file) {}

  void put(std::string_view text) {
    text_.append(text);
    if (file_ != nullptr && text_.size() >= kFlushBytes) flush();
  }
  void put_uint(uint64_t value) {
    char buffer[24];
    put(std::string_view(buffer, static_cast<size_t>(std::to_chars(buffer, buffer + sizeof buffer, value).ptr - buffer)));
  }
  // "%.9g" digits, the fewest that always round-trip a float; to_chars
  // ignores the C locale, which printf would not.
  void put_float(float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
    put(std::string_view(buffer, static_cast<size_t>(result.ptr - buffer)));
  }
  bool flush() {
    if (file_ != nullptr && !text_.empty()) {
      if (std::fwrite(text_.data(), 1, text_.size(), file_) != text_.size()) failed_ = true;
      text_.clear();
    }
    return !failed_;
  }
  std::string& text() { return text_; }

 private:
  static constexpr size_t kFlushBytes = 1 << 20;
  std::FILE* file_;
  std::string text_;
  bool failed_ = false;
};

// The attribute OBJ writes as vt (kind texture coordinate) or vn (normal), or null.
const MeshAttribute* obj_attribute(const Mesh& mesh, AttributeKind kind) {
  for (const MeshAttribute& a : mesh.attributes)
    if (a.kind == kind) return &a;
  return nullptr;
}

void put_value_lines(const MeshAttribute* a, const char* keyword, TextSink* out) {
  if (a == nullptr) return;
  for (size_t i = 0; i < a->value_count(); ++i) {
    out->put(keyword);
    for (uint32_t c = 0; c < a->components; ++c) {
      out->put(" ");
      out->put_float(a->values[a->components * i + c]);
    }
    out->put("\n");
  }
}

// Spec 15's attributes as PLY holds them: one value per vertex (every
// corner of a vertex refers to one value), or texcoords per corner.
bool one_value_per_vertex(const Mesh& mesh, const MeshAttribute& a, std::vector<uint32_t>* value_of) {
  value_of->assign(mesh.vertex_count(), UINT32_MAX);
  std::vector<uint8_t> referenced(a.value_count(), 0);
  for (size_t k = 0; k < mesh.corners.size(); ++k) {
    uint32_t& v = (*value_of)[mesh.corners[k]];
    if (v != UINT32_MAX && v != a.corner_values[k]) return false;
    v = a.corner_values[k];
    referenced[v] = 1;
  }
  // A vertex no face uses has the value of its own number when there is a
  // value a vertex (as the readers and spec 15.6's mapping 0 give them).
  if (a.value_count() == mesh.vertex_count())
    for (size_t v = 0; v < mesh.vertex_count(); ++v)
      if ((*value_of)[v] == UINT32_MAX && !referenced[v]) (*value_of)[v] = uint32_t(v);
  return true;
}

// The attribute OBJ writes on its v lines (r g b after x y z), or null: the
// first colour of 3 components with one value per vertex.
const MeshAttribute* obj_vertex_colour(const Mesh& mesh) {
  std::vector<uint32_t> value_of;
  for (const MeshAttribute& a : mesh.attributes)
    if (a.kind == AttributeKind::kColour && a.components == 3 && one_value_per_vertex(mesh, a, &value_of)) return &a;
  return nullptr;
}

// The OBJ statement of a face label (spec 16) the reader makes, or "".
const char* obj_keyword(const std::string& label) {
  if (label == "object") return "o";
  if (label == "group") return "g";
  if (label == "material") return "usemtl";
  if (label == "smoothing") return "s";
  return "";
}

// Corners as v, v/t, v//n or v/t/n (1-based); face labels as o, g, usemtl
// and s statements where they change, the material's files as mtllib.
void write_obj(const Mesh& mesh, TextSink* out) {
  for (const FaceLabels& l : mesh.face_labels)
    if (l.name == "material" && !l.references.empty()) {
      out->put("mtllib");
      for (const std::string& r : l.references) out->put(" " + r);
      out->put("\n");
    }
  const MeshAttribute* colour = obj_vertex_colour(mesh);
  std::vector<uint32_t> colour_of;
  if (colour) one_value_per_vertex(mesh, *colour, &colour_of);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    out->put("v");
    for (int axis = 0; axis < 3; ++axis) {
      out->put(" ");
      out->put_float(mesh.positions[3 * v + axis]);
    }
    // A vertex with no colour in the mesh (its value is not its own): 0 0 0, as in PLY.
    for (uint32_t c = 0; colour && c < 3; ++c) {
      out->put(" ");
      out->put_float(colour_of[v] == UINT32_MAX ? 0.f : colour->values[3 * size_t(colour_of[v]) + c]);
    }
    out->put("\n");
  }
  const MeshAttribute* texcoord = obj_attribute(mesh, AttributeKind::kTextureCoordinate);
  const MeshAttribute* normal = obj_attribute(mesh, AttributeKind::kNormal);
  put_value_lines(texcoord, "vt", out);
  put_value_lines(normal, "vn", out);
  std::vector<uint32_t> shown;  // per label, the value the last statement set
  for (const FaceLabels& l : mesh.face_labels) shown.push_back(l.none());
  size_t corner = 0;
  for (size_t f = 0; f < mesh.face_sizes.size(); ++f) {
    const uint32_t size = mesh.face_sizes[f];
    for (size_t j = 0; j < mesh.face_labels.size(); ++j) {
      const FaceLabels& l = mesh.face_labels[j];
      if (l.face_values[f] == shown[j]) continue;
      shown[j] = l.face_values[f];
      out->put(std::string(obj_keyword(l.name)) + (l.values[shown[j]].empty() ? "" : " ") + l.values[shown[j]] + "\n");
    }
    out->put("f");
    for (uint32_t i = 0; i < size; ++i, ++corner) {
      out->put(" ");
      out->put_uint(uint64_t{mesh.corners[corner]} + 1);
      if (texcoord || normal) out->put("/");
      if (texcoord) out->put_uint(uint64_t{texcoord->corner_values[corner]} + 1);
      if (normal) {
        out->put("/");
        out->put_uint(uint64_t{normal->corner_values[corner]} + 1);
      }
    }
    out->put("\n");
  }
}

void put_face_lines(const Mesh& mesh, TextSink* out) {
  size_t corner = 0;
  for (uint32_t size : mesh.face_sizes) {
    out->put_uint(size);
    for (uint32_t i = 0; i < size; ++i) {
      out->put(" ");
      out->put_uint(mesh.corners[corner++]);
    }
    out->put("\n");
  }
}

void write_off(const Mesh& mesh, TextSink* out) {
  out->put("OFF\n");
  out->put_uint(mesh.vertex_count());
  out->put(" ");
  out->put_uint(mesh.face_count());
  out->put(" 0\n");
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    out->put_float(mesh.positions[3 * v]);
    out->put(" ");
    out->put_float(mesh.positions[3 * v + 1]);
    out->put(" ");
    out->put_float(mesh.positions[3 * v + 2]);
    out->put("\n");
  }
  put_face_lines(mesh, out);
}


// The PLY properties of an attribute (names, in component order).
std::vector<const char*> ply_property_names(const MeshAttribute& a) {
  for (const auto& [names, what] : ply_attribute_names())
    if (a.name == what.first && a.kind == what.second && names.size() == a.components) return names;
  return {};
}

// Colours and alpha as uchar when their values go above 1 (read from uchar
// properties), else as float.
bool ply_uchar(const MeshAttribute& a) {
  if (a.kind != AttributeKind::kColour && a.name != "alpha") return false;
  for (float x : a.values)
    if (x > 1.5f) return true;
  return false;
}

// The values of PLY elements, as the header declares them: ASCII (a line
// per element, values separated by spaces) or binary_little_endian (each
// value in its type's bytes, least significant first, whatever the host).
class PlyValues {
 public:
  PlyValues(TextSink* out, bool binary) : out_(out), binary_(binary) {}
  void put_float(float x) {
    if (!binary_) return text_value().put_float(x);
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    put_little_endian(bits, 4);
  }
  // An integer of PLY type `type`: "uchar", "int" or "uint".
  void put_integer(uint64_t v, const char* type) {
    if (!binary_) return text_value().put_uint(v);
    put_little_endian(v, std::strcmp(type, "uchar") == 0 ? 1 : 4);
  }
  void end_element() {
    if (!binary_) out_->put("\n");
    first_ = true;
  }

 private:
  TextSink& text_value() {
    if (!first_) out_->put(" ");
    first_ = false;
    return *out_;
  }
  void put_little_endian(uint64_t v, int bytes) {
    char b[8];
    for (int i = 0; i < bytes; ++i) b[i] = char((v >> (8 * i)) & 0xFF);
    out_->put(std::string_view(b, size_t(bytes)));
  }

  TextSink* out_;
  bool binary_;
  bool first_ = true;
};

void write_ply(const Mesh& mesh, TextSink* out, bool binary) {
  uint32_t max_degree = 0;
  for (uint32_t size : mesh.face_sizes) max_degree = std::max(max_degree, size);
  // The narrowest common types that hold the data, so other tools read it.
  const char* count_type = max_degree <= 255 ? "uchar" : "uint";
  const char* index_type = mesh.vertex_count() <= uint64_t{INT32_MAX} ? "int" : "uint";
  const char* texcoord_count_type = max_degree <= 127 ? "uchar" : "uint";
  std::vector<std::pair<const MeshAttribute*, std::vector<uint32_t>>> per_vertex;
  const MeshAttribute* corner_texcoord = nullptr;
  for (const MeshAttribute& a : mesh.attributes) {
    std::vector<uint32_t> value_of;
    if (one_value_per_vertex(mesh, a, &value_of))
      per_vertex.emplace_back(&a, std::move(value_of));
    else
      corner_texcoord = &a;  // unwritable_parts let only texcoords through
  }
  out->put(binary ? "ply\nformat binary_little_endian 1.0\nelement vertex " : "ply\nformat ascii 1.0\nelement vertex ");
  out->put_uint(mesh.vertex_count());
  out->put("\nproperty float x\nproperty float y\nproperty float z\n");
  for (const auto& [a, value_of] : per_vertex)
    for (const char* name : ply_property_names(*a)) out->put(std::string("property ") + (ply_uchar(*a) ? "uchar " : "float ") + name + "\n");
  out->put("element face ");
  out->put_uint(mesh.face_count());
  out->put(std::string("\nproperty list ") + count_type + " " + index_type + " vertex_indices\n");
  if (corner_texcoord) out->put(std::string("property list ") + texcoord_count_type + " float texcoord\n");
  out->put("end_header\n");
  PlyValues values(out, binary);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) values.put_float(mesh.positions[3 * v + k]);
    for (const auto& [a, value_of] : per_vertex)
      for (uint32_t c = 0; c < a->components; ++c) {
        const float x = value_of[v] == UINT32_MAX ? 0.f : a->values[a->components * size_t(value_of[v]) + c];
        if (ply_uchar(*a))
          values.put_integer(uint64_t(std::clamp(std::lround(x), 0L, 255L)), "uchar");
        else
          values.put_float(x);
      }
    values.end_element();
  }
  size_t corner = 0;
  for (uint32_t size : mesh.face_sizes) {
    values.put_integer(size, count_type);
    for (uint32_t i = 0; i < size; ++i) values.put_integer(mesh.corners[corner + i], index_type);
    if (corner_texcoord) {
      values.put_integer(2 * uint64_t(size), texcoord_count_type);
      for (uint32_t i = 0; i < size; ++i)
        for (uint32_t c = 0; c < 2; ++c)
          values.put_float(corner_texcoord->values[2 * size_t(corner_texcoord->corner_values[corner + i]) + c]);
    }
    corner += size;
    values.end_element();
  }
}

// What the format cannot write is an error, never a silent loss: OBJ writes
// one texture-coordinate, one normal and one per-vertex colour attribute, PLY per-vertex normals,
// colours, alpha and texcoords (per corner too), OFF none. Empty if `a` fits.
std::string attribute_unwritable(const Mesh& mesh, const MeshAttribute& a, const std::string& format) {
  const bool obj_kind = a.kind == AttributeKind::kTextureCoordinate || a.kind == AttributeKind::kNormal;
  if (format == "obj" && ((obj_kind && obj_attribute(mesh, a.kind) == &a) || obj_vertex_colour(mesh) == &a)) return "";
  std::vector<uint32_t> value_of;
  if (format == "ply" && !ply_property_names(a).empty() &&
      (one_value_per_vertex(mesh, a, &value_of) || (a.kind == AttributeKind::kTextureCoordinate && a.components == 2)))
    return "";
  return "the mesh has attribute \"" + a.name + "\", which ." + format +
         (format == "obj"   ? " cannot hold besides the first texture coordinates, normals and vertex colours"
          : format == "ply" ? " cannot hold (PLY holds normals, colours and alpha one per vertex, texture coordinates per vertex or per corner)"
                            : " output cannot hold; write .obj, .ply or .qmc");
}

// OBJ writes the labels it reads (o, g, usemtl, s), as long as no face goes
// back to having none after a face with one (OBJ has no statement for it).
// Empty if `l` fits.
std::string labels_unwritable(const FaceLabels& l, const std::string& format) {
  if (format != "obj" || *obj_keyword(l.name) == '\0')
    return "the mesh has face labels \"" + l.name + "\", which ." + format +
           " output cannot hold; write .obj (object, group, material, smoothing) or .qmc";
  bool labelled = false;
  for (uint32_t v : l.face_values) {
    if (labelled && v == l.none())
      return "face labels \"" + l.name + "\": a face without one after faces with one, which .obj cannot say";
    labelled = labelled || v != l.none();
  }
  return "";
}

Status check_parts_fit(const Mesh& mesh, const std::string& format) {
  const std::vector<UnwritablePart> parts = unwritable_parts(mesh, format);
  return parts.empty() ? Status::Ok() : invalid(parts.front().reason);
}

// Writing a mesh we could not read back would only move the failure later.
Status validate_for_writing(const Mesh& mesh) {
  if (mesh.positions.size() % 3 != 0) return invalid("mesh positions are not a multiple of 3 floats");
  for (float value : mesh.positions) {
    if (!std::isfinite(value)) return invalid("mesh has a non-finite coordinate");
  }
  uint64_t corners = 0;
  for (uint32_t size : mesh.face_sizes) {
    if (size < 3) return invalid("mesh has a face with fewer than 3 corners");
    corners += size;
  }
  if (corners != mesh.corners.size()) return invalid("mesh face sizes do not add up to its corner count");
  for (uint32_t index : mesh.corners) {
    if (index >= mesh.vertex_count()) return invalid("mesh has a corner index out of range");
  }
  return Status::Ok();
}

bool is_writable_format(const std::string& format) { return format == "obj" || format == "off" || format == "ply"; }

void write_any(const Mesh& mesh, const std::string& format, const MeshWriteOptions& options, TextSink* out) {
  if (format == "obj") {
    write_obj(mesh, out);
  } else if (format == "off") {
    write_off(mesh, out);
  } else {
    write_ply(mesh, out, options.binary_ply);
  }
}

}  // namespace

Status read_mesh(const std::string& path, Mesh* mesh, std::vector<std::string>* warnings) {
  std::string format = extension_of(path);
  if (!is_readable_format(format)) {
    return invalid(path + ": unsupported extension (expected .obj, .off, .ply or .stl)");
  }
  std::string data;
  Status status = read_file(path, &data);
  if (!status.ok()) return status;
  return read_named(data, format, path, mesh, warnings);
}

Status read_mesh_from_memory(std::string_view text_or_bytes, std::string_view format, Mesh* mesh,
                             std::vector<std::string>* warnings) {
  std::string lowered = to_lower(format);
  if (!is_readable_format(lowered)) {
    return invalid("unsupported format " + quoted(format) + " (expected obj, off, ply or stl)");
  }
  return read_named(text_or_bytes, lowered, "<" + lowered + " data>", mesh, warnings);
}

std::string mesh_format_of(const std::string& path) { return extension_of(path); }

std::vector<UnwritablePart> unwritable_parts(const Mesh& mesh, std::string_view format) {
  const std::string lowered = to_lower(format);
  std::vector<UnwritablePart> parts;
  if (!is_writable_format(lowered)) return parts;
  for (const MeshAttribute& a : mesh.attributes)
    if (std::string reason = attribute_unwritable(mesh, a, lowered); !reason.empty()) parts.push_back({a.name, reason});
  for (const FaceLabels& l : mesh.face_labels)
    if (std::string reason = labels_unwritable(l, lowered); !reason.empty()) parts.push_back({l.name, reason});
  return parts;
}

Status write_mesh_to_memory(const Mesh& mesh, std::string_view format, std::string* text,
                            const MeshWriteOptions& options) {
  std::string lowered = to_lower(format);
  if (!is_writable_format(lowered)) return invalid("cannot write format " + quoted(format) + " (expected obj, off or ply)");
  if (text == nullptr) return invalid("write_mesh_to_memory: text is null");
  Status status = validate_for_writing(mesh);
  if (status.ok()) status = check_parts_fit(mesh, lowered);
  if (!status.ok()) return status;
  TextSink sink(nullptr);
  write_any(mesh, lowered, options, &sink);
  *text = std::move(sink.text());
  return Status::Ok();
}

Status write_mesh(const std::string& path, const Mesh& mesh, const MeshWriteOptions& options) {
  std::string format = extension_of(path);
  if (!is_writable_format(format)) return invalid(path + ": cannot write this extension (expected .obj, .off or .ply)");
  Status status = validate_for_writing(mesh);
  if (status.ok()) status = check_parts_fit(mesh, format);
  if (!status.ok()) return Status(status.code(), path + ": " + status.message());
  return write_file_atomically(path, [&](std::FILE* file) {
    TextSink sink(file);
    write_any(mesh, format, options, &sink);
    return sink.flush();
  });
}

}  // namespace qmc::tools
