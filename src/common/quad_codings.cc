// Codings of seed 001 chapter 4 (tables 4-2, 4-6, 4-8), the plain 4-bit
// code of its section 4.1, and the Huffman coding of spec 5.3.5.
#include "common/quad_codings.h"

#include <string>

#include "common/huffman.h"

namespace qmc {
namespace {

struct TableRow {
  uint8_t type;
  uint8_t next;  // QuadClass
  const char* code;
};

// Rows per coding, for the context of the current quad's class. "A" rows
// are the seed's "Quad started with Q1-5", "B" rows "started with Q6-13".
constexpr TableRow kCodingIA[] = {{1, 0, "00"},   {1, 1, "01"},   {2, 0, "1100"}, {2, 1, "1101"}, {3, 0, "1010"},
                                  {3, 1, "1011"}, {4, 0, "1000"}, {4, 1, "1001"}, {5, 1, "111"}};
constexpr TableRow kCodingIB[] = {{6, 0, "1010"},    {6, 1, "1011"},    {7, 0, "111100"}, {7, 1, "111101"},
                                  {8, 0, "111010"},  {8, 1, "111011"},  {9, 0, "111110"}, {9, 1, "111111"},
                                  {10, 1, "11100"},  {11, 0, "1100"},   {11, 1, "1101"},  {12, 1, "100"},
                                  {13, 1, "0"}};
constexpr TableRow kCodingIIB[] = {{6, 0, "1010"},   {6, 1, "1011"},   {7, 0, "111100"}, {7, 1, "111101"},
                                   {8, 0, "111010"}, {8, 1, "111011"}, {9, 0, "111110"}, {9, 1, "111111"},
                                   {10, 1, "1100"},  {11, 0, "11100"}, {11, 1, "1101"},  {12, 1, "100"},
                                   {13, 1, "0"}};
constexpr TableRow kCodingIIIA[] = {{1, 0, "000"},  {1, 1, "111"},  {2, 0, "1100"}, {2, 1, "1101"}, {3, 0, "001"},
                                    {3, 1, "101"},  {4, 0, "1000"}, {4, 1, "1001"}, {5, 1, "01"}};
constexpr TableRow kCodingIIIB[] = {{6, 0, "1010"},   {6, 1, "1011"},   {7, 0, "10010"},  {7, 1, "10011"},
                                    {8, 0, "111110"}, {8, 1, "111111"}, {9, 0, "11100"},  {9, 1, "11101"},
                                    {10, 1, "1000"},  {11, 0, "1100"},  {11, 1, "1101"},  {12, 1, "01"},
                                    {13, 1, "00"}};

struct RowSpan {
  const TableRow* rows;
  size_t count;
};

RowSpan rows_of(QuadCoding coding, QuadClass context) {
  const bool a = context == QuadClass::kA;
  switch (coding) {
    case QuadCoding::kCodingI: return a ? RowSpan{kCodingIA, std::size(kCodingIA)} : RowSpan{kCodingIB, std::size(kCodingIB)};
    case QuadCoding::kCodingII: return a ? RowSpan{kCodingIA, std::size(kCodingIA)} : RowSpan{kCodingIIB, std::size(kCodingIIB)};
    case QuadCoding::kCodingIII:
      return a ? RowSpan{kCodingIIIA, std::size(kCodingIIIA)} : RowSpan{kCodingIIIB, std::size(kCodingIIIB)};
    default: return {nullptr, 0};
  }
}

constexpr int kMaxFixedLength = 6;

// 6-bit lookup of a fixed table: the code word that starts with those bits.
struct FixedLookup {
  struct Entry {
    uint8_t type = 0, next = 0, length = 0;
  };
  Entry entries[1 << kMaxFixedLength];
};

// A row's code word, read from its string of '0' and '1'.
QuadCodeWord code_word_of(const TableRow& row) {
  QuadCodeWord w;
  for (const char* c = row.code; *c; ++c) w.bits = uint8_t((w.bits << 1) | (*c == '1'));
  w.length = uint8_t(std::char_traits<char>::length(row.code));
  return w;
}

FixedLookup build_lookup(RowSpan span) {
  FixedLookup lookup;
  for (size_t r = 0; r < span.count; ++r) {
    const QuadCodeWord w = code_word_of(span.rows[r]);
    const int shift = kMaxFixedLength - int(w.length);
    for (uint32_t i = 0; i < (1u << shift); ++i)
      lookup.entries[(uint32_t(w.bits) << shift) | i] = {span.rows[r].type, span.rows[r].next, w.length};
  }
  return lookup;
}

const FixedLookup& lookup_of(QuadCoding coding, QuadClass context) {
  static const FixedLookup tables[3][2] = {
      {build_lookup(rows_of(QuadCoding::kCodingI, QuadClass::kA)), build_lookup(rows_of(QuadCoding::kCodingI, QuadClass::kB))},
      {build_lookup(rows_of(QuadCoding::kCodingII, QuadClass::kA)), build_lookup(rows_of(QuadCoding::kCodingII, QuadClass::kB))},
      {build_lookup(rows_of(QuadCoding::kCodingIII, QuadClass::kA)),
       build_lookup(rows_of(QuadCoding::kCodingIII, QuadClass::kB))}};
  return tables[int(coding) - 1][int(context)];
}

// The code words of a fixed table by (type, next class), so that a stream
// is written and measured without reading the table's strings per quad.
struct FixedWords {
  QuadCodeWord word[kQuadTypeCount + 1][2];
};

FixedWords build_words(QuadCoding coding) {
  FixedWords words;
  for (QuadClass context : {QuadClass::kA, QuadClass::kB}) {
    const RowSpan span = rows_of(coding, context);
    for (size_t r = 0; r < span.count; ++r)
      words.word[span.rows[r].type][span.rows[r].next] = code_word_of(span.rows[r]);
  }
  return words;
}

const FixedWords& words_of(QuadCoding coding) {
  static const FixedWords tables[3] = {build_words(QuadCoding::kCodingI), build_words(QuadCoding::kCodingII),
                                       build_words(QuadCoding::kCodingIII)};
  return tables[int(coding) - 1];
}

QuadClass next_class(const std::vector<uint8_t>& types, size_t i) {
  // The last quad announces class B (spec 5.3.2): every type has such a code word.
  return i + 1 < types.size() ? quad_class(types[i + 1]) : QuadClass::kB;
}

bool is_fixed(QuadCoding coding) {
  return coding == QuadCoding::kCodingI || coding == QuadCoding::kCodingII || coding == QuadCoding::kCodingIII;
}

// Per-context Huffman code lengths for the (type, next class) pairs.
std::array<std::vector<uint8_t>, 2> huffman_lengths(const std::vector<uint8_t>& types) {
  std::array<std::vector<uint64_t>, 2> freq{std::vector<uint64_t>(quad_pair_alphabet(QuadClass::kA), 0),
                                            std::vector<uint64_t>(quad_pair_alphabet(QuadClass::kB), 0)};
  for (size_t i = 0; i < types.size(); ++i)
    ++freq[int(quad_class(types[i]))][quad_pair_symbol(types[i], next_class(types, i))];
  return {huffman_code_lengths(freq[0]), huffman_code_lengths(freq[1])};
}

bool any_used(const std::vector<uint8_t>& lengths) {
  for (uint8_t l : lengths)
    if (l) return true;
  return false;
}

}  // namespace

const char* quad_coding_name(QuadCoding coding) {
  switch (coding) {
    case QuadCoding::kPlain4: return "plain 4-bit";
    case QuadCoding::kCodingI: return "Coding I";
    case QuadCoding::kCodingII: return "Coding II";
    case QuadCoding::kCodingIII: return "Coding III";
    case QuadCoding::kHuffman: return "Huffman";
  }
  return "unknown";
}

QuadCodeWord fixed_code_word(QuadCoding coding, int type, QuadClass next) {
  if (!is_fixed(coding) || type < 1 || type > kQuadTypeCount) return {};
  return words_of(coding).word[type][int(next)];
}

int read_fixed_code_word(QuadCoding coding, QuadClass current, BitReader* reader, QuadClass* next) {
  const FixedLookup& lookup = lookup_of(coding, current);
  const FixedLookup::Entry e = lookup.entries[reader->peek_bits(kMaxFixedLength)];
  const uint64_t left = reader->bits_remaining();
  if (e.length == 0) {
    // No code word starts with these bits, unless the stream ended before all
    // 6 were there: then a longer code word may have been cut (truncation).
    if (left >= kMaxFixedLength) return 0;
    const int free_bits = kMaxFixedLength - int(left);
    const uint32_t prefix = reader->peek_bits(int(left)) << free_bits;
    for (uint32_t s = 0; s < (1u << free_bits); ++s)
      if (lookup.entries[prefix | s].length > 0) return -1;
    return 0;
  }
  if (left < e.length) return -1;
  reader->skip_bits(e.length);
  *next = QuadClass(e.next);
  return e.type;
}

uint32_t quad_pair_alphabet(QuadClass context) { return context == QuadClass::kA ? 10 : 16; }

uint32_t quad_pair_symbol(int type, QuadClass next) {
  const int first = quad_class(type) == QuadClass::kA ? 1 : 6;
  return uint32_t(type - first) * 2 + uint32_t(next);
}

int quad_pair_type(QuadClass context, uint32_t symbol, QuadClass* next) {
  *next = QuadClass(symbol & 1);
  return int(symbol / 2) + (context == QuadClass::kA ? 1 : 6);
}

void write_quad_stream(QuadCoding coding, const std::vector<uint8_t>& types, BitWriter* writer) {
  if (coding == QuadCoding::kPlain4) {
    for (uint8_t t : types) writer->write_bits(uint32_t(t - 1), 4);
    return;
  }
  std::array<std::vector<uint8_t>, 2> lengths;
  if (coding == QuadCoding::kHuffman) {
    lengths = huffman_lengths(types);
    for (const std::vector<uint8_t>& l : lengths) {
      writer->write_bit(any_used(l));
      if (any_used(l)) write_code_lengths(writer, l);
    }
  }
  writer->write_bit(!types.empty() && quad_class(types[0]) == QuadClass::kB);
  const HuffmanEncoder huffman[2] = {HuffmanEncoder(lengths[0]), HuffmanEncoder(lengths[1])};
  for (size_t i = 0; i < types.size(); ++i) {
    const QuadClass next = next_class(types, i);
    if (coding == QuadCoding::kHuffman) {
      huffman[int(quad_class(types[i]))].write(writer, quad_pair_symbol(types[i], next));
    } else {
      const QuadCodeWord w = words_of(coding).word[types[i]][int(next)];
      writer->write_bits(w.bits, w.length);
    }
  }
}

int64_t quad_stream_bits(QuadCoding coding, const std::vector<uint8_t>& types) {
  if (!is_fixed(coding)) {
    BitWriter writer;
    write_quad_stream(coding, types, &writer);
    return int64_t(writer.bit_count());
  }
  // What write_quad_stream writes: the first quad's class, then a code word
  // per quad, counted by (type, next class).
  uint64_t count[kQuadTypeCount + 1][2] = {};
  for (size_t i = 0; i < types.size(); ++i) ++count[types[i]][int(next_class(types, i))];
  int64_t bits = 1;
  for (int type = 1; type <= kQuadTypeCount; ++type)
    for (int next = 0; next < 2; ++next) {
      if (count[type][next] == 0) continue;
      const uint8_t length = words_of(coding).word[type][next].length;
      if (length == 0) return -1;
      bits += int64_t(count[type][next]) * length;
    }
  return bits;
}

Status read_quad_stream(QuadCoding coding, uint32_t count, BitReader* reader, std::vector<uint8_t>* types) {
  types->clear();
  types->reserve(count);
  auto truncated = [] { return Status(ErrorCode::kTruncated, "CONN: interaction codes end early"); };
  if (coding == QuadCoding::kPlain4) {
    for (uint32_t i = 0; i < count; ++i) {
      const uint32_t v = reader->read_bits(4);
      if (reader->overrun()) return truncated();
      if (v > 12) return Status(ErrorCode::kBadSymbol, "CONN: plain code " + std::to_string(v) + " is no Q-type");
      types->push_back(uint8_t(v + 1));
    }
    return Status::Ok();
  }
  HuffmanDecoder huffman[2];
  bool present[2] = {false, false};
  if (coding == QuadCoding::kHuffman) {
    for (int c = 0; c < 2; ++c) {
      present[c] = reader->read_bit();
      if (present[c])
        if (Status s = read_table(reader, quad_pair_alphabet(QuadClass(c)), &huffman[c]); !s.ok()) return s;
    }
  }
  QuadClass current = QuadClass(reader->read_bit());
  if (reader->overrun()) return truncated();
  for (uint32_t i = 0; i < count; ++i) {
    QuadClass next = QuadClass::kB;
    int type = 0;
    if (coding == QuadCoding::kHuffman) {
      if (!present[int(current)])
        return Status(ErrorCode::kBadSymbol, "CONN: a quad of a class whose Huffman table is absent");
      const int symbol = huffman[int(current)].decode(reader);
      if (reader->overrun()) return truncated();
      if (symbol < 0) return Status(ErrorCode::kBadSymbol, "CONN: invalid interaction code word");
      type = quad_pair_type(current, uint32_t(symbol), &next);
    } else {
      type = read_fixed_code_word(coding, current, reader, &next);
      if (type < 0) return truncated();
      if (type == 0) return Status(ErrorCode::kBadSymbol, "CONN: bits that are no code word of the coding");
    }
    types->push_back(uint8_t(type));
    current = next;
  }
  if (count > 0 && current != QuadClass::kB)
    return Status(ErrorCode::kBadSymbol, "CONN: the last interaction announces a following Q1-Q5");
  return Status::Ok();
}

}  // namespace qmc
