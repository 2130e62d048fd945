#include "scene/ply_check.h"

#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "core/error.h"

namespace penumbra {
namespace {

// A header longer than this is not a mesh header (real ones are a few hundred bytes); without
// a bound, a file with no end_header would be scanned as one.
constexpr size_t kMaxHeaderBytes = size_t(1) << 20;
// PLY counts are 32-bit in assimp; our indices are 32-bit too.
constexpr uint64_t kMaxElementCount = std::numeric_limits<int32_t>::max();

enum class Format { Ascii, BinaryLittle, BinaryBig };

struct Property {
  std::string name;
  int size = 0;  // bytes of the value (binary); 0 never
  bool is_float = false;
  bool is_signed = false;
  bool is_list = false;
  int count_size = 0;  // lists: bytes of the count
  bool count_signed = false;
  bool count_float = false;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct ScalarType {
  const char* name;
  int size;
  bool is_float;
  bool is_signed;
};

constexpr ScalarType kScalarTypes[] = {
    {"char", 1, false, true},    {"int8", 1, false, true},    {"uchar", 1, false, false},
    {"uint8", 1, false, false},  {"short", 2, false, true},   {"int16", 2, false, true},
    {"ushort", 2, false, false}, {"uint16", 2, false, false}, {"int", 4, false, true},
    {"int32", 4, false, true},   {"uint", 4, false, false},   {"uint32", 4, false, false},
    {"float", 4, true, true},    {"float32", 4, true, true},  {"double", 8, true, true},
    {"float64", 8, true, true},
};

const ScalarType* findType(std::string_view name) {
  for (const ScalarType& t : kScalarTypes) {
    if (name == t.name) return &t;
  }
  return nullptr;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

bool parseUnsigned(std::string_view text, uint64_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

// Face lists index the vertex element; triangle strips use -1 to restart a strip.
bool isIndexList(const Element& element, const Property& property) {
  if (!property.is_list) return false;
  if (property.name != "vertex_indices" && property.name != "vertex_index") return false;
  return element.name == "face" || element.name == "tristrips";
}

class PlyChecker {
 public:
  PlyChecker(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

  void run() {
    readHeader();
    checkUnknownElementsComeLast();
    for (const Element& e : elements_) {
      if (e.name == "vertex") vertex_count_ = e.count;
    }
    if (format_ == Format::Ascii) {
      walkAscii();
    } else {
      walkBinary();
    }
  }

 private:
  template <typename... Args>
  [[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) const {
    throw Error(fmt::format("{}: invalid PLY: {}", path_,
                            fmt::format(format, std::forward<Args>(args)...)));
  }

  void readHeader() {
    size_t pos = 0;
    int line_number = 0;
    bool have_format = false;
    bool first = true;
    while (true) {
      const std::vector<std::string_view> words = splitWords(nextHeaderLine(pos, line_number));
      if (first) {
        if (words.size() != 1 || words[0] != "ply") fail("the file does not start with 'ply'");
        first = false;
        continue;
      }
      if (words.empty()) fail("header line {} is empty", line_number);
      const std::string_view keyword = words[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") {
        if (words.size() != 1) fail("header line {}: text after end_header", line_number);
        if (!have_format) fail("the header has no format line");
        body_ = pos;
        return;
      }
      if (keyword == "format") {
        if (have_format) fail("header line {}: a second format line", line_number);
        readFormat(words, line_number);
        have_format = true;
        continue;
      }
      if (keyword == "element") {
        if (!have_format) fail("header line {}: element before the format line", line_number);
        readElement(words, line_number);
        continue;
      }
      if (keyword == "property") {
        if (elements_.empty()) fail("header line {}: property before any element", line_number);
        elements_.back().properties.push_back(readProperty(words, line_number));
        continue;
      }
      fail("header line {}: unknown keyword '{}'", line_number, keyword);
    }
  }

  // The header line from `pos` (then moved past it), numbered `line_number` (then counted).
  std::string_view nextHeaderLine(size_t& pos, int& line_number) const {
    if (pos >= bytes_.size() || pos > kMaxHeaderBytes) {
      fail("the header has no end_header line{}",
           pos > kMaxHeaderBytes ? fmt::format(" in its first {} bytes", kMaxHeaderBytes)
                                 : std::string(" (the file ends first)"));
    }
    const size_t end = bytes_.find('\n', pos);
    if (end == std::string_view::npos) {
      fail("the header has no end_header line (the file ends first)");
    }
    const std::string_view line = bytes_.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    // assimp stops reading a header line at a NUL and reads other control bytes as part of
    // a word: refuse them rather than disagree with it about what the header says.
    for (char c : line) {
      const auto u = static_cast<unsigned char>(c);
      if ((u < 0x20 && c != '\t' && c != '\r') || u == 0x7f) {
        fail("header line {} holds the control byte 0x{:02x}", line_number, unsigned(u));
      }
    }
    return line;
  }

  // "format TYPE 1.0".
  void readFormat(const std::vector<std::string_view>& words, int line_number) {
    if (words.size() != 3) fail("header line {}: expected 'format TYPE 1.0'", line_number);
    if (words[1] == "ascii") {
      format_ = Format::Ascii;
    } else if (words[1] == "binary_little_endian") {
      format_ = Format::BinaryLittle;
    } else if (words[1] == "binary_big_endian") {
      format_ = Format::BinaryBig;
    } else {
      fail("header line {}: unknown format '{}'", line_number, words[1]);
    }
  }

  // "element NAME COUNT".
  void readElement(const std::vector<std::string_view>& words, int line_number) {
    uint64_t count = 0;
    if (words.size() != 3 || !parseUnsigned(words[2], count)) {
      fail("header line {}: expected 'element NAME COUNT' with COUNT >= 0", line_number);
    }
    if (count > kMaxElementCount) {
      fail("header line {}: element '{}' declares {} items (the limit is {})", line_number,
           words[1], count, kMaxElementCount);
    }
    if (std::isdigit(static_cast<unsigned char>(words[1][0]))) {
      // assimp 5.2 reads the count of an element whose name it does not know from the
      // name itself: "element 66face 2" would be 66 items to it (or billions, and an
      // allocation of that size).
      fail("header line {}: element name '{}' starts with a digit", line_number, words[1]);
    }
    elements_.push_back(Element{std::string(words[1]), count, {}});
  }

  // assimp 5.2 takes the count of an element whose name it does not know (anything but
  // vertex, face, tristrips, edge and material) as 0 and reads its items as the next element's.
  // Harmless at the end of the file (Stanford's range_grid), a misread mesh before the
  // geometry: refuse it there.
  void checkUnknownElementsComeLast() const {
    const auto known = [](const std::string& name) {
      return name == "vertex" || name == "face" || name == "tristrips" || name == "edge" ||
             name == "material";
    };
    const auto geometry = [](const std::string& name) {
      return name == "vertex" || name == "face" || name == "tristrips";
    };
    for (size_t i = 0; i < elements_.size(); ++i) {
      const Element& e = elements_[i];
      if (known(e.name) || e.count == 0) continue;
      for (size_t j = i + 1; j < elements_.size(); ++j) {
        if (geometry(elements_[j].name)) {
          fail(
              "element '{}' ({} items) comes before the '{}' element: assimp 5.2 does not know "
              "the name and would read its items as the next element's",
              e.name, e.count, elements_[j].name);
        }
      }
    }
  }

  Property readProperty(const std::vector<std::string_view>& words, int line_number) const {
    Property p;
    if (words.size() == 5 && words[1] == "list") {
      const ScalarType* count = findType(words[2]);
      const ScalarType* value = findType(words[3]);
      if (!count || !value) fail("header line {}: unknown type in a list property", line_number);
      if (count->is_float)
        fail("header line {}: a list count must be an integer type", line_number);
      p.is_list = true;
      p.count_size = count->size;
      p.count_signed = count->is_signed;
      p.size = value->size;
      p.is_float = value->is_float;
      p.is_signed = value->is_signed;
      p.name = std::string(words[4]);
      return p;
    }
    if (words.size() != 3) {
      fail(
          "header line {}: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE "
          "NAME'",
          line_number);
    }
    const ScalarType* type = findType(words[1]);
    if (!type) fail("header line {}: unknown property type '{}'", line_number, words[1]);
    p.size = type->size;
    p.is_float = type->is_float;
    p.is_signed = type->is_signed;
    p.name = std::string(words[2]);
    return p;
  }

  // The value of one binary scalar at `at` (bounds checked by the caller), as a double: exact
  // for every integer type PLY has.
  double binaryValue(size_t at, int size, bool is_float, bool is_signed) const {
    uint8_t raw[8];
    std::memcpy(raw, bytes_.data() + at, size_t(size));
    const bool swap = (format_ == Format::BinaryBig) != (std::endian::native == std::endian::big);
    if (swap) {
      for (int i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    }
    if (is_float) {
      if (size == 4) {
        float f;
        std::memcpy(&f, raw, 4);
        return f;
      }
      double d;
      std::memcpy(&d, raw, 8);
      return d;
    }
    uint64_t u = 0;
    std::memcpy(&u, raw, size_t(size));  // little-endian host after the swap
    if (is_signed && size < 8 && (u >> (size * 8 - 1)) != 0) {
      return double(int64_t(u | (~uint64_t(0) << (size * 8))));
    }
    return double(u);
  }

  void checkListCount(const Element& e, const Property& p, uint64_t item, double count) const {
    if (!(count >= 0.0)) {
      fail("element '{}' item {}: list '{}' has a negative length ({})", e.name, item, p.name,
           count);
    }
    if (isIndexList(e, p) && e.name == "face" && count < 3.0) {
      fail("face {} has {} vertex indices (a face needs at least 3)", item, count);
    }
  }

  void checkIndex(const Element& e, uint64_t item, double index) const {
    const double lowest = e.name == "tristrips" ? -1.0 : 0.0;
    if (!(index >= lowest && index < double(vertex_count_)) || index != double(int64_t(index))) {
      fail("{} {}: vertex index {} is out of range (the file has {} vertices)", e.name, item, index,
           vertex_count_);
    }
  }

  [[noreturn]] void cutOff(const Element& e, uint64_t item) const {
    fail(
        "the body is cut off: element '{}' item {} of {} ends past the end of the file "
        "({} bytes)",
        e.name, item, e.count, bytes_.size());
  }

  void walkBinary() const {
    size_t at = body_;
    // assimp's header reader takes a line end right after end_header's as part of the header
    // and starts the body one byte late, misreading every value (and reading past the end).
    if (at < bytes_.size() && (bytes_[at] == '\n' || bytes_[at] == '\r')) {
      fail(
          "the binary body starts with a line-end byte (0x{:02x}), which assimp 5.2 skips as "
          "part of the header: it would misread every value after it",
          unsigned(static_cast<unsigned char>(bytes_[at])));
    }
    for (const Element& e : elements_) {
      if (e.count > 0 && e.properties.empty()) fail("element '{}' has no properties", e.name);
      for (uint64_t item = 0; item < e.count; ++item) {
        for (const Property& p : e.properties) {
          if (!p.is_list) {
            if (bytes_.size() - at < size_t(p.size)) cutOff(e, item);
            at += size_t(p.size);
            continue;
          }
          if (bytes_.size() - at < size_t(p.count_size)) cutOff(e, item);
          const double count = binaryValue(at, p.count_size, false, p.count_signed);
          at += size_t(p.count_size);
          checkListCount(e, p, item, count);
          if (double(bytes_.size() - at) < count * double(p.size)) cutOff(e, item);
          const size_t n = size_t(count);
          if (isIndexList(e, p)) {
            for (size_t k = 0; k < n; ++k) {
              checkIndex(e, item,
                         binaryValue(at + k * size_t(p.size), p.size, p.is_float, p.is_signed));
            }
          }
          at += n * size_t(p.size);
        }
      }
    }
    for (size_t i = at; i < bytes_.size(); ++i) {
      if (!std::isspace(static_cast<unsigned char>(bytes_[i]))) {
        fail("{} bytes follow the last element the header declares", bytes_.size() - at);
      }
    }
  }

  // Next non-blank line's words, or false at the end of the file.
  bool nextAsciiLine(size_t& at, std::vector<std::string_view>& words) const {
    while (at < bytes_.size()) {
      size_t end = bytes_.find('\n', at);
      if (end == std::string_view::npos) end = bytes_.size();
      words = splitWords(bytes_.substr(at, end - at));
      at = end + 1;
      if (!words.empty()) return true;
    }
    return false;
  }

  double asciiNumber(const Element& e, uint64_t item, std::string_view word) const {
    const std::string text(word);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) {
      fail("element '{}' item {}: '{}' is not a number", e.name, item, word);
    }
    return value;
  }

  // One item per line, as assimp reads them: a line with too few or too many values means the
  // header and the body disagree.
  void walkAscii() const {
    size_t at = body_;
    std::vector<std::string_view> words;
    for (const Element& e : elements_) {
      for (uint64_t item = 0; item < e.count; ++item) {
        if (!nextAsciiLine(at, words)) {
          fail("the body is cut off: element '{}' has {} of the {} items the header declares",
               e.name, item, e.count);
        }
        size_t w = 0;
        for (const Property& p : e.properties) {
          if (w >= words.size()) fail("element '{}' item {}: too few values", e.name, item);
          const double value = asciiNumber(e, item, words[w++]);
          if (!p.is_list) continue;
          checkListCount(e, p, item, value);
          if (value > double(words.size() - w)) {
            fail("element '{}' item {}: list '{}' declares {} values, the line holds {}", e.name,
                 item, p.name, value, words.size() - w);
          }
          if (value != double(int64_t(value))) {  // in range: checked above
            fail("element '{}' item {}: list length '{}' is not an integer", e.name, item,
                 words[w - 1]);
          }
          for (size_t k = 0; k < size_t(value); ++k) {
            const double v = asciiNumber(e, item, words[w++]);
            if (isIndexList(e, p)) checkIndex(e, item, v);
          }
        }
        if (w != words.size()) {
          fail("element '{}' item {}: {} values more than its properties declare", e.name, item,
               words.size() - w);
        }
      }
    }
    if (nextAsciiLine(at, words)) fail("the body holds more lines than the header declares");
  }

  const std::string& path_;
  std::string_view bytes_;
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  uint64_t vertex_count_ = 0;
  size_t body_ = 0;
};

}  // namespace

void checkPlyBytes(const std::string& path, std::string_view bytes) {
  PlyChecker(path, bytes).run();
}

}  // namespace penumbra
