// The .msh reader (MshReader.hpp). gmsh's own reader trusts the counts of a file (a $NodeData
// count of 1e9 in a 40 kB file allocated 6 GB; a header count one below the data aborted in a
// double free): here every count is checked against the bytes that remain before it sizes
// anything, and the groups are assembled exactly as the gmsh API returned them (GmshMesh.cpp
// currentMesh): physical groups by dimension then tag, their entities by ascending tag, within
// an entity triangles before quadrangles, in file order.
#include "MshReader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <unordered_map>

#include "ElementShape.hpp"
#include "MeshError.hpp"
#include "io/InputFile.hpp"

namespace chute::mesh {

namespace {

constexpr double kMaxCoordinate = 1e100;  // as the case reader: squared distances stay finite

// Nodes per element of gmsh's element types (gmsh's table, first to fifth order); 0: unknown.
int nodesPerElement(int type) {
  static const std::map<int, int> kNodes = {
      {1, 2},   {2, 3},   {3, 4},   {4, 4},   {5, 8},   {6, 6},   {7, 5},   {8, 3},   {9, 6},
      {10, 9},  {11, 10}, {12, 27}, {13, 18}, {14, 14}, {15, 1},  {16, 8},  {17, 20}, {18, 15},
      {19, 13}, {20, 9},  {21, 10}, {22, 12}, {23, 15}, {24, 15}, {25, 21}, {26, 4},  {27, 5},
      {28, 6},  {29, 20}, {30, 35}, {31, 56}, {92, 64}, {93, 125}};
  const auto it = kNodes.find(type);
  return it == kNodes.end() ? 0 : it->second;
}

int dimOfType(int type) {
  switch (type) {
    case 15:
      return 0;
    case 1:
    case 8:
    case 26:
    case 27:
    case 28:
      return 1;
    case 2:
    case 3:
    case 9:
    case 10:
    case 16:
    case 20:
    case 21:
    case 22:
    case 23:
    case 24:
    case 25:
      return 2;
    default:
      return 3;
  }
}

bool supportedType(int type) {
  return type == 15 || type == 1 || type == 2 || type == 3;
}

std::string clip(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& ch : out)
    if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
  return s.size() > 40 ? out + "..." : out;
}

// A position in the file: ASCII tokens (with the line counted) and little-endian binary values,
// every read bounded by the end of the data.
class Cursor {
 public:
  Cursor(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& why) const {
    throw MeshError(name_ + ":" + std::to_string(line_) + ": " + why +
                    (binary_ ? " (binary data, byte " + std::to_string(pos_) + ")" : ""));
  }
  const std::string& name() const { return name_; }
  long line() const { return line_; }
  bool binary() const { return binary_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  void setBinary(bool b) { binary_ = b; }

  void skipSpace() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) {
      if (data_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  bool atEnd() {
    skipSpace();
    return pos_ == data_.size();
  }
  std::string_view token(const std::string& what) {
    skipSpace();
    if (pos_ == data_.size()) fail(what + ": unexpected end of file");
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    return data_.substr(start, pos_ - start);
  }
  template <class T>
  T integer(const std::string& what, T lo, T hi) {
    const std::string_view t = token(what);
    T v{};
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(what + ": expected an integer, found '" + clip(t) + "'");
    if (v < lo || v > hi)
      fail(what + ": " + std::string(t) + " is outside [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]");
    return v;
  }
  // Any number gmsh may write (bounding boxes, real tags): parsed, not range-checked.
  double anyReal(const std::string& what) {
    const std::string_view t = token(what);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) || end != t.data() + t.size())
      fail(what + ": expected a number, found '" + clip(t) + "'");
    return v;
  }
  double coordinate(const std::string& what) {
    const std::string_view t = token(what);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) || end != t.data() + t.size())
      fail(what + ": expected a number, found '" + clip(t) + "'");
    // Out of range is an overflow (refused below) or an underflow (a subnormal or zero: kept).
    if (ec == std::errc::result_out_of_range) v = std::strtod(std::string(t).c_str(), nullptr);
    checkValue(what, v);
    return v;
  }
  void checkValue(const std::string& what, double v) const {
    if (!std::isfinite(v) || std::abs(v) > kMaxCoordinate) {
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", v);
      fail(what + ": " + text + " is not a finite number within +-1e100");
    }
  }
  // A string in double quotes on one line (gmsh's names), or a bare word.
  std::string quoted(const std::string& what) {
    skipSpace();
    if (pos_ < data_.size() && data_[pos_] == '"') {
      const std::size_t start = ++pos_;
      while (pos_ < data_.size() && data_[pos_] != '"' && data_[pos_] != '\n') ++pos_;
      if (pos_ == data_.size() || data_[pos_] != '"') fail(what + ": unterminated string");
      return std::string(data_.substr(start, pos_++ - start));
    }
    return std::string(token(what));
  }
  // Binary data starts after the newline that ends the current line.
  void toNextLine(const std::string& what) {
    while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\r')) ++pos_;
    if (pos_ == data_.size() || data_[pos_] != '\n')
      fail(what + ": expected the end of the line before binary data");
    ++pos_;
    ++line_;
  }
  template <class T>
  T bin(const std::string& what) {
    if (remaining() < sizeof(T)) fail(what + ": unexpected end of file");
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  template <class T>
  T binInteger(const std::string& what, T lo, T hi) {
    const T v = bin<T>(what);
    if (v < lo || v > hi)
      fail(what + ": " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]");
    return v;
  }
  // Refuses `count` items of at least `bytesEach` bytes when the file has fewer bytes left:
  // before anything of that size is allocated.
  void need(const std::string& what, std::size_t count, std::size_t bytesEach) const {
    if (bytesEach > 0 && count > remaining() / bytesEach)
      fail(what + ": " + std::to_string(count) + " entries need at least " +
           std::to_string(bytesEach) + " bytes each; " + std::to_string(remaining()) +
           " bytes are left in the file");
  }
  // Skips to the line "$End<section>" (sections chute does not read).
  void skipTo(const std::string& end) {
    const std::string needle = "\n" + end;
    const std::size_t at = data_.find(needle, pos_);
    if (at == std::string_view::npos) fail("no " + end + " before the end of the file");
    for (std::size_t i = pos_; i <= at; ++i) line_ += data_[i] == '\n';
    pos_ = at + 1;
  }

 private:
  std::string_view data_;
  std::string name_;
  std::size_t pos_ = 0;
  long line_ = 1;
  bool binary_ = false;
};

class Parser {
 public:
  Parser(std::string_view data, const std::string& name, const MshLimits& limits)
      : c_(data, name), lim_(limits) {}

  GmshMesh run() {
    while (!c_.atEnd()) {
      const std::string head(c_.token("section"));
      if (head.size() < 2 || head[0] != '$')
        c_.fail("expected a section ($Name), found '" + clip(head) + "'");
      const std::string section = head.substr(1);
      if (!haveFormat_ && section != "MeshFormat")
        c_.fail("the file does not start with $MeshFormat: not a gmsh .msh file");
      if (section == "MeshFormat") {
        if (haveFormat_) c_.fail("$MeshFormat: a second one");
        readFormat();
      } else if (section == "PhysicalNames") {
        readPhysicalNames();
      } else if (section == "Entities" && v4_) {
        readEntities();
      } else if (section == "Nodes") {
        if (haveNodes_) c_.fail("$Nodes: a second section (not supported)");
        v4_ ? readNodes4() : readNodes2();
        haveNodes_ = true;
      } else if (section == "Elements") {
        if (!haveNodes_) c_.fail("$Elements before $Nodes");
        if (haveElements_) c_.fail("$Elements: a second section (not supported)");
        v4_ ? readElements4() : readElements2();
        haveElements_ = true;
      } else if (section == "NodeData") {
        if (!haveNodes_) c_.fail("$NodeData before $Nodes");
        readNodeData();
      } else if (section == "PartitionedEntities" || section == "GhostElements") {
        c_.fail("$" + section + ": partitioned meshes are not supported (save unpartitioned)");
      } else if (section.rfind("End", 0) == 0) {
        c_.fail("$" + section + " without its section");
      } else {
        c_.skipTo("$End" + section);
      }
      c_.setBinary(false);
      const std::string end(c_.token("$End" + section));
      if (end != "$End" + section)
        c_.fail("$" + section + ": expected $End" + section + ", found '" + clip(end) +
                "' (does the count in the section header match its data?)");
    }
    if (!haveFormat_) c_.fail("empty file: not a gmsh .msh file");
    if (!haveNodes_) c_.fail("no $Nodes section");
    return build();
  }

 private:
  using Key = std::pair<int, int>;  // (dimension, tag)

  // The elements of one (dimension, entity, type), in file order: their nodes (nodesPerElement
  // each), tags and the lines they were read on (binary: their section's header line).
  struct Block {
    std::vector<std::size_t> nodes, tags;
    std::vector<long> lines;
    // MSH 2 only: the physical tag each element was first written under, and for each physical
    // tag the element its next copy would repeat.
    std::vector<int> firstPhysical;
    std::map<int, std::size_t> nextCopy;
  };

  // A count read in the current mode (ASCII token or binary size_t).
  std::size_t count(const std::string& what, std::size_t limit, std::size_t bytesEach,
                    bool binary) {
    std::size_t n = binary
                        ? c_.bin<std::size_t>(what)
                        : c_.integer<std::size_t>(what, 0, std::numeric_limits<std::size_t>::max());
    if (n > limit)
      c_.fail(what + ": " + std::to_string(n) + " is more than the limit of " +
              std::to_string(limit));
    c_.need(what, n, bytesEach);
    return n;
  }
  int intValue(const std::string& what, bool binary, int lo = INT_MIN, int hi = INT_MAX) {
    return binary ? c_.binInteger<int>(what, lo, hi) : c_.integer<int>(what, lo, hi);
  }
  std::size_t tagValue(const std::string& what, bool binary, bool size8) {
    constexpr std::size_t kMaxTag = std::numeric_limits<std::size_t>::max() / 2;
    if (!binary) return c_.integer<std::size_t>(what, 1, kMaxTag);
    if (size8) return c_.binInteger<std::size_t>(what, 1, kMaxTag);
    return static_cast<std::size_t>(c_.binInteger<int>(what, 1, INT_MAX));
  }
  double realValue(const std::string& what, bool binary, bool check) {
    if (!binary) return check ? c_.coordinate(what) : c_.anyReal(what);
    const double v = c_.bin<double>(what);
    if (check) c_.checkValue(what, v);
    return v;
  }

  void readFormat() {
    const std::string version(c_.token("$MeshFormat version"));
    if (version == "4.1")
      v4_ = true;
    else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0")
      v4_ = false;
    else if (version == "4" || version == "4.0")
      c_.fail("$MeshFormat: version 4.0 is not read: save the mesh as 4.1 or 2.2");
    else
      c_.fail("$MeshFormat: version '" + clip(version) + "': chute reads versions 2.2 and 4.1");
    binary_ = c_.integer<int>("$MeshFormat file type", 0, 1) == 1;
    const int dataSize = c_.integer<int>("$MeshFormat data size", 0, 64);
    if (dataSize != 8) c_.fail("$MeshFormat: data size " + std::to_string(dataSize) + ", not 8");
    if (binary_) {
      c_.toNextLine("$MeshFormat");
      c_.setBinary(true);
      if (c_.bin<int>("$MeshFormat byte order") != 1)
        c_.fail("$MeshFormat: binary data of another byte order (not supported)");
    }
    haveFormat_ = true;
  }

  void readPhysicalNames() {
    const std::size_t n = count("$PhysicalNames count", 1u << 24, 6, false);
    for (std::size_t i = 0; i < n; ++i) {
      const int dim = c_.integer<int>("$PhysicalNames dimension", 0, 3);
      const int tag = c_.integer<int>("$PhysicalNames tag", INT_MIN + 1, INT_MAX);
      physicalNames_[{dim, tag}] = c_.quoted("$PhysicalNames name");
    }
  }

  void readEntities() {
    const bool b = binary_;
    if (b) {
      c_.toNextLine("$Entities");
      c_.setBinary(true);
    }
    std::size_t n[4];
    for (int d = 0; d < 4; ++d)
      n[d] = count("$Entities count", std::numeric_limits<int>::max(), b ? 36 : 9, b);
    for (int d = 0; d < 4; ++d) {
      const std::string what = "$Entities (" + std::to_string(d) + "-D)";
      c_.need(what, n[d], d == 0 ? (b ? 36 : 9) : (b ? 68 : 17));
      for (std::size_t i = 0; i < n[d]; ++i) {
        const int tag = intValue(what + " tag", b);
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k) realValue(what + " bounding box", b, false);
        const std::size_t np = count(what + " physical count", INT_MAX, b ? 4 : 2, b);
        auto& phys = entityPhysicals_[{d, tag}];
        for (std::size_t k = 0; k < np; ++k) {
          const int p = intValue(what + " physical tag", b, INT_MIN + 1, INT_MAX);
          if (p != 0) phys.insert(std::abs(p));
        }
        if (d > 0) {
          const std::size_t nb = count(what + " bounding count", INT_MAX, b ? 4 : 2, b);
          for (std::size_t k = 0; k < nb; ++k) intValue(what + " bounding tag", b);
        }
      }
    }
  }

  void addNode(std::size_t tag, const Vec3& x) {
    if (!nodeIndex_.emplace(tag, xyz_.size()).second)
      c_.fail("$Nodes: node tag " + std::to_string(tag) + " appears twice");
    xyz_.push_back(x);
  }
  Vec3 point(bool binary) {
    Vec3 x;
    for (int k = 0; k < 3; ++k) x[k] = realValue("$Nodes coordinate", binary, true);
    return x;
  }

  void readNodes2() {
    const std::size_t n = count("$Nodes count", lim_.maxNodes, binary_ ? 28 : 8, false);
    if (binary_) {
      c_.toNextLine("$Nodes");
      c_.setBinary(true);
    }
    nodeIndex_.reserve(n);
    xyz_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t tag = tagValue("$Nodes tag", binary_, false);
      addNode(tag, point(binary_));
    }
  }

  void readNodes4() {
    const bool b = binary_;
    if (b) {
      c_.toNextLine("$Nodes");
      c_.setBinary(true);
    }
    const std::size_t blocks = count("$Nodes block count", lim_.maxNodes, b ? 20 : 8, b);
    const std::size_t n = count("$Nodes count", lim_.maxNodes, b ? 32 : 8, b);
    count("$Nodes min tag", std::numeric_limits<std::size_t>::max(), 0, b);
    count("$Nodes max tag", std::numeric_limits<std::size_t>::max(), 0, b);
    nodeIndex_.reserve(n);
    xyz_.reserve(n);
    std::size_t read = 0;
    std::vector<std::size_t> tags;
    for (std::size_t k = 0; k < blocks; ++k) {
      const int dim = intValue("$Nodes block dimension", b, 0, 3);
      intValue("$Nodes block entity", b);
      const int parametric = intValue("$Nodes block parametric", b, 0, 1);
      const std::size_t extra = parametric ? static_cast<std::size_t>(dim) : 0;
      const std::size_t m = count("$Nodes block size", n - read, b ? 8 * (4 + extra) : 8, b);
      tags.clear();
      for (std::size_t i = 0; i < m; ++i) tags.push_back(tagValue("$Nodes tag", b, true));
      for (std::size_t i = 0; i < m; ++i) {
        addNode(tags[i], point(b));
        for (std::size_t e = 0; e < extra; ++e) realValue("$Nodes parameter", b, false);
      }
      read += m;
    }
    if (read != n)
      c_.fail("$Nodes: the header says " + std::to_string(n) + " nodes, the blocks hold " +
              std::to_string(read));
  }

  // One element's nodes into its (dimension, entity, type) block; every node must exist. Returns
  // its index in the block.
  std::size_t addElement(int dim, int entity, int type, std::size_t tag, const std::size_t* nodes,
                         int nn) {
    auto& block = blocks_[{dim, entity, type}];
    for (int k = 0; k < nn; ++k) {
      if (!nodeIndex_.count(nodes[k]))
        c_.fail("$Elements: node " + std::to_string(nodes[k]) + " is not in $Nodes");
      block.nodes.push_back(nodes[k]);
    }
    block.tags.push_back(tag);
    block.lines.push_back(c_.line());
    return block.tags.size() - 1;
  }

  int elementType(const std::string& what, bool binary) {
    const int type = intValue(what, binary);
    if (nodesPerElement(type) == 0)
      c_.fail(what + ": " + std::to_string(type) + " is not a gmsh element type chute knows");
    return type;
  }

  void readElements2() {
    const std::size_t n = count("$Elements count", lim_.maxElements, binary_ ? 16 : 8, false);
    std::size_t nodes[125];
    if (!binary_) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t tag = tagValue("$Elements tag", false, false);
        const int type = elementType("$Elements type", false);
        const int nt = c_.integer<int>("$Elements number of tags", 0, 1000);
        int physical = 0, entity = 0;
        for (int k = 0; k < nt; ++k) {
          const int t = c_.integer<int>("$Elements tag", INT_MIN + 1, INT_MAX);
          if (k == 0) physical = t;
          if (k == 1) entity = t;
        }
        const int nn = nodesPerElement(type);
        for (int k = 0; k < nn; ++k) nodes[k] = tagValue("$Elements node", false, false);
        addElement2(type, physical, entity, tag, nodes, nn);
      }
      return;
    }
    c_.toNextLine("$Elements");
    c_.setBinary(true);
    std::size_t read = 0;
    while (read < n) {
      const int type = elementType("$Elements type", true);
      const std::size_t m = static_cast<std::size_t>(c_.binInteger<int>(
          "$Elements block size", 1, static_cast<int>(std::min<std::size_t>(n - read, INT_MAX))));
      const int nt = c_.binInteger<int>("$Elements number of tags", 0, 1000);
      const int nn = nodesPerElement(type);
      c_.need("$Elements block", m, 4 * static_cast<std::size_t>(1 + nt + nn));
      for (std::size_t i = 0; i < m; ++i) {
        const std::size_t tag = static_cast<std::size_t>(c_.bin<int>("$Elements tag"));
        int physical = 0, entity = 0;
        for (int k = 0; k < nt; ++k) {
          const int t = c_.bin<int>("$Elements tag");
          if (k == 0) physical = t;
          if (k == 1) entity = t;
        }
        for (int k = 0; k < nn; ++k) nodes[k] = tagValue("$Elements node", true, false);
        addElement2(type, physical, entity, tag, nodes, nn);
      }
      read += m;
    }
  }
  // MSH 2: the entity is the element's elementary tag; its physical groups are those of its
  // elements (gmsh's reader does the same). gmsh writes the elements of an entity once per
  // physical group of the entity, each pass in the same order under new element numbers: an
  // element of a later pass with the nodes of the element at the same place of the first pass is
  // that element again, not another one. (Read as two, a line in the groups 'lines' and 'line_0'
  // made a doubled chain: "group 'line_0' branches at node 326".) Copies in another order are
  // kept and refused as elements with the same nodes (build()).
  void addElement2(int type, int physical, int entity, std::size_t tag, const std::size_t* nodes,
                   int nn) {
    const int dim = dimOfType(type);
    auto& phys = entityPhysicals_[{dim, entity}];
    if (physical != 0) phys.insert(std::abs(physical));
    auto& block = blocks_[{dim, entity, type}];
    std::size_t& next = block.nextCopy.try_emplace(physical, 0).first->second;
    if (next < block.tags.size() && block.firstPhysical[next] != physical &&
        std::equal(nodes, nodes + nn, block.nodes.begin() + static_cast<long>(next * nn))) {
      ++next;
      return;
    }
    addElement(dim, entity, type, tag, nodes, nn);
    block.firstPhysical.push_back(physical);
    next = block.tags.size();
  }

  void readElements4() {
    const bool b = binary_;
    if (b) {
      c_.toNextLine("$Elements");
      c_.setBinary(true);
    }
    const std::size_t blocks = count("$Elements block count", lim_.maxElements, b ? 20 : 8, b);
    const std::size_t n = count("$Elements count", lim_.maxElements, b ? 16 : 4, b);
    count("$Elements min tag", std::numeric_limits<std::size_t>::max(), 0, b);
    count("$Elements max tag", std::numeric_limits<std::size_t>::max(), 0, b);
    std::size_t read = 0;
    std::size_t nodes[125];
    for (std::size_t k = 0; k < blocks; ++k) {
      const int dim = intValue("$Elements block dimension", b, 0, 3);
      const int entity = intValue("$Elements block entity", b);
      const int type = elementType("$Elements block type", b);
      if (dimOfType(type) != dim)
        c_.fail("$Elements: element type " + std::to_string(type) + " in a " + std::to_string(dim) +
                "-D entity");
      const int nn = nodesPerElement(type);
      const std::size_t m = count("$Elements block size", n - read,
                                  (b ? 8 : 2) * static_cast<std::size_t>(1 + nn), b);
      for (std::size_t i = 0; i < m; ++i) {
        const std::size_t tag = tagValue("$Elements tag", b, true);
        for (int j = 0; j < nn; ++j) nodes[j] = tagValue("$Elements node", b, true);
        addElement(dim, entity, type, tag, nodes, nn);
      }
      read += m;
    }
    if (read != n)
      c_.fail("$Elements: the header says " + std::to_string(n) + " elements, the blocks hold " +
              std::to_string(read));
  }

  void readNodeData() {
    const std::size_t ns = count("$NodeData string tag count", 1000, 3, false);
    std::string name;
    for (std::size_t i = 0; i < ns; ++i) {
      std::string s = c_.quoted("$NodeData string tag");
      if (i == 0) name = std::move(s);
    }
    const std::size_t nr = count("$NodeData real tag count", 1000, 2, false);
    for (std::size_t i = 0; i < nr; ++i) c_.anyReal("$NodeData real tag");
    const std::size_t ni = count("$NodeData integer tag count", 1000, 2, false);
    if (ni < 3) c_.fail("$NodeData: " + std::to_string(ni) + " integer tags, at least 3 needed");
    const int step = c_.integer<int>("$NodeData time step", INT_MIN, INT_MAX);
    const int comps = c_.integer<int>("$NodeData components", 1, 9);
    const std::size_t m = c_.integer<std::size_t>("$NodeData count", 0, lim_.maxNodes);
    c_.need("$NodeData values", m, binary_ ? 4 + 8 * comps : 2 + 2 * comps);
    for (std::size_t i = 3; i < ni; ++i) c_.integer<int>("$NodeData integer tag", INT_MIN, INT_MAX);
    if (binary_) {
      c_.toNextLine("$NodeData");
      c_.setBinary(true);
    }
    const bool keep = step == 0 && comps == 3;
    NodeVectors* view = keep ? &views_[name] : nullptr;
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t tag = tagValue("$NodeData node", binary_, false);
      if (!nodeIndex_.count(tag))
        c_.fail("$NodeData '" + clip(name) + "': node " + std::to_string(tag) +
                " is not in $Nodes");
      Vec3 v = Vec3::Zero();
      for (int k = 0; k < comps; ++k) {
        const double x = realValue("$NodeData value", binary_, true);
        if (k < 3) v[k] = x;
      }
      if (view && !view->emplace(tag, v).second)
        c_.fail("$NodeData '" + clip(name) + "': node " + std::to_string(tag) + " appears twice");
    }
  }

  // An element that cannot be used, or two elements of one group on the same nodes: refused
  // naming the file, the line the element was read on, its tag and its group.
  [[noreturn]] void failElement(const Block& b, std::size_t e, int type, const std::string& group,
                                const std::string& why) const {
    const char* kind = type == 1   ? "line"
                       : type == 2 ? "triangle"
                       : type == 3 ? "quadrangle"
                                   : "point";
    throw MeshError(c_.name() + ":" + std::to_string(b.lines[e]) + ": element " +
                    std::to_string(b.tags[e]) + " (" + kind + ") of physical group '" + group +
                    "': " + why + (binary_ ? " (binary data)" : ""));
  }

  // Every element of a block that is in a physical group: distinct nodes, a length or an area,
  // convex quadrangles (ElementShape.hpp). A degenerate element ran to a non-finite residual
  // (exit 3, output written) or, a non-convex quadrangle, to a wrong answer (exit 0).
  void checkShapes(const Block& b, int type, const std::string& group) const {
    const int nn = nodesPerElement(type);
    if (type == 15) return;
    Vec3 x[4];
    for (std::size_t e = 0; e < b.tags.size(); ++e) {
      const std::size_t* tags = b.nodes.data() + e * nn;
      for (int k = 0; k < nn; ++k) x[k] = xyz_[nodeIndex_.at(tags[k])];
      const ShapeProblem p = elementShapeProblem(x, tags, nn);
      if (p) failElement(b, e, type, group, p.text(p.node < 0 ? "" : std::to_string(tags[p.node])));
    }
  }

  // Two elements of one group on the same set of nodes (a repeated element, or two overlapping
  // ones): the group's stiffness, mass and load would count that place twice.
  void checkRepeats(const MeshGroup& g,
                    const std::vector<std::pair<const Block*, std::size_t>>& from,
                    const std::vector<int>& types) const {
    if (g.dim == 0) return;
    std::vector<std::pair<std::array<std::size_t, 4>, std::size_t>> keys;
    keys.reserve(g.elements.size());
    for (std::size_t i = 0; i < g.elements.size(); ++i) {
      std::array<std::size_t, 4> k{0, 0, 0, 0};
      std::copy(g.elements[i].begin(), g.elements[i].end(), k.begin());
      for (std::size_t a = 1; a < g.elements[i].size(); ++a)  // at most 4: insertion sort
        for (std::size_t b = a; b > 0 && k[b - 1] > k[b]; --b) std::swap(k[b - 1], k[b]);
      keys.emplace_back(k, i);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) {
        const std::size_t a = std::min(keys[i].second, keys[i - 1].second);
        const std::size_t b = std::max(keys[i].second, keys[i - 1].second);
        failElement(*from[b].first, from[b].second, types[b], g.name,
                    "the same nodes as element " +
                        std::to_string(from[a].first->tags[from[a].second]) + " of the group");
      }
  }

  // The elements of a surface group go round their common edges in opposite senses (one
  // orientation over the surface): an element turned over has its normal -- and the pressure on
  // it -- the other way. Two elements that run a common edge the same way are refused.
  void checkOrientation(const MeshGroup& g,
                        const std::vector<std::pair<const Block*, std::size_t>>& from,
                        const std::vector<int>& types) const {
    if (g.dim != 2) return;
    struct Edge {
      std::size_t a, b, element;
      bool operator<(const Edge& o) const { return std::tie(a, b) < std::tie(o.a, o.b); }
    };
    std::vector<Edge> edges;
    for (std::size_t i = 0; i < g.elements.size(); ++i) {
      const auto& e = g.elements[i];
      for (std::size_t k = 0; k < e.size(); ++k) edges.push_back({e[k], e[(k + 1) % e.size()], i});
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 1; i < edges.size(); ++i)
      if (edges[i].a == edges[i - 1].a && edges[i].b == edges[i - 1].b) {
        const std::size_t x = std::min(edges[i].element, edges[i - 1].element);
        const std::size_t y = std::max(edges[i].element, edges[i - 1].element);
        failElement(*from[y].first, from[y].second, types[y], g.name,
                    "turned over against element " +
                        std::to_string(from[x].first->tags[from[x].second]) +
                        " (both run their common edge from node " + std::to_string(edges[i].a) +
                        " to node " + std::to_string(edges[i].b) +
                        "): orient the surface's elements one way");
      }
  }

  GmshMesh build() {
    GmshMesh mesh;
    std::map<Key, std::vector<int>> groups;  // (dim, physical) -> entities, ascending
    for (const auto& [entity, phys] : entityPhysicals_)
      for (int p : phys) groups[{entity.first, p}].push_back(entity.second);
    std::set<std::size_t> used;
    std::set<const Block*> checked;
    std::map<std::pair<int, std::string>, int> names;  // (dim, name) -> physical tag
    std::size_t copies = 0;
    for (const auto& [key, entities] : groups) {
      MeshGroup g;
      g.dim = key.first;
      g.tag = key.second;
      const auto named = physicalNames_.find(key);
      g.name = named != physicalNames_.end() && !named->second.empty()
                   ? named->second
                   : "physical_" + std::to_string(g.dim) + "d_" + std::to_string(g.tag);
      // A case maps groups by name: of two surfaces named 'canopy' one was silently dropped.
      if (const auto [at, fresh] = names.emplace(std::pair{g.dim, g.name}, g.tag); !fresh)
        throw MeshError(c_.name() + ": physical groups " + std::to_string(at->second) + " and " +
                        std::to_string(g.tag) + " (" + std::to_string(g.dim) +
                        "-D) are both named '" + g.name +
                        "': a name must be unique among the groups of one dimension");
      std::vector<std::pair<const Block*, std::size_t>> from;  // each element's block and index
      std::vector<int> types;
      for (int entity : entities) {
        for (auto it = blocks_.lower_bound({g.dim, entity, INT_MIN});
             it != blocks_.end() && std::get<0>(it->first) == g.dim &&
             std::get<1>(it->first) == entity;
             ++it) {
          const int type = std::get<2>(it->first);
          if (!supportedType(type))
            throw MeshError(c_.name() + ": physical group '" + g.name +
                            "' has elements of gmsh type " + std::to_string(type) + " (" +
                            std::to_string(nodesPerElement(type)) +
                            " nodes): only first-order points, lines, triangles and "
                            "quadrangles are supported");
          const auto nn = static_cast<std::size_t>(nodesPerElement(type));
          const Block& b = it->second;
          const auto& v = b.nodes;
          // An element is copied into every group of its entity: a few bytes of physical tags
          // must not multiply a large block into terabytes.
          copies += v.size() / nn;
          if (copies > lim_.maxElements)
            throw MeshError(c_.name() + ": the physical groups hold more than " +
                            std::to_string(lim_.maxElements) +
                            " elements in all (the limit on elements; an element counts once "
                            "per group)");
          if (checked.insert(&b).second) checkShapes(b, type, g.name);
          for (std::size_t e = 0; e < v.size(); e += nn) {
            g.elements.emplace_back(v.begin() + static_cast<long>(e),
                                    v.begin() + static_cast<long>(e + nn));
            used.insert(v.begin() + static_cast<long>(e), v.begin() + static_cast<long>(e + nn));
            from.emplace_back(&b, e / nn);
            types.push_back(type);
          }
        }
      }
      checkRepeats(g, from, types);
      checkOrientation(g, from, types);
      mesh.groups.push_back(std::move(g));
    }
    for (std::size_t t : used) {
      mesh.nodeTags.push_back(t);
      mesh.coords.push_back(xyz_[nodeIndex_.at(t)]);
    }
    if (mesh.nodeTags.empty()) throw MeshError(c_.name() + ": the mesh has no nodes");
    mesh.buildIndex();
    mesh.views = std::move(views_);
    return mesh;
  }

  Cursor c_;
  MshLimits lim_;
  bool v4_ = false, binary_ = false;
  bool haveFormat_ = false, haveNodes_ = false, haveElements_ = false;
  std::unordered_map<std::size_t, std::size_t> nodeIndex_;
  std::vector<Vec3> xyz_;
  std::map<Key, std::string> physicalNames_;
  std::map<Key, std::set<int>> entityPhysicals_;
  std::map<std::tuple<int, int, int>, Block> blocks_;
  std::map<std::string, NodeVectors> views_;
};

}  // namespace

GmshMesh parseMsh(const std::string& bytes, const std::string& name, const MshLimits& limits) {
  return Parser(bytes, name, limits).run();
}

GmshMesh readMsh(const std::string& file, const MshLimits& limits) {
  std::string bytes;
  try {
    bytes = io::readInputFile(file, limits.maxFileBytes);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    // The historical wording for a missing mesh ("no such mesh file").
    if (what == file + ": cannot open: no such file") throw MeshError(file + ": no such mesh file");
    throw MeshError(what);
  }
  return parseMsh(bytes, file, limits);
}

}  // namespace chute::mesh
